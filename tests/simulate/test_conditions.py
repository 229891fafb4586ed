"""The twin's weather and ground: scenario fields, forcing, logs and truth."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest

from clearfast_gis.errors import InvalidInput
from clearfast_gis.simulate import load_scenario, parse_scenario, preset, simulate_survey
from clearfast_gis.simulate.surface import thermal_truth, under_canopy
from clearfast_gis.simulate.twin import build_twin, stream
from clearfast_gis.simulate.weather import site_forcing
from clearfast_gis.survey import read_toa5
from clearfast_gis.survey.toa5 import write_toa5
from clearfast_gis.thermal import clear_sky_forcing
from clearfast_gis.thermal.clouds import cloud_solar_factor
from clearfast_gis.timeutil import parse_utc


def _doc(**kw) -> dict:
    return {"format": "clearfast-scenario", "format_version": 1, **kw}


def test_weather_and_ground_fields_parse():
    scen = parse_scenario(_doc(
        weather={"cloud_cover": [[0, 0.2], [12, 0.8]], "wind_scale": 2.0, "gusts": 0.3,
                 "rain": [{"start_utc": "2026-11-15T06:00:00Z", "duration_h": 1.0,
                           "total_mm": 6.0}], "air_temp_c": [20, 34], "rh_pct": [40, 80]},
        soil={"type": "clay", "moisture": 0.3}, vegetation_cover=0.4))
    c = scen.config
    assert c.weather.cloud_cover == ((0.0, 0.2), (12.0, 0.8))
    assert c.weather.rain[0].start_s == parse_utc("2026-11-15T06:00:00Z")
    assert c.weather.rain[0].duration_s == 3600.0 and c.weather.rain[0].total_mm == 6.0
    assert c.weather.wind_scale == 2.0 and c.weather.air_temp_c == (20.0, 34.0)
    assert (c.soil_type, c.soil_moisture, c.vegetation_cover) == ("clay", 0.3, 0.4)
    assert parse_scenario(_doc(weather={"cloud_cover": 0.6})).config.weather.cloud_cover == \
        ((0.0, 0.6),)


@pytest.mark.parametrize("doc, field", [
    (_doc(weather={"cloud_cover": 1.5}), "weather.cloud_cover"),
    (_doc(weather={"cloud_cover": [[0, 0.1], [0, 0.5]]}), "weather.cloud_cover"),
    (_doc(weather={"rain": [{"start_utc": "yesterday", "duration_h": 1, "total_mm": 2}]}),
     "weather.rain.0.start_utc"),
    (_doc(weather={"rain": [{"start_utc": "2026-11-15T06:00:00Z", "duration_h": 1,
                             "total_mm": -2}]}), "weather.rain.0.total_mm"),
    (_doc(weather={"air_temp_c": [30, 20]}), "weather.air_temp_c"),
    (_doc(weather={"hail": 1}), "weather"),
    (_doc(soil={"type": "peat"}), "soil.type"),
    (_doc(soil={"type": "sand", "moisture": 2}), "soil.moisture"),
    (_doc(vegetation_cover=-0.1), "vegetation_cover"),
    (_doc(weather={"file": "missing.dat"}), "weather.file"),
])
def test_condition_errors_name_file_and_field(tmp_path, doc, field):
    path = tmp_path / "scen.json"
    path.write_text(json.dumps(doc))
    with pytest.raises(InvalidInput) as err:
        load_scenario(path)
    assert err.value.field == field
    assert "scen.json" in str(err.value)


def test_default_weather_is_the_clear_day():
    cfg = preset("demo")
    start = parse_utc(cfg.start_utc)
    f = site_forcing(cfg, start, stream(0, "gusts"))
    clear = clear_sky_forcing(cfg.latitude_deg, cfg.longitude_deg, start, cfg.duration_s, 60.0)
    for name in ("solar_wm2", "sky_lw_wm2", "air_temp_k", "wind_ms", "rh_pct"):
        np.testing.assert_array_equal(getattr(f, name), getattr(clear, name))
    assert not f.rain_mm_h.any()


def test_clouds_rain_and_wind_shape_the_forcing():
    cfg = preset("demo")
    start = parse_utc(cfg.start_utc)
    clear = site_forcing(cfg, start, stream(0, "gusts"))
    spec = parse_scenario(_doc(weather={
        "cloud_cover": 0.6, "wind_scale": 2.0,
        "rain": [{"start_utc": "2026-11-15T03:00:00Z", "duration_h": 2.0, "total_mm": 6.0}]}
    )).config
    f = site_forcing(spec, start, stream(0, "gusts"))
    dry = (f.time_s < start + 3 * 3600) | (f.time_s >= start + 5 * 3600)
    np.testing.assert_allclose(f.solar_wm2[dry], clear.solar_wm2[dry] * cloud_solar_factor(0.6))
    assert np.all(f.sky_lw_wm2 > clear.sky_lw_wm2)
    np.testing.assert_allclose(f.wind_ms, 2.0 * clear.wind_ms)
    assert np.sum(f.rain_mm_h) / 60.0 == pytest.approx(6.0, rel=0.01)
    assert np.all(f.rh_pct[~dry] >= 95.0)
    gusty = site_forcing(replace(spec, weather=replace(spec.weather, gusts=0.3)), start,
                         stream(0, "gusts"))
    ratio = gusty.wind_ms / f.wind_ms
    assert 0.15 < np.std(ratio) < 0.45 and abs(np.mean(ratio) - 1.0) < 0.15


def test_measured_weather_file_forces_the_twin(tmp_path):
    """A twin forced by a TOA5 record: the record's (cloudy) sun drives it, as logged."""
    cfg = parse_scenario(_doc(weather={"cloud_cover": 0.9})).config
    twin = build_twin(replace(cfg, n_scans=2), seed=1)
    write_toa5(tmp_path / "weather.dat", twin.weather_log())
    (tmp_path / "scen.json").write_text(json.dumps(_doc(weather={"file": "weather.dat"})))
    measured = load_scenario(tmp_path / "scen.json").config
    f = site_forcing(measured, parse_utc(cfg.start_utc), stream(0, "gusts"))
    noon = np.argmax(twin.forcing.solar_wm2)
    assert f.solar_wm2.max() == pytest.approx(twin.forcing.solar_wm2[noon], rel=0.08)
    late = replace(measured, start_utc="2026-11-20T00:00:00Z")
    with pytest.raises(InvalidInput, match="does not cover"):
        site_forcing(late, parse_utc(late.start_utc), stream(0, "gusts"))


