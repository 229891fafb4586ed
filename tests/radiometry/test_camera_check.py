"""Blackbodies as a check of a radiometric camera (issue 20, item 3): the camera's own
temperature of each blackbody against the log, gain and offset recorded per event."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.radiometry.camera import CameraRadiometry
from clearfast_gis.radiometry.camera_check import camera_blackbody_check
from clearfast_gis.survey import read_survey, write_survey_json, write_tiff_stack
from clearfast_gis.survey.logs import BlackbodyLog, write_blackbody_log
from clearfast_gis.survey.tables import write_blackbody_frames_table
from clearfast_gis.survey.testing import minimal_manifest
from clearfast_gis.timeutil import parse_utc

T0 = parse_utc("2026-11-15T00:00:00Z")


def _survey(tmp_path, with_blackbodies: bool = True):
    m = minimal_manifest("cam", 16, 12, 1)
    rad = CameraRadiometry("linear", scale_k=0.01, offset_k=0.0)
    m["camera"]["radiometry"] = rad.to_manifest()
    m["camera"]["bit_depth"] = 16
    if not with_blackbodies:
        for k in ("blackbody_frames", "blackbody_log"):
            m["files"].pop(k)
    write_survey_json(tmp_path / "survey.json", m)
    if with_blackbodies:
        # the camera reads the blackbodies 0.3 K low at 35 C and 0.1 K low at 20 C:
        # gain = 15 / 14.8, offset at blackbody 2 = +0.1 K
        cam_c = {1: 35.0 - 0.3, 2: 20.0 - 0.1}
        rows = {k: [] for k in ("event", "blackbody", "band", "time_s", "file", "page")}
        for ev in range(2):
            stack = []
            for bb in (1, 2):
                for r in range(10):
                    stack.append(np.full((12, 16), round((cam_c[bb] + 273.15) / 0.01),
                                         np.uint16))
                    for k, v in (("event", ev), ("blackbody", bb), ("band", 0),
                                 ("time_s", T0 + 600 + 1500 * ev + 10 * bb + r),
                                 ("file", f"blackbody/event_{ev:03d}_b0.tif"),
                                 ("page", len(stack) - 1)):
                        rows[k].append(v)
            write_tiff_stack(tmp_path / f"blackbody/event_{ev:03d}_b0.tif", np.stack(stack))
        write_blackbody_frames_table(tmp_path / "blackbody" / "frames.csv",
                                     {k: np.asarray(v) for k, v in rows.items()})
        t = T0 + np.arange(0.0, 3601.0, 60.0)
        write_blackbody_log(tmp_path / "blackbody" / "temperatures.csv",
                            BlackbodyLog(t, np.full(t.size, 35.0), np.full(t.size, 20.0)))
    return read_survey(tmp_path)


def test_offset_and_gain_per_event(tmp_path):
    check = camera_blackbody_check(_survey(tmp_path))
    assert [c["event"] for c in check] == [0, 1]
    for c in check:
        assert c["bb1_log_c"] == pytest.approx(35.0) and c["bb2_log_c"] == pytest.approx(20.0)
        assert c["bb1_camera_c"] == pytest.approx(34.7, abs=0.006)
        assert c["bb2_camera_c"] == pytest.approx(19.9, abs=0.006)
        assert c["gain"] == pytest.approx(15.0 / 14.8, abs=1e-3)
        assert c["offset_k"] == pytest.approx(0.1, abs=0.006)
        # the fitted map sends the camera's readings of both blackbodies onto the log
        for cam, log in ((c["bb1_camera_c"], 35.0), (c["bb2_camera_c"], 20.0)):
            mapped = c["bb2_camera_c"] + c["offset_k"] + c["gain"] * (cam - c["bb2_camera_c"])
            assert mapped == pytest.approx(log, abs=0.01)


def test_nothing_to_check_without_blackbodies(tmp_path):
    assert camera_blackbody_check(_survey(tmp_path, with_blackbodies=False)) == []
