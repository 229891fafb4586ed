"""The day's contrast: the reference mine under a clear and an overcast sky."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from clearfast_gis.thermal import get_soil
from clearfast_gis.thermal.clouds import cloud_solar_factor, cloudy_sky_longwave
from clearfast_gis.thermal.daycontrast import clear_sky_index, contrast_noise_k, day_contrast

from .conftest import LAT_DEG, LON_DEG


def _overcast(forcing):
    return dataclasses.replace(
        forcing, solar_wm2=forcing.solar_wm2 * cloud_solar_factor(1.0),
        sky_lw_wm2=cloudy_sky_longwave(forcing.air_temp_k, forcing.rh_pct, 1.0))


def test_clear_day_shows_deeper_than_an_overcast_one(forcing, scans):
    soil = get_soil("moist_sand")
    clear = day_contrast(forcing, soil, scans, 0.05, LAT_DEG, LON_DEG)
    dull = day_contrast(_overcast(forcing), soil, scans, 0.05, LAT_DEG, LON_DEG)
    # contrast falls with depth, and an overcast sky takes most of it
    assert np.all(np.diff(clear.peak_contrast_k) < 0)
    assert np.all(dull.peak_contrast_k < clear.peak_contrast_k)
    # design guide: +2.2 K at 1 cm, +0.44 K at 5 cm for a 10 cm TNT AP mine in moist sand
    # (docs/thermal.md verification, 48 scans: +2.40 / +0.51 K)
    assert clear.contrast_at(0.01) == pytest.approx(2.3, abs=0.3)
    assert clear.contrast_at(0.05) == pytest.approx(0.5, abs=0.1)
    assert np.all(clear.showing_share >= dull.showing_share)
    assert clear.showing_share[4] > dull.showing_share[4]  # 5 cm: shown in more scans
    noisy = day_contrast(_overcast(forcing), soil, scans, 0.15, LAT_DEG, LON_DEG)
    assert noisy.deepest_showing_m < clear.deepest_showing_m
    # a depth shows when its contrast reaches 3 sigma in a quarter of the scans
    assert np.all(np.diff(clear.showing_share) <= 0)
    shows = clear.showing_share >= 0.25
    assert clear.deepest_showing_m == pytest.approx(clear.depths_m[shows].max())
    assert clear.clear_sky_index == pytest.approx(1.0, abs=1e-6)
    assert dull.clear_sky_index == pytest.approx(0.25, abs=1e-6)
    rec = dull.as_dict()
    assert rec["rain_mm"] == 0.0 and len(rec["peak_contrast_k"]) == len(rec["depths_m"])


def test_nothing_shows_in_heavy_noise(forcing, scans):
    day = day_contrast(forcing, get_soil("moist_sand"), scans, 5.0, LAT_DEG, LON_DEG)
    assert np.isnan(day.deepest_showing_m)
    assert day.as_dict()["deepest_showing_m"] is None


def test_clear_sky_index_of_a_night_is_undefined(forcing):
    night = dataclasses.replace(forcing, time_s=forcing.time_s[:60],
                                solar_wm2=forcing.solar_wm2[:60],
                                sky_lw_wm2=forcing.sky_lw_wm2[:60],
                                air_temp_k=forcing.air_temp_k[:60],
                                wind_ms=forcing.wind_ms[:60], rh_pct=forcing.rh_pct[:60],
                                rain_mm_h=forcing.rain_mm_h[:60])
    assert np.isnan(clear_sky_index(night, LAT_DEG, LON_DEG))


def test_contrast_noise_falls_back_to_the_camera():
    class Inv:
        def __init__(self, rms):
            self.residual_rms_k = rms

    assert contrast_noise_k({1: Inv(0.1), 2: Inv(0.3), 3: Inv(0.2)}) == pytest.approx(0.2)
    # the background clutter counts when it is the larger
    assert contrast_noise_k({1: Inv(0.02)}, clutter_k=0.045) == pytest.approx(0.045)
    assert contrast_noise_k({1: Inv(0.05)}, clutter_k=0.045) == pytest.approx(0.05)

    class Survey:
        manifest = {"camera": {"netd_k": 0.08}}

    assert contrast_noise_k({}, Survey()) == 0.08
    assert contrast_noise_k({}) == 0.05


def test_dull_day_is_said_at_the_top_of_the_report(forcing, scans):
    """Under a full overcast a 5 cm mine gives less than the detector's cut: the day is
    called dull, the warning names the depth, and the report says it above the map."""
    from clearfast_gis.export.products import weak_day, weak_day_text
    from clearfast_gis.report.html import ReportData, render_html

    soil, noise = get_soil("moist_sand"), 0.07  # clutter of a textured site, K
    clear = day_contrast(forcing, soil, scans, noise, LAT_DEG, LON_DEG)
    dull = day_contrast(_overcast(forcing), soil, scans, noise, LAT_DEG, LON_DEG)
    assert not weak_day(clear) and weak_day(dull)
    # the detector's cut: 0.7 of the modelled contrast against 3 sigma (4 less the peak lift)
    assert dull.delivered_fraction * dull.contrast_at(0.05) < 3 * noise
    text = weak_day_text(dull)
    assert f"deeper than about {100 * dull.deepest_showing_m:.0f} cm" in text
    html = render_html(ReportData("S1", "site", 32636, 0.0, 3600.0, [], b"",
                                  warnings=[f"low thermal contrast: {text}"]))
    assert html.index("Low thermal contrast.") < html.index("Mosaics and detections")
    plain = render_html(ReportData("S1", "site", 32636, 0.0, 3600.0, [], b""))
    assert "Low thermal contrast." not in plain
