"""Placement of the frames against the simulated survey's true poses (issue #6)."""

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.evaluation.truth import placement_errors, rigid_residual_px

PIXEL_M = 0.02


def _points(n: int = 200, seed: int = 0) -> np.ndarray:
    return np.random.default_rng(seed).uniform([-10, -15], [10, 15], (n, 2))


@given(st.floats(-0.1, 0.1), st.floats(-0.1, 0.1))
@settings(max_examples=30, deadline=None)
def test_rigid_residual_of_a_shift_is_its_length(dx, dy):
    x = _points()
    d = np.tile([dx, dy], (len(x), 1))
    assert rigid_residual_px(x, d, PIXEL_M) == pytest.approx(math.hypot(dx, dy) / PIXEL_M,
                                                             abs=1e-9)


def test_rigid_residual_of_a_rotation_is_its_rms_arc():
    x = _points()
    theta = 1e-4  # radians about the points' centroid
    xc = x - x.mean(axis=0)
    d = theta * np.column_stack([-xc[:, 1], xc[:, 0]])
    want = theta * np.sqrt(np.mean(np.sum(xc ** 2, axis=1))) / PIXEL_M
    assert rigid_residual_px(x, d, PIXEL_M) == pytest.approx(want, rel=1e-9)


def test_rigid_residual_ignores_what_no_rigid_motion_explains():
    """A scale change (or noise) is not a misregistration that a rotation and shift make."""
    x = _points()
    d = 1e-3 * (x - x.mean(axis=0))
    assert rigid_residual_px(x, d, PIXEL_M) == pytest.approx(0.0, abs=1e-9)
    assert math.isnan(rigid_residual_px(x[:2], d[:2], PIXEL_M))


def test_demo_placement_against_true_poses(demo_survey, demo_products):
    """Every scan's content lies within 3 cm RMS of its true place, and its misregistration
    against the reference scan, cell by cell, is at most half a mosaic cell."""
    score = placement_errors(demo_survey, demo_products)
    manifest = json.loads((demo_products / "products.json").read_text())
    assert score.reference_scan == manifest["scans"][1]["reference_scan"]
    assert score.scans == [r["scan"] for r in manifest["scans"]]
    assert max(score.abs_rms_m) < 0.03, score.abs_rms_m
    k = score.scans.index(score.reference_scan)
    assert math.isnan(score.relative_px[k])
    assert math.isnan(score.relative_rigid_px[k])
    rel = [v for i, v in enumerate(score.relative_px) if i != k]
    rigid = [v for i, v in enumerate(score.relative_rigid_px) if i != k]
    assert all(np.isfinite(rel)) and max(rel) <= 0.5, rel
    assert all(0 <= r <= v + 1e-9 for r, v in zip(rigid, rel, strict=True)), (rigid, rel)
