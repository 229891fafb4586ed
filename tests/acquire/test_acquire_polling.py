"""The polled weather station and the temperature logger, through ptys and device simulators."""

from __future__ import annotations

import threading
import time

import numpy as np
import pytest

from clearfast_gis.acquire import PortSpec, ThermocoupleLogger, WeatherStationLogger, open_port
from clearfast_gis.acquire.ptydevice import PtyDevice
from clearfast_gis.simulate.devices import (
    ScheduledLines,
    SimulatedTemperatureLogger,
    SimulatedWeatherStation,
)
from clearfast_gis.survey import (
    BlackbodyLog,
    SoilLog,
    WeatherLog,
    read_blackbody_log,
    read_soil_log,
    read_toa5,
)
from clearfast_gis.survey.toa5 import toa5_text
from clearfast_gis.timeutil import parse_utc
from tests.acquire.test_acquire_faults import _until

T0 = parse_utc("2026-11-15T00:00:00Z")


class SceneClock:
    """A scene clock the test sets."""

    def __init__(self, t: float) -> None:
        self.t = t

    def __call__(self) -> float:
        return self.t


def _table(n: int) -> WeatherLog:
    k = np.arange(n, dtype=float)
    return WeatherLog(T0 + 60.0 * k, 10.0 + 0.25 * k, 60.0 + k, 1005.0 + 0.1 * k,
                      np.full(n, 2.0), 5.0 * k, 300.0 + k, np.zeros(n))


class Running:
    """A logger in its thread until the block ends."""

    def __init__(self, logger) -> None:
        self.logger, self.stop = logger, threading.Event()

    def __enter__(self):
        self.thread = self.logger.start(self.stop)
        return self.logger

    def __exit__(self, *exc) -> None:
        self.stop.set()
        self.thread.join(5.0)


def test_polled_station_fills_the_log_and_a_restart_asks_for_the_rest(tmp_path):
    clock = SceneClock(T0 + 5.5 * 60)
    table = _table(10)
    station = SimulatedWeatherStation(table, clock, page=4)
    path = tmp_path / "weather.dat"
    with PtyDevice(station, name="weather") as dev:
        def logger() -> WeatherStationLogger:
            return WeatherStationLogger(open_port(PortSpec(dev.path, 9600)), path, clock=clock,
                                        poll_interval_s=60.0, station="clearfast_sim")

        with Running(logger()) as w:
            _until(lambda: w.n_records == 6)  # records 0-5 exist: a page of 4, MORE, then 2
            assert station.requests == [0, 4]
            clock.t = T0 + 6.2 * 60  # less than a poll interval later: no request
            time.sleep(0.05)
            assert station.requests == [0, 4]
            clock.t = T0 + 6.6 * 60
            _until(lambda: w.n_records == 7)
            assert station.requests == [0, 4, 6] and w.n_polls == 3 and w.n_timeouts == 0
        clock.t = T0 + 20 * 60
        with Running(logger()) as w2:  # the acquisition restarts: no record twice
            _until(lambda: w2.n_records == 3)
        assert station.requests[-1] == 7 and w2.n_duplicates == 0
    # the file is exactly the station's table, written as the survey writer writes it
    assert path.read_bytes() == toa5_text(table, "clearfast_sim").encode()
    log = read_toa5(path)
    np.testing.assert_allclose(log.air_temp_c, table.air_temp_c)


def test_hung_station_and_line_noise_are_counted(tmp_path):
    clock = SceneClock(T0 + 2.5 * 60)
    station = SimulatedWeatherStation(_table(5), clock)
    events: list[tuple] = []
    with PtyDevice(station, name="weather") as dev:
        w = WeatherStationLogger(open_port(PortSpec(dev.path, 9600)), tmp_path / "w.dat",
                                 clock=clock, poll_interval_s=60.0, reply_timeout_s=0.1,
                                 on_event=lambda *e: events.append(e))
        dev.mute = True
        with Running(w):
            _until(lambda: w.n_timeouts == 1)
            clock.t += 61.0
            dev.mute = False
            dev.inject(b"\x15\xfe#!noise\r\n")
            _until(lambda: w.n_records == 4)  # minutes 0 to 3 exist at 3.52 min
            # a duplicate sent by a confused station is not written again
            dev.inject(station.lines[1] + b"END\r\n")
            _until(lambda: w.n_duplicates == 1)
    assert w.n_bad == 1 and w.n_records == 4
    assert events[0] == ("weather", "no reply", "GET 0: no END within 0.1 s")
    assert len(read_toa5(tmp_path / "w.dat")) == 4


