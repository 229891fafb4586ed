"""Weather station and thermocouple loggers write files the survey readers read back."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import serial

from clearfast_gis.acquire import ThermocoupleLogger, WeatherStationLogger, toa5_header
from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey import SoilLog, WeatherLog, read_soil_log, read_toa5, write_soil_log
from clearfast_gis.survey.station_profiles import parse_station_profile
from clearfast_gis.survey.toa5 import toa5_text
from clearfast_gis.timeutil import format_utc, parse_utc

T0 = parse_utc("2026-11-15T00:00:00Z")


def _loop():
    return serial.serial_for_url("loop://", timeout=0.05)


def _toa5_line(k: int, air: str = "15.25") -> str:
    ts = format_utc(T0 + 60 * k, "seconds").replace("T", " ").rstrip("Z")
    return f'"{ts}",{100 + k},{air},61.5,1005.3,2.1,{50 * k},301.5,0\r\n'


def test_weather_records_in_contract_order_read_back(tmp_path):
    path = tmp_path / "weather.dat"
    w = WeatherStationLogger(_loop(), path)
    stream = "".join(_toa5_line(k) for k in range(3)) + _toa5_line(3, '"NAN"')
    stream += "garbage line\r\n" + '"2026-13-45 00:00:00",5,1,2,3,4,5,6,7\r\n'
    w.feed(stream.encode())  # no header yet: nothing is mapped by position
    assert (w.n_records, w.n_unmapped, w.n_bad) == (0, 4, 2)
    w.feed((toa5_header() + stream).encode())
    w.log.close()
    assert (w.n_records, w.n_bad) == (4, 4)
    log = read_toa5(path)
    np.testing.assert_array_equal(log.time_s, T0 + 60.0 * np.arange(4))
    np.testing.assert_allclose(log.air_temp_c[:3], 15.25)
    assert math.isnan(log.air_temp_c[3])
    np.testing.assert_allclose(log.solar_wm2, [0, 50, 100, 150])
    np.testing.assert_allclose(log.sky_lw_wm2, 301.5)
    lines = path.read_bytes().split(b"\r\n")
    assert lines[4].split(b",")[1] == b"100"  # the station's record number is kept
    # same bytes as the survey writer for the same records (after the header)
    ref = toa5_text(log).split("\r\n")
    assert path.read_bytes().decode().split("\r\n")[:4] == ref[:4]


def test_weather_header_lines_set_columns_by_name_and_restart_appends(tmp_path):
    path = tmp_path / "weather.dat"
    header = ('"TOA5","station","CR1000X","1","x","y","1","Min"\r\n'
              '"TIMESTAMP","RECORD","RH_Avg","AirTC_Avg","WS_ms_Avg","BP_hPa_Avg","SlrW_Avg"\r\n'
              '"TS","RN","%","Deg C","meters/second","hPa","W/m^2"\r\n'
              '"","","Avg","Avg","Avg","Avg","Avg"\r\n')
    w = WeatherStationLogger(_loop(), path)
    w.feed((header + '"2026-11-15 00:01:00",7,55.0,12.5,3.5,1001.0,0\r\n').encode())
    w.log.close()
    w2 = WeatherStationLogger(_loop(), path)  # restarted logger: the station's header again
    w2.feed((header + '"2026-11-15 00:02:00",,80.0,16.0,1.0,1002.0,10.0\r\n').encode())
    w2.log.close()
    text = path.read_bytes().decode()
    assert text.count('"TOA5"') == 1
    log = read_toa5(path)
    np.testing.assert_allclose(log.air_temp_c, [12.5, 16.0])
    np.testing.assert_allclose(log.rh_pct, [55.0, 80.0])
    np.testing.assert_allclose(log.wind_ms, [3.5, 1.0])
    assert np.isnan(log.sky_lw_wm2).all()  # the station has no pyrgeometer
    assert text.split("\r\n")[5].split(",")[1] == "8"  # counted on from the file


def test_weather_columns_by_name_and_units_converted_never_by_position(tmp_path):
    """A station that sends records without a header had its solar irradiance written as
    air temperature: such lines are refused; its profile's header maps them by name, and a
    station in deg F, inHg and km/h is converted."""
    profile = parse_station_profile(json.dumps({
        "format": "clearfast-station-profile", "format_version": 1,
        "header": ["TIMESTAMP", "RECORD", "SlrW", "WS_kmh", "AirF", "Humid", "Baro"],
        "columns": {"solar_wm2": {"column": "SlrW", "unit": "W/m^2"},
                    "wind_ms": {"column": "WS_kmh", "unit": "km/h"},
                    "air_temp_c": {"column": "AirF", "unit": "deg F"},
                    "rh_pct": {"column": "Humid", "unit": "%"},
                    "pressure_hpa": {"column": "Baro", "unit": "inHg"}}}))
    line = b'"2026-11-15 00:01:00",1,147.0,3.6,59.0,40.0,29.92\r\n'
    events: list[tuple] = []
    bare = WeatherStationLogger(_loop(), tmp_path / "bare.dat", on_event=lambda *e:
                                events.append(e))
    bare.feed(line)
    bare.log.close()
    assert (bare.n_records, bare.n_unmapped) == (0, 1)
    assert events[0][1] == "unmapped" and "no TOA5 field-name line" in events[0][2]
    w = WeatherStationLogger(_loop(), tmp_path / "w.dat", profile=profile)
    w.feed(line)
    w.log.close()
    log = read_toa5(tmp_path / "w.dat")
    assert log.solar_wm2[0] == 147.0 and log.air_temp_c[0] == pytest.approx(15.0)
    assert log.wind_ms[0] == pytest.approx(1.0, abs=1e-5)
    assert log.pressure_hpa[0] == pytest.approx(1013.2, abs=0.05)
    assert log.rh_pct[0] == 40.0


def test_weather_refuses_to_append_to_a_foreign_file(tmp_path):
    path = tmp_path / "weather.dat"
    path.write_text("time,temp\n1,2\n")
    with pytest.raises(InvalidInput, match="not a TOA5 file"):
        WeatherStationLogger(_loop(), path)
    path.write_text(toa5_header().replace("Rain_mm_Tot", "Rain"))
    with pytest.raises(InvalidInput, match="other columns"):
        WeatherStationLogger(_loop(), path)


def test_soil_lines_read_back_and_bad_lines_counted(tmp_path):
    path = tmp_path / "soil.csv"
    depths = (0.02, 0.05, 0.10)
    s = ThermocoupleLogger(_loop(), path, depths)
    s.feed(b"# TC logger v2 ready\r\n"
           b"T,2026-11-15T00:00:00Z,18.4123,17.95,17.031\r\n"
           b"T,2026-11-15T00:10:00,18.5,NAN,17.0\r\n"
           b"T,2026-11-15T00:20:00Z,18.6,17.9\r\n"          # one channel missing
           b"T,not-a-time,1,2,3\r\n"
           b"T,2026-11-15T00:30:00Z,18.7,abc,17.0\r\n"
           b"T,2026-11-15T00:40:00Z,18.8,17.8,17.1\n"
           b"T,2026-11-15T00:50:00Z,18.9")              # unfinished: not written
    s.log.close()
    assert (s.n_records, s.n_bad) == (3, 3)
    log = read_soil_log(path)
    np.testing.assert_array_equal(log.depth_m, depths)
    np.testing.assert_array_equal(log.time_s, T0 + np.array([0.0, 600.0, 2400.0]))
    np.testing.assert_allclose(log.temp_c[[0, 2]], [[18.4123, 17.95, 17.031],
                                                    [18.8, 17.8, 17.1]])
    assert math.isnan(log.temp_c[1, 1])
    # identical to the survey writer's file for the same log
    ref = tmp_path / "ref.csv"
    write_soil_log(ref, SoilLog(log.time_s, log.depth_m, log.temp_c))
    assert path.read_bytes() == ref.read_bytes()


def test_soil_refuses_other_depths_on_restart(tmp_path):
    path = tmp_path / "soil.csv"
    ThermocoupleLogger(_loop(), path, (0.02, 0.05)).log.close()
    with pytest.raises(InvalidInput, match="another header"):
        ThermocoupleLogger(_loop(), path, (0.02, 0.10))
    with pytest.raises(InvalidInput, match="same depth"):
        ThermocoupleLogger(_loop(), tmp_path / "x.csv", (0.02, 0.02))


def test_weather_log_is_the_writer_format():
    log = WeatherLog(*(np.array([v]) for v in (T0, 1.5, 2, 3, 4, 5, 6, 7)))
    assert toa5_header() == "".join(x + "\r\n" for x in toa5_text(log).split("\r\n")[:4])
