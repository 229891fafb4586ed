"""MissionRunner: calibration events, staged exposures, crash recovery, resume, the drop folder."""

from __future__ import annotations

import threading
import time

import numpy as np
import pytest

from clearfast_gis.acquire.camera import (
    CallableCamera,
    CameraError,
    CameraTimeout,
    DropFolderCamera,
    DropFolderServer,
    Exposure,
    parse_camera_spec,
    read_drop_frame,
    write_drop_frame,
)
from clearfast_gis.acquire.framestore import INCOMING, FrameStore
from clearfast_gis.acquire.mission import Blackbodies, MissionRunner
from clearfast_gis.acquire.simulated import ManualClock
from clearfast_gis.survey import read_blackbody_frames_table, read_frames_table, read_tiff_stack
from clearfast_gis.survey.testing import minimal_mission
from clearfast_gis.timeutil import parse_utc
from tests.acquire.test_acquire_mission import FakeCamera, FakePtu

T0 = parse_utc("2026-11-15T00:00:00Z")
W, H = 16, 12
BB = Blackbodies(heated=(150.0, 20.0), ambient=(-150.0, 20.0), frames=3)


def _runner(root, clock, camera=None, **kw) -> MissionRunner:
    mission = minimal_mission(3, 4, 1500.0, W, H)
    return MissionRunner(mission, FakePtu(clock), camera or FakeCamera(clock, 2), root,
                         settle_s=0.5, clock=clock, sleep=clock.sleep, blackbodies=BB, **kw)


def test_calibration_event_then_positions_each_scan(tmp_path):
    clock = ManualClock(T0)
    ptu, camera = FakePtu(clock), FakeCamera(clock, 2)
    mission = minimal_mission(2, 3, 1500.0, W, H)
    result = MissionRunner(mission, ptu, camera, tmp_path, clock=clock, sleep=clock.sleep,
                           blackbodies=BB).run()
    assert result.n_calibration_frames == 12 and result.n_frames == 6
    # one move per blackbody (frames at the same pointing need no move), then the positions
    targets = [(m[1], m[2]) for m in ptu.moves[:5]]
    assert targets == [(150.0, 20.0), (-150.0, 20.0), (-20.0, -45.0), (-10.0, -45.0),
                       (0.0, -45.0)]
    bb = read_blackbody_frames_table(tmp_path / "blackbody/frames.csv")
    assert len(bb) == 2 * 2 * 3 * 2  # events x blackbodies x frames x bands
    ev0 = bb.take((bb.event == 0) & (bb.band == 1))
    assert list(ev0.blackbody) == [1, 1, 1, 2, 2, 2] and list(ev0.page) == list(range(6))
    np.testing.assert_allclose(ev0.time_s, camera.times[:6])
    pages = read_tiff_stack(tmp_path / "blackbody/event_001_b1.tif")
    # frame k of the run is filled with 1000 + 100 b + k; event 1 starts at exposure 9
    np.testing.assert_array_equal(pages[:, 5, 5], 1100 + np.arange(9, 15))
    fr = read_frames_table(tmp_path / "frames.csv")
    assert list(fr.position[fr.band == 0]) == [0, 1, 2, 0, 1, 2]
    assert not (tmp_path / INCOMING / "scan_000").exists()  # staging emptied


def test_crash_loses_only_the_exposure_in_flight_and_resume_completes(tmp_path):
    clock = ManualClock(T0)
    camera = FakeCamera(clock, 2)

    def dying_camera():
        if len(camera.times) == 8:  # the power fails during exposure 9 (scan 0 position 1)
            raise SystemExit("power cut")
        return camera()

    runner = _runner(tmp_path, clock, dying_camera)
    runner.store.consolidate = lambda scan: None  # killed: no clean-up runs
    with pytest.raises(SystemExit):
        runner.run(resume=True)
    staged = sorted(p.name for p in (tmp_path / INCOMING / "scan_000").iterdir())
    assert staged == ["bb1_000.tif", "bb1_001.tif", "bb1_002.tif", "bb2_000.tif",
                      "bb2_001.tif", "bb2_002.tif", "pos_00000.tif", "pos_00001.tif"][:8]
    assert not (tmp_path / "frames.csv").exists()

    clock.advance(300.0)  # restarted within scan 0's window
    result = _runner(tmp_path, clock, camera).run(resume=True, start_s=T0)
    assert result.missed_scans == [] and result.late_scans == [0]
    assert result.n_calibration_frames == 2 * 6 and result.n_frames == 2 + 2 * 4
    fr = read_frames_table(tmp_path / "frames.csv")
    assert len(fr) == 3 * 4 * 2
    s0 = fr.take((fr.scan == 0) & (fr.band == 0))
    # positions 0-1 were taken before the crash, 2-3 after it; pages in mission order
    np.testing.assert_allclose(s0.time_s[:2], camera.times[6:8])
    assert s0.time_s[2] > s0.time_s[1] + 290.0 and list(s0.page) == [0, 1, 2, 3]
    stack = read_tiff_stack(tmp_path / "frames/scan_000_b0.tif")
    np.testing.assert_array_equal(stack[:2, 5, 5], [1006, 1007])
    bb = read_blackbody_frames_table(tmp_path / "blackbody/frames.csv")
    assert len(bb.take(bb.event == 0)) == 12  # the event of scan 0 was not repeated


