"""Operating curves and the reliability table."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.evaluation.operating import (
    expected_operating_curve,
    operating_curve,
    pd_at_false_alarm_rate,
    reliability_table,
)


def test_measured_curve_down_a_ranked_list():
    # 5 suspects: mine 0, false alarm, mine 1, deep mine (not scored, not a false alarm), FA
    hit = np.array([0, -1, 1, -1, -1])
    fa = np.array([False, True, False, False, True])
    pd, fa_m2 = operating_curve(hit, fa, n_mines=2, area_m2=100.0)
    assert pd.tolist() == [0.0, 0.5, 0.5, 1.0, 1.0, 1.0]
    assert fa_m2.tolist() == pytest.approx([0, 0, 0.01, 0.01, 0.01, 0.02])
    assert pd_at_false_alarm_rate(pd, fa_m2, 0.01) == 1.0
    assert pd_at_false_alarm_rate(pd, fa_m2, 0.005) == 0.5


def test_expected_curve_sums_the_likelihoods():
    c = expected_operating_curve(np.array([0.9, 0.6, 0.1]), 50.0)
    assert c["priority"] == [1, 2, 3]
    assert c["expected_mines"] == pytest.approx([0.9, 1.5, 1.6])
    assert c["expected_false_alarms_per_m2"] == pytest.approx([0.002, 0.01, 0.028])


def test_reliability_of_a_calibrated_predictor():
    rng = np.random.default_rng(0)
    p = rng.uniform(0, 1, 20000)
    y = rng.uniform(0, 1, p.size) < p
    for row in reliability_table(p, y):
        assert row["n"] > 0
        assert row["mine_fraction"] == pytest.approx(row["mean_p"], abs=0.03)
    empty = reliability_table(np.array([0.05]), np.array([False]))
    assert empty[-1]["n"] == 0 and empty[-1]["mine_fraction"] is None
