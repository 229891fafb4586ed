"""The trial preset (the paper's layout) on one scan: planner pattern, 3 bands, validates."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from clearfast_gis.simulate import preset, simulate_survey
from clearfast_gis.survey import read_mission, read_survey
from clearfast_gis.survey.validate import validate_survey


def test_trial_one_scan_validates(tmp_path):
    cfg = replace(preset("trial"), n_scans=1, first_scan_offset_s=10 * 3600.0)
    res = simulate_survey(tmp_path / "trial", cfg, seed=0)
    report = validate_survey(res.root)
    assert report.problems == []
    sv = read_survey(res.root)
    assert sv.manifest["camera"]["resolution"] == [320, 256]
    assert [b.name for b in sv.bands] == ["LW1", "LW2", "LW3"]
    mission = read_mission(res.root / "mission.json")
    assert mission["area"][2] - mission["area"][0] == 30.0
    assert mission["area"][3] - mission["area"][1] == 20.0
    assert 200 <= len(mission["positions"]) <= 300  # the 2004 trial: 261
    # the truth records each band's filter-wheel misregistration
    rows = (res.root / "truth" / "bands.csv").read_text().splitlines()
    shifts = np.array([[float(x) for x in r.split(",")[4:6]] for r in rows[1:]])
    np.testing.assert_allclose(shifts, [b.shift_px for b in cfg.bands])
