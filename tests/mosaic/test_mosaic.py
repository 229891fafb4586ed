"""Mosaicking: projection round trips, best-source insertion, co-registration of noisy poses."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.geometry.cameras import EquiangularCamera
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.geometry.pose import CameraPose
from clearfast_gis.geometry.projection import frame_footprint
from clearfast_gis.mosaic import (
    FrameInput,
    build_scan_mosaic,
    fit_linear_histogram_mapping,
    mosaic_grid,
    project_frame,
)
from clearfast_gis.mosaic.coregister import coregister_projected, measure_correction

CAM = EquiangularCamera(96, 72, 18.0)
X0, Y0 = 500_000.0, 3_890_000.0


def ground_field(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """A smooth, textured ground temperature in degrees C with a few discs (mines)."""
    xl, yl = x - X0, y - Y0
    t = 15.0 + 0.8 * np.sin(xl * 1.7) * np.cos(yl * 1.3) + 0.5 * np.sin(xl * 4.1 + yl * 2.3)
    for cx, cy, r, dt in [(2.0, 14.0, 0.17, 2.0), (-1.5, 12.5, 0.05, 1.5), (0.5, 16.0, 0.3, -1.8)]:
        t = t + dt * np.exp(-(((xl - cx) ** 2 + (yl - cy) ** 2) / (r * r)) ** 2)
    return t


def render(pose: CameraPose) -> np.ndarray:
    """The frame a camera at ``pose`` sees of ``ground_field`` (exact per-pixel sampling)."""
    v, u = np.mgrid[0:CAM.height, 0:CAM.width]
    g = CAM.ground_points(u.ravel().astype(float), v.ravel().astype(float), pose)
    return ground_field(g[:, 0], g[:, 1]).reshape(CAM.height, CAM.width).astype(np.float32)


def poses() -> list[CameraPose]:
    out = []
    for el in (-38.0, -48.0):
        for az in (-20.0, -7.0, 6.0, 19.0):
            out.append(CameraPose(np.array([X0, Y0, 12.0]), az, el))
    return out


def test_project_frame_round_trip():
    pose = poses()[1]
    grid = GroundGrid.from_bounds(X0 - 8, Y0 + 5, X0 + 8, Y0 + 22, 0.02, 32636)
    pf = project_frame(render(pose), CAM, pose, grid)
    assert pf is not None
    rs, cs = pf.window.slices
    xx, yy = np.meshgrid(grid.x_centres()[cs], grid.y_centres()[rs])
    truth = ground_field(xx, yy)
    ok = pf.valid
    assert ok.sum() > 10_000
    err = pf.values[0][ok] - truth[ok]
    # bilinear resampling of a frame whose ground pixel is ~3-6 cm: small but not zero
    assert np.sqrt(np.mean(err**2)) < 0.08
    # cells outside the frame's footprint stay NaN
    fp = frame_footprint(CAM, pose)
    assert fp.area > 1.0


def test_mosaic_picks_nadir_source_and_covers_union():
    ps = poses()
    grid = mosaic_grid([frame_footprint(CAM, p) for p in ps], 0.03, 32636)
    frames = [FrameInput(i, render(p)[None], p) for i, p in enumerate(ps)]
    m = build_scan_mosaic(frames, CAM, grid, 1, coregister=False)
    xx, yy = np.meshgrid(grid.x_centres(), grid.y_centres())
    ok = m.footprint_mask
    err = m.values[0][ok] - ground_field(xx, yy)[ok]
    assert np.sqrt(np.mean(err**2)) < 0.08
    # near-range cells come from the steeper rows (elevation -48: indices 4..7)
    near = ok & (yy < Y0 + 10.5)
    assert near.any()
    assert np.all(m.source[near] >= 4)
    # no blending: every value equals the chosen source's own projection
    pf = project_frame(frames[5].values, CAM, ps[5], grid)
    rs, cs = pf.window.slices
    sel = (m.source[rs, cs] == 5) & pf.valid
    np.testing.assert_array_equal(m.values[0][rs, cs][sel], pf.values[0][sel])


def test_coregistration_removes_pose_error():
    """Frames rendered from true poses, projected with poses off by ~10 cm, are put back."""
    rng = np.random.default_rng(3)
    true = poses()
    grid = mosaic_grid([frame_footprint(CAM, p) for p in true], 0.03, 32636)
    reference = build_scan_mosaic(
        [FrameInput(i, render(p)[None], p) for i, p in enumerate(true)], CAM, grid, 1,
        coregister=False).values
    frames = []
    for i, p in enumerate(true):
        off = np.r_[rng.normal(0, 0.08, 2), 0.0]
        frames.append(FrameInput(i, render(p)[None],
                                 CameraPose(p.position_m + off, p.azimuth_deg, p.elevation_deg)))
    raw = build_scan_mosaic(frames, CAM, grid, 1, coregister=False)
    fixed = build_scan_mosaic(frames, CAM, grid, 1, coregister=True, reference=reference,
                              max_shift_m=0.3)
    xx, yy = np.meshgrid(grid.x_centres(), grid.y_centres())
    truth = ground_field(xx, yy)

    def rms(m):
        ok = m.footprint_mask
        return float(np.sqrt(np.mean((m.values[0][ok] - truth[ok]) ** 2)))

    print('rms raw/fixed', rms(raw), rms(fixed))
    assert rms(raw) > 0.12
    assert rms(fixed) < 0.4 * rms(raw)
    applied = [c for c in fixed.corrections.values() if c.applied]
    assert len(applied) >= 6
    for i, c in fixed.corrections.items():
        if c.applied:
            d = frames[i].pose.position_m[:2] - true[i].position_m[:2]
            # the applied ground shift undoes the position error (within 2 cm)
            assert np.hypot(c.dx_m + d[0], c.dy_m + d[1]) < 0.02


@pytest.mark.parametrize("gain,offset", [(1.0, 0.0), (0.9, 1.5), (1.2, -3.0)])
def test_seam_mapping_recovers_linear_change(gain, offset):
    rng = np.random.default_rng(0)
    m = rng.normal(15, 2, 5000)
    f = (m - offset) / gain
    a, b = fit_linear_histogram_mapping(m, f)
    assert a == pytest.approx(gain, rel=1e-6)
    assert b == pytest.approx(offset, abs=1e-5)


def test_measure_correction_is_the_applied_correction():
    """The attitude ties' measurement (no warp) gives the correction, transform included,
    that the mosaic's co-registration applies, and it undoes a known position error."""
    true = poses()
    grid = mosaic_grid([frame_footprint(CAM, p) for p in true], 0.03, 32636)
    reference = build_scan_mosaic(
        [FrameInput(i, render(p)[None], p) for i, p in enumerate(true)], CAM, grid, 1,
        coregister=False).values
    off = np.array([0.07, -0.05, 0.0])
    p = true[2]
    pf = project_frame(render(p), CAM, CameraPose(p.position_m + off, p.azimuth_deg,
                                                 p.elevation_deg), grid)
    rs, cs = pf.window.slices
    corr, t = measure_correction(pf, reference[:, rs, cs], grid.pixel_size, max_shift_m=0.3)
    warped, corr2, t2 = coregister_projected(pf, reference[:, rs, cs], grid.pixel_size,
                                             max_shift_m=0.3)
    assert corr.applied and corr.reason == "ok"
    assert corr == corr2 and t == t2
    assert np.hypot(corr.dx_m + off[0], corr.dy_m + off[1]) < 0.02
    assert warped is not pf and warped.values.shape == pf.values.shape
