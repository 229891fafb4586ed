"""Real station tables: Campbell TOA5 files from public stations (in
``../shared/data/real-field-files/toa5``), station profiles, unit conversions, one error for
everything missing, plausibility (ranges, pressure at altitude, stuck sensors, spikes)."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey import SoilLog, WeatherLog
from clearfast_gis.survey.logs import parse_soil_log
from clearfast_gis.survey.plausibility import check_series, pressure_range_hpa
from clearfast_gis.survey.station_profiles import parse_station_profile
from clearfast_gis.survey.stations import read_station_table
from clearfast_gis.survey.toa5 import parse_weather_table, toa5_text
from clearfast_gis.timeutil import parse_utc
from tests.conftest import SHARED

TOA5 = SHARED / "data" / "real-field-files" / "toa5"
CLIMAVUE = TOA5 / "LouisPauchet__data_SN6134_ClimatVUE_ClimatVIEW_1h.dat"
SKI = TOA5 / "markrusselldev__public_api_SkiSF_MetData.dat"
HAUKEX = TOA5 / "haukex__tests_toa5_TestLogger_Hourly_1.dat"
DAILY = TOA5 / "markrusselldev__public_api_TOA5-example.dat"
real = pytest.mark.skipif(not TOA5.is_dir(), reason="real field files not present")


def _column(path, name: str) -> np.ndarray:
    """A column of a TOA5 file as floats, read with the csv module alone."""
    with open(path, newline="", encoding="utf-8") as fh:
        rows = list(csv.reader(fh))
    i = rows[1].index(name)
    return np.array([float(r[i]) if r[i] != "NAN" else np.nan for r in rows[4:]])


def _profile(**doc) -> object:
    return parse_station_profile(json.dumps({"format": "clearfast-station-profile",
                                             "format_version": 1, **doc}))


@real
def test_climavue50_table_is_recognised_without_a_profile():
    table = read_station_table(CLIMAVUE)
    assert {q: c.column for q, c in table.columns.items()} == {
        "air_temp_c": "AirT_C_Avg", "rh_pct": "RH", "pressure_hpa": "BP_mbar_Avg",
        "wind_ms": "WS_ms_S_WVT", "solar_wm2": "SlrFD_W_Avg", "rain_mm": "Rain_mm_Tot"}
    w = table.weather
    assert len(w) == 371 and w.time_s[0] == parse_utc("2024-07-21T00:00:00Z")
    np.testing.assert_array_equal(w.air_temp_c, _column(CLIMAVUE, "AirT_C_Avg"))
    np.testing.assert_array_equal(w.pressure_hpa, _column(CLIMAVUE, "BP_mbar_Avg"))  # mbar
    np.testing.assert_array_equal(w.wind_ms, _column(CLIMAVUE, "WS_ms_S_WVT"))
    np.testing.assert_array_equal(w.solar_wm2, _column(CLIMAVUE, "SlrFD_W_Avg"))
    assert np.isnan(w.sky_lw_wm2).all()  # no pyrgeometer: estimated downstream
    assert table.findings(altitude_m=10.0) == []  # a real station is plausible


@real
def test_station_in_fahrenheit_mph_and_inhg_is_converted():
    need = ("air_temp_c", "rh_pct", "pressure_hpa", "wind_ms")  # it logs no irradiance
    table = read_station_table(SKI, required=need)
    w = table.weather
    np.testing.assert_allclose(w.air_temp_c, (_column(SKI, "AirTF_Avg") - 32.0) / 1.8,
                               atol=1e-12)
    np.testing.assert_allclose(w.wind_ms, _column(SKI, "WS_mph_Avg") * 0.44704, atol=1e-12)
    np.testing.assert_allclose(w.pressure_hpa, _column(SKI, "BP_inHg_Avg") * 33.8638866667,
                               rtol=1e-10)
    assert w.pressure_hpa[0] == pytest.approx(971.55, abs=0.01)  # 28.69 inHg
    with pytest.raises(InvalidInput) as e:
        read_station_table(SKI)
    msg = e.value.one_line()
    assert "line 2: missing global solar irradiance" in msg
    assert "the file has columns TIMESTAMP, RECORD, AirTF_Max" in msg and "station profile" \
        in msg


@real
def test_one_error_lists_every_missing_quantity_and_the_columns():
    with pytest.raises(InvalidInput) as e:
        read_station_table(HAUKEX)
    msg = e.value.one_line()
    for what in ("air temperature", "relative humidity", "barometric pressure", "wind speed",
                 "global solar irradiance"):
        assert what in msg
    assert "AirT_C(42), RelHumid_Avg(3)" in msg and "--station-profile" in msg
    assert "\n" not in msg


@real
def test_profile_maps_a_stations_own_names():
    prof = _profile(columns={"air_temp_c": {"column": "AirT_C(42)"},
                             "rh_pct": {"column": "RelHumid_Avg(3)", "unit": "%"}})
    table = read_station_table(HAUKEX, prof, required=("air_temp_c", "rh_pct"))
    np.testing.assert_array_equal(table.weather.air_temp_c, _column(HAUKEX, "AirT_C(42)"))
    np.testing.assert_array_equal(table.weather.rh_pct, _column(HAUKEX, "RelHumid_Avg(3)"))
    daily = _profile(columns={"pressure_hpa": {"column": "BaromPres_Max"},
                              "solar_wm2": {"column": "SlrkW_Max"}})
    t = read_station_table(DAILY, daily, required=("pressure_hpa", "solar_wm2"))
    np.testing.assert_allclose(t.weather.pressure_hpa,
                               _column(DAILY, "BaromPres_Max") * 1.33322387415)  # mmHg
    np.testing.assert_allclose(t.weather.solar_wm2, _column(DAILY, "SlrkW_Max") * 1000.0)


def _table(n=30, **over) -> WeatherLog:
    t = parse_utc("2026-11-15T00:00:00Z") + 60.0 * np.arange(n)
    rng = np.random.default_rng(3)
    cols = dict(air_temp_c=15 + rng.normal(0, 0.1, n), rh_pct=60 + rng.normal(0, 1, n),
                pressure_hpa=1005 + rng.normal(0, 0.1, n), wind_ms=np.full(n, 2.0),
                solar_wm2=np.full(n, 100.0), sky_lw_wm2=np.full(n, 300.0),
                rain_mm=np.zeros(n))
    cols.update(over)
    return WeatherLog(time_s=t, **cols)


def test_wrong_columns_are_problems_naming_line_column_and_value():
    # a station whose solar went into the air temperature column and wind into pressure
    n = 30
    w = _table(n, air_temp_c=np.full(n, 147.0), pressure_hpa=np.full(n, 3.5))
    findings = parse_weather_table(toa5_text(w)).findings(altitude_m=160.0)
    texts = [f.text() for f in findings]
    assert texts[0].startswith("AirTC_Avg (air_temp_c): 30 value(s) outside -60..60 deg C, "
                               "first line 5: 147 deg C")
    assert any(t.startswith("BP_hPa_Avg (pressure_hpa): 30 value(s) outside 924.176..1064.18 "
                            "hPa at 160 m, first line 5: 3.5 hPa") for t in texts)
    assert findings[0].line == 5 and findings[0].value == 147.0


def test_stuck_sensor_and_spike():
    t = parse_utc("2026-11-15T00:00:00Z") + 600.0 * np.arange(60)  # 10 h
    v = 15.0 + 0.1 * np.sin(np.arange(60))
    lines = np.arange(60) + 5
    assert check_series("air_temp_c", "T", t, v, lines, "deg C") == []
    stuck = v.copy()
    stuck[10:50] = 14.2  # 6.5 h of one value
    (f,) = check_series("air_temp_c", "T", t, stuck, lines, "deg C")
    assert f.line == 15 and "stuck sensor: 14.2 deg C for 40 records (6.5 h)" in f.message
    spiky = v.copy()
    spiky[20] += 20.0
    (f,) = check_series("air_temp_c", "T", t, spiky, lines, "deg C")
    assert f.line == 25 and f.message.startswith("1 spike(s) of more than 8 deg C")
    # solar is zero all night: never a stuck sensor
    assert check_series("solar_wm2", "S", t, np.zeros(60), lines, "W/m^2") == []
    lo, hi = pressure_range_hpa(0.0)
    assert (lo, hi) == pytest.approx((943.25, 1083.25))
    assert pressure_range_hpa(3000.0)[1] < 780.0


def test_cr1000x_weather_program_with_cnr4_names_needs_no_profile():
    """A CR1000X "Weather" program with a CNR4 (column names of a real quarter-hourly table
    met in the acceptance run): RelHumid sample, WindSpd_m_s_Avg, Rad_SWin_Avg, Rad_LWin_Avg
    were not recognised and every quantity but air, pressure and rain was called missing."""
    w = _table(5)
    names = {"AirTC_Avg": "AirT_C_Avg", "RH_Avg": "RelHumid", "BP_hPa_Avg": "BP_mbar_Avg",
             "WS_ms_Avg": "WindSpd_m_s_Avg", "SlrW_Avg": "Rad_SWin_Avg",
             "IRSky_Avg": "Rad_LWin_Avg"}
    head, rest = toa5_text(w).split("\r\n", 2)[1], toa5_text(w).split("\r\n", 2)
    for old, new in names.items():
        head = head.replace(f'"{old}"', f'"{new}"')
    table = parse_weather_table("\r\n".join([rest[0], head, rest[2]]))
    assert {q: c.column for q, c in table.columns.items() if q != "rain_mm"} == {
        "air_temp_c": "AirT_C_Avg", "rh_pct": "RelHumid", "pressure_hpa": "BP_mbar_Avg",
        "wind_ms": "WindSpd_m_s_Avg", "solar_wm2": "Rad_SWin_Avg", "sky_lw_wm2": "Rad_LWin_Avg"}
    for q in ("air_temp_c", "rh_pct", "pressure_hpa", "wind_ms", "solar_wm2", "sky_lw_wm2"):
        np.testing.assert_allclose(getattr(table.weather, q), getattr(w, q), rtol=1e-5)


@settings(max_examples=60, deadline=None)
@given(st.permutations(list(range(7))))
def test_property_columns_go_by_name_never_by_position(order):
    """Any column order gives the same values (the TOA5 names decide, not positions)."""
    w = _table(4)
    rows = [r.split(",") for r in toa5_text(w).split("\r\n") if r]
    perm = [0, 1] + [2 + k for k in order]
    text = "\r\n".join([",".join(rows[0])] + [",".join(r[i] for i in perm) for r in rows[1:]])
    back = parse_weather_table(text).weather
    for q in ("air_temp_c", "rh_pct", "pressure_hpa", "wind_ms", "solar_wm2", "sky_lw_wm2"):
        np.testing.assert_allclose(getattr(back, q), getattr(w, q), rtol=1e-5)


@settings(max_examples=60, deadline=None)
@given(st.floats(-40, 50), st.sampled_from(["deg F", "°F", "K", "deg C"]))
def test_property_temperature_units(t_c, unit):
    value = {"deg F": t_c * 1.8 + 32.0, "°F": t_c * 1.8 + 32.0, "K": t_c + 273.15,
             "deg C": t_c}[unit]
    text = ('"TOA5","s","CR1000","1","x","y","1","t"\r\n"TIMESTAMP","RECORD","AirT"\r\n'
            f'"TS","RN","{unit}"\r\n"","","Avg"\r\n"2026-11-15 00:00:00",0,{value!r}\r\n')
    prof = _profile(columns={"air_temp_c": {"column": "AirT"}})
    w = parse_weather_table(text, profile=prof, required=("air_temp_c",)).weather
    assert w.air_temp_c[0] == pytest.approx(t_c, abs=1e-9)


def test_profile_errors_name_the_field():
    with pytest.raises(InvalidInput, match=r"columns.wind_ms.unit: unit 'furlongs' is not a "
                       r"speed unit"):
        _profile(columns={"wind_ms": {"column": "WS", "unit": "furlongs"}})
    with pytest.raises(InvalidInput, match="station_profile.json: columns"):
        _profile(columns={"wind": {"column": "WS"}})
    with pytest.raises(InvalidInput, match=r"line 2: missing .*profile column 'Nope' not in "
                       r"the file"):
        parse_weather_table(toa5_text(_table(3)),
                            profile=_profile(columns={"air_temp_c": {"column": "Nope"}}))


def test_soil_logger_table_with_depths_from_the_profile():
    text = ('"TOA5","soil","CR1000X","1","x","y","1","TC"\r\n'
            '"TIMESTAMP","RECORD","TC_Avg(1)","TC_Avg(2)","TC_Avg(3)"\r\n'
            '"TS","RN","Deg F","Deg F","Deg F"\r\n"","","Avg","Avg","Avg"\r\n'
            '"2026-11-15 00:00:00",0,68,59,50\r\n"2026-11-15 00:10:00",1,"NAN",59.9,50\r\n')
    with pytest.raises(InvalidInput) as e:
        parse_soil_log(text)
    assert "needs the depth of each thermocouple column; the file has columns TIMESTAMP, " \
        "RECORD, TC_Avg(1)" in e.value.one_line()
    prof = _profile(soil={"depths": [{"column": "TC_Avg(3)", "depth_m": 0.2},
                                     {"column": "TC_Avg(1)", "depth_m": 0.02},
                                     {"column": "TC_Avg(2)", "depth_m": 0.05}]})
    log = parse_soil_log(text, profile=prof)
    assert isinstance(log, SoilLog)
    np.testing.assert_array_equal(log.depth_m, [0.02, 0.05, 0.2])
    np.testing.assert_allclose(log.temp_c[0], [20.0, 15.0, 10.0])
    assert np.isnan(log.temp_c[1, 0]) and log.temp_c[1, 1] == pytest.approx(15.5)


def test_soil_columns_that_state_their_depth_need_no_profile():
    text = ('"TOA5","soil","CR1000X","1","x","y","1","TC"\r\n'
            '"TIMESTAMP","RECORD","Tsoil_5cm_Avg","Tsoil_20cm_Avg","TC_2cm","BattV"\r\n'
            '"TS","RN","Deg C","Deg C","Deg C","Volts"\r\n"","","Avg","Avg","Smp","Smp"\r\n'
            '"2026-11-15 00:00:00",0,15,12,18,12.9\r\n')
    log = parse_soil_log(text)
    np.testing.assert_allclose(log.depth_m, [0.02, 0.05, 0.2])
    np.testing.assert_allclose(log.temp_c[0], [18.0, 15.0, 12.0])


@real
def test_a_real_weather_table_given_as_the_soil_log_says_what_to_do():
    with pytest.raises(InvalidInput, match="needs the depth of each thermocouple column"):
        parse_soil_log(CLIMAVUE.read_text(), "soil.dat")
