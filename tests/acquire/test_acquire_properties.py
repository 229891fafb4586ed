"""Property tests of the acquisition's parsers: whatever arrives, the drivers count it and
never fail; what the simulators send, they read back exactly."""

from __future__ import annotations

import math

import numpy as np
import serial
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.acquire import GnssLogger, ThermocoupleLogger, WeatherStationLogger
from clearfast_gis.acquire.soil import parse_thermocouple_line
from clearfast_gis.simulate.devices import Fault, SimulatedWeatherStation, parse_fault
from clearfast_gis.survey import WeatherLog, gga_sentence, zda_sentence
from clearfast_gis.timeutil import format_utc

T0 = 1794700800.0  # 2026-11-15T00:00:00Z
_times = st.floats(min_value=946684800.0, max_value=4102444799.0).map(lambda t: float(int(t)))
_temps = st.floats(min_value=-60.0, max_value=90.0, allow_nan=False)


def _loop():
    return serial.serial_for_url("loop://", timeout=0.05)


@settings(max_examples=100, deadline=None)
@given(_times, st.lists(st.one_of(_temps, st.just(math.nan)), min_size=1, max_size=8),
       st.sampled_from(["T", "B"]))
def test_temperature_lines_round_trip(t, temps, tag):
    vals = ",".join("NAN" if math.isnan(v) else f"{v:.3f}" for v in temps)
    rec = parse_thermocouple_line(f"{tag},{format_utc(t, 'seconds')},{vals}\r\n", len(temps),
                                  tag)
    assert rec[0] == t
    written = [float(f"{v:.3f}") for v in temps]  # the decimals on the line (0.0025 -> 0.003)
    np.testing.assert_allclose(rec[1], written, atol=1e-9, equal_nan=True)
    other = "B" if tag == "T" else "T"
    assert parse_thermocouple_line(f"{tag},{format_utc(t)},{vals}", len(temps), other) is None


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(_temps, st.floats(0, 100), st.floats(900, 1100),
                          st.floats(0, 30), st.floats(0, 1200)), min_size=1, max_size=6),
       st.integers(1, 4))
def test_station_lines_read_back_exactly(tmp_path_factory, rows, page):
    n = len(rows)
    a = np.round(np.array(rows), 2)
    log = WeatherLog(T0 + 60.0 * np.arange(n), a[:, 0], a[:, 1], a[:, 2], a[:, 3], a[:, 4],
                     np.full(n, 300.0), np.zeros(n))
    station = SimulatedWeatherStation(log, lambda: T0 + 1e6, page=page)
    path = tmp_path_factory.mktemp("w") / "weather.dat"
    w = WeatherStationLogger(_loop(), path, poll_interval_s=60.0)
    first = 0
    while first < n:
        station.feed(f"GET {first}\r\n".encode())
        w.feed(station.pending_output())
        first = w._next_record
    w.close_logs()
    assert w.n_records == n and w.n_bad == 0 and w.n_duplicates == 0
    from clearfast_gis.survey import read_toa5
    back = read_toa5(path)
    np.testing.assert_allclose(back.air_temp_c, log.air_temp_c, atol=1e-9)
    np.testing.assert_allclose(back.solar_wm2, log.solar_wm2, atol=1e-9)


@settings(max_examples=100, deadline=None)
@given(st.binary(max_size=600))
def test_drivers_take_any_bytes(tmp_path_factory, data):
    d = tmp_path_factory.mktemp("any")
    good = (gga_sentence(T0, 35.0, 33.0, 100.0, 4, 12, 0.8) + "\r\n" + zda_sentence(T0)
            + "\r\n").encode()
    for logger in (GnssLogger(_loop(), d / "g.nmea"),
                   WeatherStationLogger(_loop(), d / "w.dat", poll_interval_s=60.0),
                   ThermocoupleLogger(_loop(), d / "s.csv", blackbody_path=d / "bb.csv")):
        logger.feed(data + b"\n" + good)
        logger.close_logs()
        assert logger.n_lines_in == data.count(b"\n") + 3
    assert logger.n_records + logger.n_blackbody <= data.count(b"\n") + 1


@settings(max_examples=100, deadline=None)
@given(st.sampled_from(["unplug", "mute", "noise", "rtk-loss"]),
       st.sampled_from(["gnss", "ptu", "weather", "soil", "camera"]),
       st.integers(0, 10**6), st.integers(1, 10**5))
def test_fault_text_round_trip(kind, device, at, duration):
    if kind == "rtk-loss":
        device = "gnss"
    if device == "camera" and kind != "mute":
        return
    fault = Fault(kind, device, float(at), 0.0 if kind == "noise" else float(duration))
    assert parse_fault(str(fault)) == fault
