"""The drop folder with a radiometric camera (issue 20, item 4): FLIR R-JPEG and TLinear
files answer the requests, the mission runner writes a survey with the camera's radiometry
and no blackbodies, and a camera that changes its radiometry mid-survey is refused."""

from __future__ import annotations

import json
import shutil
import threading
import time

import numpy as np
import pytest

from clearfast_gis.acquire import ManualClock, MissionRunner
from clearfast_gis.acquire.camera import CameraError, DropFolderCamera
from clearfast_gis.cameras import read_frames
from clearfast_gis.cameras.tiff import write_tiff
from clearfast_gis.survey import read_survey, validate_survey
from clearfast_gis.survey.testing import minimal_manifest, minimal_mission
from tests.acquire.test_acquire_mission import T0, FakePtu, _log_instruments
from tests.cameras.conftest import SAMPLES

pytestmark = pytest.mark.filterwarnings("ignore::rasterio.errors.NotGeoreferencedWarning")
W, H = 16, 12


class CameraSide(threading.Thread):
    """Answers each request in ``folder`` with ``write(folder, sequence)``."""

    def __init__(self, folder, write) -> None:
        super().__init__(daemon=True)
        self.folder, self.write = folder, write
        self.done = threading.Event()

    def run(self) -> None:
        last = 0
        while not self.done.is_set():
            try:
                seq = json.loads((self.folder / "request.json").read_text())["sequence"]
            except (OSError, ValueError):
                seq = last
            if seq > last:
                self.write(self.folder, seq)
                last = seq
            time.sleep(0.002)


def tlinear_writer(scale_after: int | None = None):
    def write(folder, seq):
        scale = 0.04 if scale_after is not None and seq > scale_after else 0.01
        counts = np.full((H, W), round((288.15 + seq) / scale), np.uint16)
        write_tiff(folder / f"frame_{seq:06d}.tif", counts, "K", scale=scale)
    return write


def run_mission(tmp_path, write, n_scans=2, n_pos=3):
    drop = tmp_path / "drop"
    drop.mkdir()
    side = CameraSide(drop, write)
    side.start()
    clock = ManualClock(T0)
    try:
        cam = DropFolderCamera(drop, timeout_s=20.0, clock=clock)
        manifest = minimal_manifest("acq", W, H, 1, duration_s=3000.0)
        runner = MissionRunner(minimal_mission(n_scans, n_pos, 1500.0, W, H), FakePtu(clock),
                               cam, tmp_path / "s", manifest=manifest, clock=clock,
                               sleep=clock.sleep)
        return runner.run()
    finally:
        side.done.set()
        side.join()


def test_tlinear_camera_runs_the_mission_into_a_radiometric_survey(tmp_path):
    result = run_mission(tmp_path, tlinear_writer())
    assert result.n_frames == 6
    survey = read_survey(tmp_path / "s")
    assert survey.radiometry.kind == "linear" and survey.radiometry.scale_k == 0.01
    stack = survey.read_scan(1, 0)
    t_k = survey.radiometry.sensor_temperature_k(stack[:, 0, 0])
    np.testing.assert_allclose(t_k, 288.15 + np.array([4, 5, 6]), atol=0.005)
    _log_instruments(tmp_path / "s")
    report = validate_survey(tmp_path / "s")
    # no blackbody files needed with a radiometric camera; markers come from elsewhere
    assert {p.file for p in report.problems} == {"markers.csv"}, report.problems


def test_camera_changing_its_radiometry_is_refused(tmp_path):
    with pytest.raises(CameraError, match="radiometry differs from the survey's"):
        run_mission(tmp_path, tlinear_writer(scale_after=2))


def test_flir_rjpeg_drop_frame(tmp_path):
    src = SAMPLES / "files" / "Nervengift" / "read_thermal.py" / "examples" / "ax8.jpg"
    assert src.exists(), f"real sample missing: {src} (../shared/data lies beside the checkout)"
    drop = tmp_path / "drop"
    drop.mkdir()
    side = CameraSide(drop, lambda d, seq: shutil.copy(src, d / f"frame_{seq:06d}.jpg"))
    side.start()
    try:
        exp = DropFolderCamera(drop, timeout_s=20.0).capture()
    finally:
        side.done.set()
        side.join()
    ref = read_frames(src)[0]
    assert exp.counts.shape == (1, 60, 80)
    np.testing.assert_array_equal(exp.counts[0], ref.raw)
    assert exp.radiometry.kind == "flir-planck" and exp.radiometry.planck == ref.planck
    assert exp.time_s == (ref.time.timestamp(),)
    assert not list(drop.glob("frame_*"))  # read and deleted