def test_interrupted_calibration_event_is_taken_again_whole(tmp_path):
    clock = ManualClock(T0)
    camera = FakeCamera(clock, 2)

    def dying_camera():
        if len(camera.times) == 4:  # during the ambient blackbody
            raise SystemExit("power cut")
        return camera()

    with pytest.raises(SystemExit):
        _runner(tmp_path, clock, dying_camera).run(resume=True, scans=[0])
    clock.advance(600.0)
    result = _runner(tmp_path, clock, camera).run(resume=True, scans=[0], start_s=T0)
    assert result.n_calibration_frames == 6 and result.n_frames == 4
    bb = read_blackbody_frames_table(tmp_path / "blackbody/frames.csv")
    ev = bb.take(bb.band == 0)
    assert list(ev.blackbody) == [1, 1, 1, 2, 2, 2]
    np.testing.assert_allclose(ev.time_s, camera.times[4:10])  # all after the restart


def test_resume_skips_scans_whose_window_has_passed(tmp_path):
    clock = ManualClock(T0)
    _runner(tmp_path, clock).run(scans=[0])
    clock.now_s = T0 + 3100.0  # scan 1's window (1500-3000 s) is over; scan 2 (3000 s) runs
    events: list[tuple] = []
    result = _runner(tmp_path, clock, on_event=lambda *e: events.append(e)).run(
        resume=True, start_s=T0)
    assert result.missed_scans == [1] and result.scans == [2] and result.late_scans == [2]
    assert ("mission", "missed", "scan 1: its window ended 100 s ago") in events
    fr = read_frames_table(tmp_path / "frames.csv")
    assert sorted(set(fr.scan.tolist())) == [0, 2]
    moves = [e for e in events if e[1] == "move"]
    assert moves[0][2] == "scan 2 blackbody 1: pan 150.000 tilt 20.000 -> 150.010 19.990"


def test_consolidation_repeated_after_a_crash_between_tiff_and_table(tmp_path):
    clock = ManualClock(T0)
    runner = _runner(tmp_path, clock)
    runner.run(scans=[0])
    reference = {p: (tmp_path / p).read_bytes() for p in
                 ("frames.csv", "frames/scan_000_b0.tif", "blackbody/frames.csv")}
    # take scan 0 position 3 again: its new exposure is staged, then consolidation dies after
    # writing the TIFF, before the table
    store: FrameStore = runner.store
    cap = store.read_staged(store.stage(_capture_again(tmp_path, store)))
    real = store._write_table
    store._write_table = lambda *a: (_ for _ in ()).throw(OSError("disk gone"))
    with pytest.raises(OSError):
        store.consolidate(0)
    store._write_table = real
    store.consolidate(0)  # the next run does it again, completely
    fr = read_frames_table(tmp_path / "frames.csv")
    row = fr.take((fr.scan == 0) & (fr.position == 3) & (fr.band == 0))
    assert row.time_s[0] == cap.time_s[0] and row.page[0] == 3
    stack = read_tiff_stack(tmp_path / "frames/scan_000_b0.tif")
    assert stack.shape[0] == 4 and stack[3, 0, 0] == 7
    assert (tmp_path / "blackbody/frames.csv").read_bytes() == reference["blackbody/frames.csv"]
    old = reference["frames.csv"].decode().splitlines()
    new = (tmp_path / "frames.csv").read_text().splitlines()
    assert [a for a, b in zip(old, new, strict=True) if a != b] == old[7:9]  # position 3


