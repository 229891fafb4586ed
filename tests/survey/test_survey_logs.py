"""TOA5 weather, soil, blackbody and marker logs: round trips, errors, fuzzing."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey import (
    BlackbodyLog,
    Markers,
    SoilLog,
    WeatherLog,
    parse_blackbody_log,
    parse_soil_log,
    parse_toa5,
    read_blackbody_log,
    read_markers,
    read_soil_log,
    read_toa5,
    write_blackbody_log,
    write_markers,
    write_soil_log,
    write_toa5,
)
from clearfast_gis.survey.toa5 import toa5_text
from clearfast_gis.timeutil import parse_utc

T0 = parse_utc("2026-11-15T00:00:00Z")

CAMPBELL = '''"TOA5","CR1000X_Site","CR1000X","4242","Std.06","CPU:met.CR1X","1234","Table1min"
"TIMESTAMP","RECORD","AirTC_Avg","RH_Avg","BP_hPa_Avg","WS_ms_Avg","SlrW_Avg","IRSky_Avg","Rain_mm_Tot"
"TS","RN","Deg C","%","hPa","meters/second","W/m^2","W/m^2, sky long-wave down","mm"
"","","Avg","Avg","Avg","Avg","Avg","Avg","Tot"
"2026-11-15 00:01:00",0,12.31,71.2,1004.6,1.84,0,"NAN",0
"2026-11-15 00:02:00",1,12.28,71.5,1004.6,"NAN",0,301.2,0.2
'''


def _weather(n: int = 30) -> WeatherLog:
    rng = np.random.default_rng(1)
    v = rng.normal(size=(7, n))
    v[2, n // 2] = np.nan
    return WeatherLog(T0 + 60.0 * np.arange(n), 12 + v[0], 60 + v[1], 1005 + v[2], 2 + v[3],
                      np.abs(400 * v[4]), 300 + v[5], np.abs(v[6]))


def test_toa5_round_trip(tmp_path):
    log = _weather()
    write_toa5(tmp_path / "w.dat", log)
    back = read_toa5(tmp_path / "w.dat")
    for name in ("time_s", "air_temp_c", "rh_pct", "pressure_hpa", "wind_ms", "solar_wm2",
                 "sky_lw_wm2", "rain_mm"):
        np.testing.assert_allclose(getattr(back, name), getattr(log, name), rtol=1e-5,
                                   equal_nan=True, err_msg=name)


def test_toa5_units_with_comment_rejected_but_campbell_layout_read():
    with pytest.raises(InvalidInput, match="IRSky_Avg: unit"):
        parse_toa5(CAMPBELL)
    log = parse_toa5(CAMPBELL.replace("W/m^2, sky long-wave down", "W/m^2"))
    assert log.time_s.tolist() == [T0 + 60, T0 + 120]
    assert np.isnan(log.sky_lw_wm2[0]) and log.sky_lw_wm2[1] == 301.2
    assert np.isnan(log.wind_ms[1]) and log.rain_mm[1] == 0.2


def test_toa5_errors_name_line_and_column():
    text = toa5_text(_weather(3))
    kmh = parse_toa5(text.replace("meters/second", "km/h"))  # converted, not refused
    np.testing.assert_allclose(kmh.wind_ms, parse_toa5(text).wind_ms / 3.6)
    with pytest.raises(InvalidInput) as e:
        parse_toa5(text.replace("meters/second", "furlongs/fortnight"))
    assert e.value.one_line().startswith("weather.dat: line 3: WS_ms_Avg: unit "
                                         "'furlongs/fortnight' is not a speed unit")
    lines = text.splitlines()
    lines[5] = lines[5].replace('"2026-11-15 00:01:00"', '"yesterday"')
    with pytest.raises(InvalidInput) as e:
        parse_toa5("\n".join(lines))
    assert e.value.one_line() == ("weather.dat: line 6: TIMESTAMP: expected an ISO 8601 UTC "
                                  "time, got 'yesterday'")
    with pytest.raises(InvalidInput, match="not a TOA5"):
        parse_toa5("TIMESTAMP,AirTC\n")
    with pytest.raises(InvalidInput, match=r"line 2: missing relative humidity \(rh_pct, "
                       r"e.g. RH_Avg\); the file has columns TIMESTAMP, RECORD, AirTC_Avg, "
                       r"RHumid"):
        parse_toa5(text.replace("RH_Avg", "RHumid"))


def test_optional_columns_absent_give_nan():
    rows = [r.split(",") for r in toa5_text(_weather(2)).splitlines()]
    text = "\n".join(",".join(r[:7]) for r in rows)
    log = parse_toa5(text)
    assert np.isnan(log.sky_lw_wm2).all() and np.isnan(log.rain_mm).all()


def test_soil_round_trip_and_depth_order(tmp_path):
    depth = np.array([0.5, 0.02, 0.1])
    temp = np.array([[15.0, 20.5, 17.25], [15.0, np.nan, 17.5]])
    write_soil_log(tmp_path / "soil.csv", SoilLog(T0 + np.array([0.0, 600.0]), depth, temp))
    back = read_soil_log(tmp_path / "soil.csv")
    np.testing.assert_array_equal(back.depth_m, [0.02, 0.1, 0.5])
    np.testing.assert_allclose(back.temp_c, temp[:, [1, 2, 0]], equal_nan=True)
    with pytest.raises(InvalidInput, match="is not T_<depth>m_C"):
        parse_soil_log("time_utc,T_surface\n")
    with pytest.raises(InvalidInput, match="line 2: T_0.020m_C: expected a number"):
        parse_soil_log("time_utc,T_0.020m_C\n2026-11-15T00:00:00Z,warm\n")


def test_blackbody_log_and_markers_round_trip(tmp_path):
    log = BlackbodyLog(T0 + 60 * np.arange(5.0), 25 + np.arange(5.0) / 8, np.full(5, 14.5))
    write_blackbody_log(tmp_path / "bb.csv", log)
    back = read_blackbody_log(tmp_path / "bb.csv")
    np.testing.assert_allclose(back.bb1_c, log.bb1_c)
    np.testing.assert_allclose(back.time_s, log.time_s)
    m = Markers(("A", "B,2"), np.array([35.123456789, -1.0]), np.array([33.1, 179.5]),
                ('stake "north"', ""))
    write_markers(tmp_path / "m.csv", m)
    mb = read_markers(tmp_path / "m.csv")
    assert mb.id == m.id and mb.description == m.description
    np.testing.assert_allclose(mb.lat_deg, m.lat_deg, atol=1e-9)


FUZZ = settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
VALID = {
    "toa5": (parse_toa5, toa5_text(_weather(4))),
    "soil": (parse_soil_log, "time_utc,T_0.020m_C,T_0.050m_C\n2026-11-15T00:00:00Z,1.5,2\n"
                             "2026-11-15T00:10:00Z,NAN,2.5\n"),
    "bb": (parse_blackbody_log, "time_utc,bb1_c,bb2_c\n2026-11-15T00:00:00Z,25.0,15.0\n"),
}


@FUZZ
@given(st.sampled_from(sorted(VALID)), st.text(max_size=300))
def test_fuzz_random_text(kind, text):
    parser = VALID[kind][0]
    try:
        parser(text)
    except InvalidInput:
        pass


@FUZZ
@given(st.sampled_from(sorted(VALID)),
       st.lists(st.tuples(st.integers(0, 10_000), st.sampled_from(list('0123456789,."-:TZN\n ')) |
                          st.just("")), min_size=1, max_size=10))
def test_fuzz_mutated_valid_files(kind, edits):
    parser, text = VALID[kind]
    chars = list(text)
    for pos, ch in edits:
        chars[pos % len(chars)] = ch
    try:
        out = parser("".join(chars))
    except InvalidInput:
        return
    assert np.all(np.isfinite(out.time_s))
