"""Survey-wide attitude adjustment: recovered truth from synthetic ties."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from clearfast_gis.attitude import (
    LinearTie,
    adjust_attitudes,
    attitude_at,
    displacement_jacobian,
    interpolation_weights,
    moved_point,
)
from clearfast_gis.geometry.cameras import EquiangularCamera
from clearfast_gis.geometry.pose import CameraPose, pose_from_ptu

CAMERA = EquiangularCamera(320, 256, 16.0)
POSITION = np.array([0.0, 0.0, 13.0])
#: the scan pattern: (azimuth, elevation) degrees
PATTERN = [(az, el) for el in (-35.0, -55.0) for az in np.linspace(-40.0, 40.0, 9)]
SCAN_S = 1800.0
FRAME_S = 3.0


def true_attitude(t_s: np.ndarray) -> np.ndarray:
    """A sinking, tilting lift: saturating drift (12 h time constant), degrees (N, 3)."""
    f = 1.0 - np.exp(-np.atleast_1d(t_s) / 43200.0)
    return np.column_stack([-6.0 * f, 3.0 * f, 4.5 * f])


def pose(k: int, attitude) -> CameraPose:
    az, el = PATTERN[k]
    return CameraPose(POSITION, az, el, tuple(float(a) for a in attitude))


def frame_time(scan: int, k: int) -> float:
    return scan * SCAN_S + k * FRAME_S


def placed(k: int, t: float, base, ground: np.ndarray) -> np.ndarray:
    """Where content truly at ``ground`` is put when the frame is placed with ``base``."""
    uv = CAMERA.project(np.array([[ground[0], ground[1], 0.0]]), pose(k, true_attitude(t)[0]))
    return CAMERA.ground_points(uv[:, 0], uv[:, 1], pose(k, base))[0, :2]


def centre_ground(k: int, t: float) -> np.ndarray:
    p = pose(k, true_attitude(t)[0])
    return CAMERA.ground_points(np.array([159.5]), np.array([127.5]), p)[0, :2]


def synthetic_ties(bases: np.ndarray, ref: int, marker_scans: set[int], markers_per_scan: int
                   ) -> list[LinearTie]:
    ties = []
    for s, base in enumerate(bases):
        for k in range(len(PATTERN)):
            t = frame_time(s, k)
            ground = centre_ground(k, t)
            p = placed(k, t, base, ground)
            jac = displacement_jacobian(CAMERA, pose(k, base), *p)
            if s in marker_scans and k < markers_per_scan:
                ties.append(LinearTie(s, t, base, jac, ground - p, 5.0))
            if s != ref:
                tr = frame_time(ref, k)
                pr = placed(k, tr, bases[ref], ground)
                ties.append(LinearTie(s, t, base, jac, pr - p, 1.0, ref, tr, bases[ref],
                                      displacement_jacobian(CAMERA, pose(k, bases[ref]), *pr)))
    return ties


def test_moved_point_and_jacobian_agree():
    p = pose(3, (0.2, -0.1, 0.3))
    x, y = centre_ground(3, 0.0)
    jac = displacement_jacobian(CAMERA, p, x, y)
    step = np.array([0.05, -0.03, 0.02])
    moved = moved_point(CAMERA, p, x, y, np.array(p.attitude_rpy_deg) + step)
    np.testing.assert_allclose(moved - (x, y), jac @ step, atol=1e-4)
    np.testing.assert_allclose(moved_point(CAMERA, p, x, y, p.attitude_rpy_deg), (x, y),
                               atol=1e-9)
    # about 13 m x 1/57 rad per degree at these ranges
    assert 0.1 < np.abs(jac).max() < 1.0


def test_interpolation_reproduces_nodes_and_lines():
    nodes_t = np.array([0.0, 10.0, 30.0])
    nodes = np.array([[0.0, 1.0, 2.0], [1.0, 1.0, 0.0], [3.0, 0.0, 0.0]])
    np.testing.assert_allclose(attitude_at(nodes_t, nodes_t, nodes), nodes)
    np.testing.assert_allclose(attitude_at(np.array([5.0, 20.0]), nodes_t, nodes),
                               [[0.5, 1.0, 1.0], [2.0, 0.5, 0.0]])
    # linear extrapolation at both ends
    np.testing.assert_allclose(attitude_at(np.array([-10.0, 40.0]), nodes_t, nodes),
                               [[-1.0, 1.0, 4.0], [4.0, -0.5, 0.0]])
    i0, i1, w1 = interpolation_weights(np.array([7.0]), np.array([3.0]))
    assert (i0[0], i1[0], w1[0]) == (0, 0, 0.0)


@given(st.lists(st.floats(-1e3, 1e3), min_size=25, max_size=25), st.booleans())
def test_linear_tie_round_trip(values, with_ref):
    v = [3, 1.7e9] + values[:12] if not with_ref else [3, 1.7e9] + values[:12] + [
        1, 1.6e9] + values[12:21]
    tie = LinearTie.from_list(v)
    assert tie.as_list() == pytest.approx(v)
    assert (tie.ref_scan is None) != with_ref


def test_adjustment_recovers_a_drifting_attitude():
    n_scans, ref = 8, 4
    node_times = np.array([np.mean([frame_time(s, k) for k in range(len(PATTERN))])
                           for s in range(n_scans)])
    truth = true_attitude(node_times)
    rng = np.random.default_rng(1)
    # each scan's own fit: off by up to ~0.15 deg (the reference scan too)
    bases = truth + rng.normal(0.0, 0.08, truth.shape)
    ties = synthetic_ties(bases, ref, marker_scans={2, 3, 5, 6}, markers_per_scan=2)
    adj = adjust_attitudes(ties, list(range(n_scans)), node_times, bases)
    before = np.abs(bases - truth).max()
    after = np.abs(adj.nodes_rpy_deg - truth).max()
    assert before > 0.1
    assert after < 0.02 and after < before / 5, (after, adj.nodes_rpy_deg - truth)
    assert adj.rms_m < 0.1 * adj.rms_before_m
    assert adj.n_used == adj.n_ties == len(ties)


def test_adjustment_rejects_an_outlier_and_smooths_scans_without_ties():
    n_scans, ref = 5, 2
    node_times = np.array([frame_time(s, 8) for s in range(n_scans)])
    truth = true_attitude(node_times)
    bases = truth + 0.05
    ties = synthetic_ties(bases, ref, marker_scans={0, 1, 2, 3, 4}, markers_per_scan=3)
    bad = ties[0]
    ties.append(LinearTie(bad.scan, bad.time_s, bad.base_rpy_deg, bad.jac,
                          bad.d_m + (0.5, -0.4), 5.0))
    adj = adjust_attitudes(ties, list(range(n_scans)), node_times, bases)
    assert np.abs(adj.nodes_rpy_deg - truth).max() < 0.01
    assert adj.n_used == len(ties) - 1
    # no ties at all: scans whose own attitudes follow a steady drift keep them; a scan
    # off that drift is pulled towards its neighbours
    steady = np.outer(node_times / 3600.0, [0.1, -0.05, 0.02])
    alone = adjust_attitudes([], list(range(n_scans)), node_times, steady)
    np.testing.assert_allclose(alone.nodes_rpy_deg, steady, atol=1e-9)
    kinked = steady.copy()
    kinked[2] += 0.2
    pulled = adjust_attitudes([], list(range(n_scans)), node_times, kinked)
    assert np.all(np.abs(pulled.nodes_rpy_deg[2] - steady[2]) < 0.1)


def test_attitude_change_turns_the_antenna_to_camera_lever_arm():
    """A pose from an antenna position keeps the antenna fixed when its attitude changes: the
    camera 0.4 m below the antenna moves by ~3 cm for 4.5 deg of roll, as the true pose."""
    platform = {"antenna_to_camera_m": [0.0, 0.0, -0.4]}
    antenna = np.array([0.0, 0.0, 13.4])
    att = (-4.5, 1.0, 2.0)
    placed = pose_from_ptu(antenna, 10.0, -40.0, platform)
    truth = pose_from_ptu(antenna, 10.0, -40.0, platform, att)
    turned = placed.with_attitude(att)
    np.testing.assert_allclose(turned.position_m, truth.position_m, atol=1e-12)
    assert turned.attitude_rpy_deg == truth.attitude_rpy_deg
    assert 0.03 < np.hypot(*(turned.position_m - placed.position_m)[:2]) < 0.035
    # content seen with the true pose and placed with the zero attitude moves back exactly
    uv = np.array([[160.0], [128.0]])
    ground = CAMERA.ground_points(uv[0], uv[1], truth)[0, :2]
    where = CAMERA.ground_points(uv[0], uv[1], placed)[0, :2]
    np.testing.assert_allclose(moved_point(CAMERA, placed, *where, att), ground, atol=1e-6)
    # a pose without an antenna offset only turns
    bare = pose(2, (0.0, 0.0, 0.0)).with_attitude(att)
    np.testing.assert_allclose(bare.position_m, POSITION)