def _capture_again(root, store):
    from clearfast_gis.acquire.framestore import POSITION, Capture
    counts = np.full((2, H, W), 7, np.uint16)
    return Capture(0, POSITION, 3, 0, 1.5, -45.0, (T0 + 999.0, T0 + 999.4), counts)


def test_camera_timeout_is_retried_once_then_fails(tmp_path):
    clock = ManualClock(T0)
    camera = FakeCamera(clock, 2)
    fails = {"n": 0}

    def flaky():
        if len(camera.times) == 7 and fails["n"] < 1:
            fails["n"] += 1
            raise CameraTimeout("camera: no frame_000008.tif within 10 s", "/drop")
        return camera()

    result = _runner(tmp_path, clock, flaky).run(scans=[0])
    assert result.n_retries == 1 and result.n_frames == 4

    def dead():
        raise CameraTimeout("camera: no frame within 10 s", "/drop")

    with pytest.raises(CameraTimeout):
        _runner(tmp_path / "b", clock, dead).run(scans=[0])


def test_drop_folder_round_trip_and_timeout(tmp_path):
    drop = tmp_path / "drop"
    drop.mkdir()
    (drop / "frame_000001.tif").write_bytes(b"left over from a previous session")
    counts = np.arange(2 * H * W, dtype=np.uint16).reshape(2, H, W)
    seen = []

    def grab():
        seen.append(time.monotonic())
        return Exposure(counts + len(seen), (T0 + len(seen), T0 + len(seen) + 0.4))

    server = DropFolderServer(CallableCamera(grab), drop).start()
    try:
        cam = DropFolderCamera(drop, timeout_s=2.0, clock=lambda: T0)
        assert not (drop / "frame_000001.tif").exists()
        for k in (1, 2, 3):
            exp = cam.capture()
            np.testing.assert_array_equal(exp.counts, counts + k)
            assert exp.time_s == (T0 + k, T0 + k + 0.4)
        assert server.n_frames == 3 and not list(drop.glob("frame_*"))
        server.mute = True
        t0 = time.monotonic()
        with pytest.raises(CameraTimeout) as err:
            cam.timeout_s = 0.2
            cam.capture()
        assert str(err.value) == f"{drop}: camera: no frame_000004.tif within 0.2 s"
        assert 0.2 <= time.monotonic() - t0 < 2.0
        server.mute = False  # a late frame of request 4 is never taken for request 5
        cam.timeout_s = 2.0
        exp = cam.capture()
        assert len(seen) in (4, 5)  # the server may answer request 4 before it sees 5
        np.testing.assert_array_equal(exp.counts, counts + len(seen))
        assert not list(drop.glob("frame_*"))  # a late frame is cleared too
        cam.close()
    finally:
        server.stop()


def test_drop_frames_and_specs_are_checked(tmp_path):
    path = write_drop_frame(tmp_path, 7, Exposure(np.zeros((1, 3, 4), np.uint16), None))
    assert path.name == "frame_000007.tif" and read_drop_frame(path).time_s is None
    (tmp_path / "bad.tif").write_bytes(b"II*\x00garbage")
    with pytest.raises(CameraError, match="unreadable frame"):
        read_drop_frame(tmp_path / "bad.tif")
    with pytest.raises(CameraError, match="drop folder not found"):
        DropFolderCamera(tmp_path / "nope")
    spec = parse_camera_spec(f"drop:{tmp_path},timeout=2.5")
    assert (spec.folder, spec.timeout_s) == (str(tmp_path), 2.5)
    for bad in ("usb:0", "drop:", f"drop:{tmp_path},timeout=-1", "drop:x,timeout=abc"):
        with pytest.raises(ValueError):
            parse_camera_spec(bad)


def test_stop_request_ends_after_the_current_exposure(tmp_path):
    clock = ManualClock(T0)
    stop = threading.Event()
    camera = FakeCamera(clock, 2)

    def stopping():
        frame = camera()
        if len(camera.times) == 2:
            stop.set()
        return frame

    result = _runner(tmp_path, clock, stopping, stop=stop).run(resume=True)
    assert result.stopped and result.n_calibration_frames == 2 and result.n_frames == 0
    bb = read_blackbody_frames_table(tmp_path / "blackbody/frames.csv")
    assert len(bb) == 4 and not (tmp_path / INCOMING / "scan_000").exists()
