"""MissionRunner: stop-and-go scans into a survey folder the survey readers accept."""

from __future__ import annotations

import threading

import numpy as np
import pytest
import serial

from clearfast_gis.acquire import (
    GnssLogger,
    ManualClock,
    MissionRunner,
    PanTiltUnit,
    SimulatedPtu,
    ThermocoupleLogger,
    WeatherStationLogger,
    simulated_ptu_device,
)
from clearfast_gis.acquire.weather import toa5_header
from clearfast_gis.errors import ClearfastError, InvalidInput
from clearfast_gis.survey import (
    gga_sentence,
    read_frames_table,
    read_mission,
    read_survey,
    read_tiff_stack,
    rmc_sentence,
    validate_survey,
)
from clearfast_gis.survey.testing import minimal_manifest, minimal_mission
from clearfast_gis.timeutil import format_utc, parse_utc

T0 = parse_utc("2026-11-15T00:00:00Z")
W, H = 16, 12


class FakePtu:
    """Moves take 2 s on the clock; read-back is quantised to 0.05 degree."""

    def __init__(self, clock: ManualClock) -> None:
        self.clock = clock
        self.moves: list[tuple[float, float, float]] = []

    def move_to(self, pan_deg: float, tilt_deg: float) -> tuple[float, float]:
        self.clock.advance(2.0)
        self.moves.append((self.clock(), pan_deg, tilt_deg))
        return round(pan_deg / 0.05) * 0.05 + 0.01, round(tilt_deg / 0.05) * 0.05 - 0.01


class FakeCamera:
    """Each frame is filled with its sequence number (x 100 per band)."""

    def __init__(self, clock: ManualClock, n_bands: int = 1) -> None:
        self.clock = clock
        self.n_bands = n_bands
        self.times: list[float] = []

    def __call__(self) -> np.ndarray:
        k = len(self.times)
        self.times.append(self.clock())
        frame = np.empty((self.n_bands, H, W), np.uint16)
        for b in range(self.n_bands):
            frame[b] = 1000 + 100 * b + k
        frame[:, 0, 0] = np.arange(self.n_bands)
        return frame[0] if self.n_bands == 1 else frame


@pytest.mark.parametrize("n_bands", [1, 2])
def test_two_scans_three_positions(tmp_path, n_bands):
    clock = ManualClock(T0)
    ptu, camera = FakePtu(clock), FakeCamera(clock, n_bands)
    mission = minimal_mission(2, 3, 1500.0, W, H)
    manifest = minimal_manifest("acq", W, H, n_bands, duration_s=3000.0)
    runner = MissionRunner(mission, ptu, camera, tmp_path / "s", manifest=manifest,
                           settle_s=0.5, clock=clock, sleep=clock.sleep)
    result = runner.run()
    assert result.scans == [0, 1] and result.n_frames == 6 and not result.stopped
    assert result.late_scans == []
    # stop-and-go: the camera fires settle_s after each move completes
    np.testing.assert_allclose(camera.times, [m[0] + 0.5 for m in ptu.moves])
    # scan 1 starts at its planned time (T0 + 1500 s), not when scan 0 ended
    assert ptu.moves[3][0] == pytest.approx(T0 + 1500.0 + 2.0)

    survey = read_survey(tmp_path / "s")
    assert list(survey.scans) == [0, 1] and list(survey.positions) == [0, 1, 2]
    fr = survey.frames
    assert len(fr) == 6 * n_bands
    for b in range(n_bands):
        stack = survey.read_scan(1, b)
        assert stack.shape == (3, H, W) and stack.dtype == np.uint16
        np.testing.assert_array_equal(stack[:, 5, 5], 1000 + 100 * b + np.array([3, 4, 5]))
        assert survey.read_frame(0, 2, b)[5, 5] == 1000 + 100 * b + 2
    rows = fr.take((fr.band == 0) & (fr.scan == 1))
    np.testing.assert_allclose(rows.time_s, camera.times[3:], atol=1e-3)
    np.testing.assert_allclose(rows.pan_deg, [-19.99, -9.99, 0.01], atol=1e-6)
    np.testing.assert_allclose(rows.tilt_deg, -45.01, atol=1e-6)
    assert list(rows.file) == ["frames/scan_001_b0.tif"] * 3 and list(rows.page) == [0, 1, 2]
    assert read_mission(tmp_path / "s" / "mission.json") == mission

    _log_instruments(tmp_path / "s")
    report = validate_survey(tmp_path / "s")
    # everything this package writes validates; blackbody and markers come from elsewhere
    assert {p.file for p in report.problems} == {"blackbody/frames.csv",
                                                 "blackbody/temperatures.csv", "markers.csv"}


