"""Ties between two placed scans measured mosaic against mosaic (refined adjustment)."""

from __future__ import annotations

import numpy as np

from clearfast_gis.attitude import (
    LinearTie,
    ReferenceMosaic,
    adjust_attitudes,
    displacement_jacobian,
    frame_windows,
    mosaic_ties,
    moved_point,
    neighbour_pairs,
)
from clearfast_gis.geometry.cameras import EquiangularCamera
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.geometry.pose import CameraPose
from clearfast_gis.mosaic import FrameInput, build_scan_mosaic, temporal_transform

CAM = EquiangularCamera(96, 72, 18.0)
X0, Y0 = 500_000.0, 3_890_000.0
GRID = GroundGrid.from_bounds(X0 - 9, Y0 + 4, X0 + 9, Y0 + 24, 0.02, 32636)
PATTERN = [(az, el) for el in (-38.0, -48.0) for az in (-20.0, -7.0, 6.0, 19.0)]


def ground_field(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Textured ground temperature, degrees C."""
    xl, yl = x - X0, y - Y0
    return (15.0 + 0.8 * np.sin(xl * 1.7) * np.cos(yl * 1.3) + 0.5 * np.sin(xl * 4.1 + yl * 2.3)
            + 0.3 * np.sin(xl * 9.0 - yl * 7.0))


def pose(k: int, attitude=(0.0, 0.0, 0.0)) -> CameraPose:
    az, el = PATTERN[k]
    return CameraPose(np.array([X0, Y0, 12.0]), az, el, tuple(float(a) for a in attitude))


def render(p: CameraPose) -> np.ndarray:
    v, u = np.mgrid[0:CAM.height, 0:CAM.width]
    g = CAM.ground_points(u.ravel().astype(float), v.ravel().astype(float), p)
    return ground_field(g[:, 0], g[:, 1]).reshape(CAM.height, CAM.width).astype(np.float32)


def placed_scan(scan: int, time_s: float, true_rpy, placed_rpy) -> ReferenceMosaic:
    """A scan seen with the attitude ``true_rpy`` and mosaicked with ``placed_rpy``."""
    frames = [FrameInput(k, render(pose(k, true_rpy))[None], pose(k, placed_rpy))
              for k in range(len(PATTERN))]
    m = build_scan_mosaic(frames, CAM, GRID, 1, coregister=False)
    return ReferenceMosaic(scan, m.values, m.source,
                           lambda k: (time_s + k, pose(k, placed_rpy)))


def test_neighbour_pairs_in_time_order():
    assert neighbour_pairs([3, 5, 8], (-2, -1, 1, 2)) == [
        (3, 5), (3, 8), (5, 3), (5, 8), (8, 3), (8, 5)]
    assert neighbour_pairs([4], (-1, 1)) == []


def test_frame_windows_bound_each_position():
    src = -np.ones((40, 50), dtype=np.int64)
    src[2:10, 5:30] = 0
    src[20:39, 0:50] = 3
    src[12:14, 0:3] = 5  # too small
    wins = frame_windows(src, n_samples=10, min_cells=50)
    assert [p for p, _ in wins] == [0, 3]
    assert wins[0][1] == (slice(2, 10), slice(5, 30))
    assert wins[1][1] == (slice(20, 39), slice(0, 50))


def test_mosaic_ties_measure_the_relative_displacement():
    true_a, placed_a = (0.05, -0.08, 0.10), (0.0, 0.0, 0.0)
    true_b, placed_b = (0.02, 0.03, -0.04), (0.0, 0.0, 0.0)
    a = placed_scan(1, 1000.0, true_a, placed_a)
    b = placed_scan(2, 2000.0, true_b, placed_b)
    ties = mosaic_ties(a, b, CAM, GRID, n_samples=8)
    assert len(ties) >= 6
    errs = []
    for t in ties:
        k = int(round(t.time_s - 1000.0))
        # the content the tie is about: placed at the centre of frame k's cells in scan a
        truly_at = moved_point(CAM, pose(k, placed_a), *_centre(a, k), true_a)
        in_b = moved_point(CAM, pose(k, true_b), *truly_at, placed_b)  # where b placed it
        errs.append(t.d_m - (in_b - _centre(a, k)))
        assert t.ref_scan == 2 and t.scan == 1 and t.weight == 1.0
    errs = np.array(errs)
    # a few centimetres of relative displacement, measured to a few millimetres
    assert np.abs(errs).max() < 0.006, errs
    assert 0.01 < np.abs([t.d_m for t in ties]).max() < 0.1


def _centre(m: ReferenceMosaic, k: int) -> np.ndarray:
    """Ground centroid (metres) of the cells frame ``k`` supplies to mosaic ``m``."""
    rows, cols = np.nonzero(m.source == k)
    ps = GRID.pixel_size
    return np.array([GRID.x0 + (cols.mean() + 0.5) * ps, GRID.y0 - (rows.mean() + 0.5) * ps])


def test_mosaic_ties_at_zero_shift_are_kept():
    a = placed_scan(1, 1000.0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    b = placed_scan(2, 2000.0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    ties = mosaic_ties(a, b, CAM, GRID, n_samples=8)
    assert len(ties) >= 6
    assert np.abs([t.d_m for t in ties]).max() < 0.003


def test_neighbour_ties_pull_a_scan_without_evidence_into_place():
    """Scan 1 (between two scans that see markers) was placed 0.1 deg off; its ties to both
    neighbours, with the neighbours' markers, bring it back."""
    truth = np.array([[0.0, 0.0, 0.0], [0.02, -0.03, 0.04], [0.04, -0.06, 0.08]])
    placed = truth.copy()
    placed[1] += (0.1, 0.05, -0.1)
    times = np.array([1000.0, 2000.0, 3000.0])
    scans = [placed_scan(s, times[s], truth[s], placed[s]) for s in range(3)]
    ties = [t for s, n in neighbour_pairs([0, 1, 2], (-1, 1))
            for t in mosaic_ties(scans[s], scans[n], CAM, GRID, n_samples=8)]
    markers = []
    for s in (0, 2):
        for k in (0, 3, 4, 7):
            p = pose(k, placed[s])
            c = _centre(scans[s], k)
            markers.append(LinearTie(s, times[s] + k, placed[s],
                                     displacement_jacobian(CAM, p, *c),
                                     moved_point(CAM, p, *c, truth[s]) - c, 5.0))
    adj = adjust_attitudes(markers + ties, [0, 1, 2], times, placed, smooth_deg_h2=10.0)
    assert np.abs(placed - truth).max() >= 0.1
    assert np.abs(adj.nodes_rpy_deg - truth).max() < 0.02, adj.nodes_rpy_deg - truth
    assert adj.rms_m < 0.2 * adj.rms_before_m


def test_whole_mosaic_ties_hold_across_contrast_inversion():
    """Against the reference scan the shift of each sample frame is read from the registration
    of the two whole mosaics: it still measures the relative displacement when the reference
    shows the ground's pattern inverted (night against noon)."""
    true_a, placed_a = (0.05, -0.08, 0.10), (0.0, 0.0, 0.0)
    true_b, placed_b = (0.02, 0.03, -0.04), (0.0, 0.0, 0.0)
    a = placed_scan(1, 1000.0, true_a, placed_a)
    b = placed_scan(2, 2000.0, true_b, placed_b)
    night = ReferenceMosaic(2, 30.0 - b.values, b.source, b.frame_at)
    whole = temporal_transform(night.values[0], a.values[0])
    assert whole.converged
    ties = mosaic_ties(a, night, CAM, GRID, n_samples=8, transform=whole)
    assert len(ties) >= 6
    errs = []
    for t in ties:
        k = int(round(t.time_s - 1000.0))
        truly_at = moved_point(CAM, pose(k, placed_a), *_centre(a, k), true_a)
        in_b = moved_point(CAM, pose(k, true_b), *truly_at, placed_b)
        errs.append(t.d_m - (in_b - _centre(a, k)))
        assert t.ref_scan == 2 and t.scan == 1
    errs = np.array(errs)
    # a few centimetres of attitude-driven displacement: its rotation-and-shift part is
    # measured to millimetres on average; what no rigid motion explains is left (~1 cm)
    assert np.abs(errs.mean(axis=0)).max() < 0.003, errs
    assert np.abs(errs).max() < 0.015, errs
