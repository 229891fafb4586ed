"""What cannot be a mine is set aside as a candidate, with its reason."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from clearfast_gis.detection.screening import (
    MAX_DIAMETER_M,
    MIN_DIAMETER_M,
    MIN_SCANS,
    screen,
    set_aside_reason,
)


def rec(aid="A1", area_m2=0.01, diameter_m=0.104, n_scans=6):
    return {"anomaly_id": aid, "area_m2": area_m2, "diameter_m": diameter_m, "n_scans": n_scans}


def test_an_ap_mine_footprint_stays_a_suspect():
    assert set_aside_reason(rec(), 48) is None
    assert set_aside_reason(rec(area_m2=0.09, diameter_m=0.337), 48) is None


def test_one_cell_blob_is_set_aside_by_its_area():
    why = set_aside_reason(rec(area_m2=0.0004, diameter_m=0.068), 48)
    assert why is not None and "4 cm2" in why and "smallest mine" in why


@pytest.mark.parametrize(("diameter", "word"), [(0.04, "smaller"), (0.9, "larger")])
def test_footprints_outside_the_mine_sizes(diameter, word):
    why = set_aside_reason(rec(area_m2=math.pi * diameter**2 / 4, diameter_m=diameter), 48)
    assert why is not None and word in why


def test_too_few_scans_unless_a_single_image():
    assert "seen in 1 of 48 scans" in set_aside_reason(rec(n_scans=1), 48)
    assert set_aside_reason(rec(n_scans=2), 6) is None  # drifting lift: a mine in 2 of 6
    assert set_aside_reason(rec(n_scans=1), 1) is None


@given(st.floats(0.0, 2.0), st.floats(0.0, 2.0), st.integers(0, 48))
def test_screen_partitions_and_keeps_order(area, diameter, n):
    records = [rec("A1"), rec("A2", area, diameter, n), rec("A3", 0.0001, 0.01, 1)]
    suspects, candidates = screen(records, 48)
    assert len(suspects) + len(candidates) == 3
    assert [r["anomaly_id"] for r in suspects] == sorted(r["anomaly_id"] for r in suspects)
    assert all(r["set_aside_reason"] for r in candidates)
    kept = MIN_DIAMETER_M <= diameter <= MAX_DIAMETER_M and n >= MIN_SCANS \
        and area >= math.pi * (MIN_DIAMETER_M / 2) ** 2
    assert any(r["anomaly_id"] == "A2" for r in suspects) == kept