def test_temperature_logger_soil_and_blackbody_lines(tmp_path):
    clock = SceneClock(T0 - 1.0)
    t_soil = T0 + 600.0 * np.arange(3)
    soil = SoilLog(t_soil, np.array([0.02, 0.05, 0.1, 0.2, 0.5]),
                   15.0 + np.arange(15.0).reshape(3, 5) / 8.0)
    t_bb = T0 + 60.0 * np.arange(21)
    bb = BlackbodyLog(t_bb, 25.0 + 0.001 * np.arange(21), 15.0 - 0.002 * np.arange(21))
    engine = SimulatedTemperatureLogger(soil, bb, clock)
    with PtyDevice(engine, name="soil") as dev:
        logger = ThermocoupleLogger(open_port(PortSpec(dev.path, 9600)), tmp_path / "soil.csv",
                                    blackbody_path=tmp_path / "blackbody" / "temperatures.csv")
        with Running(logger):
            clock.t = T0 + 1200.0
            _until(lambda: logger.n_blackbody == 21 and logger.n_records == 3)
    out = read_soil_log(tmp_path / "soil.csv")
    np.testing.assert_array_equal(out.time_s, t_soil)
    np.testing.assert_allclose(out.temp_c, np.round(soil.temp_c, 3))
    bbl = read_blackbody_log(tmp_path / "blackbody" / "temperatures.csv")
    np.testing.assert_array_equal(bbl.time_s, t_bb)
    np.testing.assert_allclose(bbl.bb1_c, bb.bb1_c, atol=5e-4)
    np.testing.assert_allclose(bbl.bb2_c, bb.bb2_c, atol=5e-4)
    text = (tmp_path / "blackbody" / "temperatures.csv").read_text()
    assert text.splitlines()[:2] == ["time_utc,bb1_c,bb2_c", "2026-11-15T00:00:00Z,25.0000,15.0000"]
    assert logger.status()["last_blackbody"]["temp_c"] == [25.02, 14.96]


def test_scheduled_lines_restart_with_the_scene_clock():
    """A rig builds its engines (the soil profile can take seconds: a first compile) and then
    sets the scene clock back to the start: after restart() every line due from then on is
    sent."""
    clock = SceneClock(T0 + 5000.0)  # the clock ran on while the engine was built
    engine = ScheduledLines(T0 + 600.0 * np.arange(12), lambda k: b"%d\r\n" % k, clock)
    clock.t = T0 - 1.0  # set back
    engine.restart()
    assert engine.pending_output() == b"" and not engine.finished
    clock.t = T0 + 1200.0
    assert engine.pending_output() == b"0\r\n1\r\n2\r\n"
    clock.t = T0 + 7000.0
    assert engine.pending_output() == b"".join(b"%d\r\n" % k for k in range(3, 12))
    assert engine.finished


@pytest.mark.parametrize("line", ["B,2026-11-15T00:00:00Z,25.0", "B,yesterday,25,15",
                                  "B,2026-11-15T00:00:00Z,25,inf"])
def test_bad_blackbody_lines_are_counted(tmp_path, line):
    import serial
    logger = ThermocoupleLogger(serial.serial_for_url("loop://", timeout=0.05),
                                tmp_path / "soil.csv", blackbody_path=tmp_path / "bb.csv")
    logger.feed((line + "\r\n").encode())
    logger.close_logs()
    assert logger.n_bad == 1 and logger.n_blackbody == 0
    assert (tmp_path / "bb.csv").read_text() == "time_utc,bb1_c,bb2_c\n"