def test_grass_shades_the_soil_and_hides_contrast(small_config):
    cfg = replace(small_config, vegetation_cover=0.5)
    twin = build_twin(cfg, seed=2)
    shaded = under_canopy(twin.forcing, 0.5)
    np.testing.assert_allclose(shaded.solar_wm2, 0.5 * twin.forcing.solar_wm2)
    noon = twin.start_s + 10 * 3600.0
    times = np.array([noon])
    bare = thermal_truth(twin.forcing, times, twin.objects)
    grass = thermal_truth(twin.forcing, times, twin.objects, twin.ground)
    assert grass.canopy == 0.5
    assert grass.soil_k["site"][0] < bare.soil_k["site"][0] - 2.0
    key = next(iter(bare.objects))
    assert np.abs(grass.objects[key].contrast_k).max() < np.abs(bare.objects[key].contrast_k).max()


def test_rainy_loam_survey_logs_rain_and_keeps_its_day(tmp_path, small_config):
    cfg = parse_scenario(_doc(
        weather={"rain": [{"start_utc": "2026-11-15T02:00:00Z", "duration_h": 1.0,
                           "total_mm": 5.0}], "cloud_cover": 0.3},
        soil={"type": "loam", "moisture": 0.4}), base=small_config).config
    res = simulate_survey(tmp_path / "s", cfg, seed=4)
    root = tmp_path / "s"
    log = read_toa5(root / "weather.dat")
    assert np.nansum(log.rain_mm) == pytest.approx(5.0, abs=0.1)
    again = load_scenario(root / "truth" / "scenario.json").config
    assert again.weather == cfg.weather and again.soil_type == "loam"
    assert res is not None
