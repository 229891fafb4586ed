"""A survey cut to its first scans reads the same bytes and validates."""

from __future__ import annotations

import os

import pytest

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey import read_survey, validate_survey
from clearfast_gis.survey.model import read_blackbody_frames
from clearfast_gis.survey.subset import subset_survey
from clearfast_gis.survey.testing import make_minimal_survey


def test_first_scans_kept_and_frames_hard_linked(tmp_path):
    src = make_minimal_survey(tmp_path / "all", n_scans=4, n_positions=3, n_bands=2)
    out = subset_survey(src, tmp_path / "part", 2)
    assert validate_survey(out).valid
    whole, part = read_survey(src), read_survey(out)
    assert sorted(int(s) for s in part.scans) == [0, 1]
    assert len(part.frames.time_s) == 2 * 3 * 2
    assert (part.frames.time_s == whole.frames.time_s[:12]).all()
    a, b = src / "frames" / "scan_001_b1.tif", out / "frames" / "scan_001_b1.tif"
    assert os.stat(a).st_ino == os.stat(b).st_ino  # the same file, not a copy
    assert not (out / "frames" / "scan_002_b0.tif").exists()
    # calibration events up to the first one after the last kept frame
    events = {e.event for e in read_blackbody_frames(part)}
    t_last = part.frames.time_s.max()
    later = [e for e in read_blackbody_frames(whole) if e.time_s > t_last]
    assert max(events) <= min(e.event for e in later)


def test_subset_rejects_more_scans_than_the_survey_has(tmp_path):
    src = make_minimal_survey(tmp_path / "all", n_scans=2)
    with pytest.raises(InvalidInput, match="cannot keep 3 scans of 2"):
        subset_survey(src, tmp_path / "part", 3)