def _log_instruments(root) -> None:
    """GNSS, weather and soil records over the survey's hour, through the loggers."""
    loop = serial.serial_for_url("loop://", timeout=0.05)
    gnss, weather = GnssLogger(loop, root / "gnss.nmea"), WeatherStationLogger(loop, root /
                                                                               "weather.dat")
    soil = ThermocoupleLogger(loop, root / "soil.csv")
    weather.feed(toa5_header().encode())  # the station's header: columns go by name
    for t in T0 + np.arange(0.0, 3001.0, 5.0):
        gnss.feed((gga_sentence(t, 35.17, 33.36, 170.0, 4, 14, 0.7) + "\r\n"
                   + rmc_sentence(t, 35.17, 33.36) + "\r\n").encode())
        ts = format_utc(t, "seconds")
        if t % 60 == 0:
            weather.feed(f'"{ts[:-1]}",0,15.0,60.0,1005.0,2.0,0,300,0\r\n'.encode())
        if t % 600 == 0:
            soil.feed(f"T,{ts},18,17,16,15,14\r\n".encode())
    for logger in (gnss, weather, soil):
        logger.log.close()


def test_stop_mid_scan_keeps_the_frames_taken_and_resume_completes(tmp_path):
    clock = ManualClock(T0)
    stop = threading.Event()
    camera = FakeCamera(clock)

    def camera_then_stop() -> np.ndarray:
        frame = camera()
        if len(camera.times) == 4:  # first frame of scan 1
            stop.set()
        return frame

    mission = minimal_mission(2, 3, 1500.0, W, H)
    root = tmp_path / "s"
    r = MissionRunner(mission, FakePtu(clock), camera_then_stop, root, clock=clock,
                      sleep=clock.sleep, stop=stop).run()
    assert r.stopped and r.scans == [0, 1] and r.n_frames == 4
    fr = read_frames_table(root / "frames.csv")
    assert list(fr.scan) == [0, 0, 0, 1]

    clock.advance(100.0)  # later: take scan 1 again, completely; it starts late
    r2 = MissionRunner(mission, FakePtu(clock), camera, root, clock=clock,
                       sleep=clock.sleep).run(scans=[1], start_s=T0)
    assert r2.scans == [1] and r2.late_scans == [1] and not r2.stopped
    fr = read_frames_table(root / "frames.csv")
    assert list(fr.scan) == [0, 0, 0, 1, 1, 1] and list(fr.page) == [0, 1, 2, 0, 1, 2]


def test_with_the_ptu_driver_over_a_pty(tmp_path):
    clock = ManualClock(T0)
    mission = minimal_mission(2, 3, 1500.0, W, H)
    with simulated_ptu_device(SimulatedPtu()) as (name, sim):
        port = serial.Serial(name, 9600, timeout=0.05)
        try:
            ptu = PanTiltUnit(port, timeout_s=2.0)
            ptu.initialize()
            MissionRunner(mission, ptu, FakeCamera(clock), tmp_path, clock=clock,
                          sleep=clock.sleep).run()
        finally:
            port.close()
    assert sim.received.count("A") == 6
    fr = read_frames_table(tmp_path / "frames.csv")
    res = 185.1428 / 3600.0
    steps = np.round(np.array([-20.0, -10.0, 0.0]) / res)
    np.testing.assert_allclose(fr.pan_deg, np.tile(steps * res, 2), atol=1e-6)
    np.testing.assert_allclose(fr.tilt_deg, np.round(-45.0 / res) * res, atol=1e-6)


def test_bad_inputs_are_reported(tmp_path):
    clock = ManualClock(T0)
    mission = minimal_mission(1, 2, 60.0, W, H)
    bad = dict(mission, n_scans=0)
    with pytest.raises(InvalidInput, match="mission.json: n_scans"):
        MissionRunner(bad, FakePtu(clock), FakeCamera(clock), tmp_path)
    runner = MissionRunner(mission, FakePtu(clock), lambda: np.zeros((H, W), np.float32),
                           tmp_path, clock=clock, sleep=clock.sleep)
    with pytest.raises(ClearfastError, match="camera: camera returned a .* float32 array"):
        runner.run()
    manifest = minimal_manifest("x", W + 1, H)
    runner = MissionRunner(mission, FakePtu(clock), FakeCamera(clock), tmp_path,
                           manifest=manifest, clock=clock, sleep=clock.sleep)
    with pytest.raises(ClearfastError,
                       match=r"shape \(1, 12, 16\), expected \(1, 12, 17\) .* survey.json"):
        runner.run()
    with pytest.raises(InvalidInput, match="scan 3 is not in the mission"):
        MissionRunner(mission, FakePtu(clock), FakeCamera(clock), tmp_path,
                      clock=clock, sleep=clock.sleep).run(scans=[3])


def test_frames_taken_before_a_device_failure_are_kept(tmp_path):
    clock = ManualClock(T0)
    mission = minimal_mission(1, 3, 60.0, W, H)
    ptu = FakePtu(clock)

    class FailingPtu:
        def move_to(self, pan_deg: float, tilt_deg: float) -> tuple[float, float]:
            if len(ptu.moves) == 2:
                raise ClearfastError("pan/tilt unit: no reply to 'A' within 60 s", "/dev/ttyS0")
            return ptu.move_to(pan_deg, tilt_deg)

    with pytest.raises(ClearfastError, match="no reply to 'A'"):
        MissionRunner(mission, FailingPtu(), FakeCamera(clock), tmp_path, clock=clock,
                      sleep=clock.sleep).run()
    fr = read_frames_table(tmp_path / "frames.csv")
    assert list(fr.position) == [0, 1]
    assert read_tiff_stack(tmp_path / "frames/scan_000_b0.tif").shape == (2, H, W)
