"""Ground-projection maps, footprints and per-cell viewing geometry."""

from __future__ import annotations

import math

import cv2
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.geometry import (
    CameraPose,
    EquiangularCamera,
    GroundGrid,
    PinholeCamera,
    frame_footprint,
    ground_maps,
    incidence_angle_map,
    off_axis_angle_map,
    slant_range_map,
)

CAMERAS = [EquiangularCamera(160, 128, 24.0),
           PinholeCamera(160, 128, 380.0, 375.0, 80.3, 62.9, (-0.2, 0.05, 0.001, -0.001, 0.0))]
GRID = GroundGrid.from_bounds(-20.0, -5.0, 20.0, 30.0, 0.1, 32636)


def _reference(camera, pose, grid):
    x, y = grid.cell_centres()
    uv = camera.project(np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)]), pose)
    seen = camera.in_frame(uv).reshape(grid.shape)
    return uv[:, 0].reshape(grid.shape), uv[:, 1].reshape(grid.shape), seen


@pytest.mark.parametrize("camera", CAMERAS, ids=["equiangular", "pinhole"])
@given(st.floats(-180, 180), st.floats(-80, -20), st.floats(5, 20),
       st.tuples(st.floats(-2, 2), st.floats(-2, 2), st.floats(-5, 5)))
@settings(max_examples=25, deadline=None)
def test_maps_match_project(camera, az, el, h, att):
    pose = CameraPose([0.3, -0.7, h], az, el, att)
    mx, my = ground_maps(camera, pose, GRID)
    assert mx.dtype == np.float32 and mx.shape == GRID.shape
    ru, rv, seen = _reference(camera, pose, GRID)
    # cells on the hull boundary may flip with float32 rounding of the comparison
    boundary = (np.abs(ru) < 1e-6) | (np.abs(ru - (camera.width - 1)) < 1e-6) \
        | (np.abs(rv) < 1e-6) | (np.abs(rv - (camera.height - 1)) < 1e-6)
    assert np.array_equal((mx >= 0)[~boundary], seen[~boundary])
    assert np.all(mx[~seen & ~boundary] == -1) and np.all(my[~seen & ~boundary] == -1)
    ok = seen & (mx >= 0)
    np.testing.assert_allclose(mx[ok], ru[ok], atol=1e-4)
    np.testing.assert_allclose(my[ok], rv[ok], atol=1e-4)
    # every cell computed (no outline bound): the same maps
    ux, uy = ground_maps(camera, pose, GRID, bound=False)
    assert np.array_equal(ux, mx) and np.array_equal(uy, my)


@pytest.mark.parametrize("camera", CAMERAS, ids=["equiangular", "pinhole"])
def test_remap_puts_pixels_on_their_ground_cells(camera):
    """A frame whose pixel values are their own column index remaps to the cell's u."""
    pose = CameraPose([0.0, -3.0, 12.0], 10.0, -45.0)
    frame = np.tile(np.arange(camera.width, dtype=np.float32), (camera.height, 1))
    mx, my = ground_maps(camera, pose, GRID)
    out = cv2.remap(frame, mx, my, cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT,
                    borderValue=np.nan)
    seen = mx >= 0
    assert seen.sum() > 1000
    np.testing.assert_allclose(out[seen], mx[seen], atol=2e-2)


def test_behind_and_below_not_seen():
    cam = CAMERAS[0]
    mx, _ = ground_maps(cam, CameraPose([0, 0, 10], 180.0, -40.0), GRID)  # looks south
    assert np.all(mx[:, :][GRID.cell_centres()[1] > 1.0] == -1)
    mx, my = ground_maps(cam, CameraPose([0, 0, -1], 0.0, -40.0), GRID)  # under the ground
    assert np.all(mx == -1) and np.all(my == -1)


def test_whole_grid_when_looking_at_nadir():
    cam = PinholeCamera.from_aperture(101, 81, 60.0)
    pose = CameraPose([0.0, 10.0, 10.0], 0.0, -90.0)
    mx, _ = ground_maps(cam, pose, GRID)
    ru, _, seen = _reference(cam, pose, GRID)
    assert np.array_equal(mx >= 0, seen)


def test_nadir_footprint_is_known_rectangle():
    cam = PinholeCamera(201, 101, 400.0, 400.0, 100.0, 50.0)
    pose = CameraPose([5.0, 7.0, 8.0], 0.0, -90.0)
    fp = frame_footprint(cam, pose)
    # x: 200 px / 400 px * 8 m = 4 m wide, y: 100 / 400 * 8 = 2 m
    assert fp.area == pytest.approx(4.0 * 2.0, rel=1e-9)
    assert fp.bounds == pytest.approx((3.0, 6.0, 7.0, 8.0))


def test_equiangular_footprint_is_annular_sector():
    cam = EquiangularCamera(161, 121, 20.0)
    pose = CameraPose([0.0, 0.0, 10.0], 0.0, -40.0)
    fp = frame_footprint(cam, pose, samples_per_edge=400)
    half_v = math.radians(20.0) / 160 * 60
    r_near = 10.0 / math.tan(math.radians(40.0) + half_v)
    r_far = 10.0 / math.tan(math.radians(40.0) - half_v)
    exact = math.radians(20.0) / 2.0 * (r_far**2 - r_near**2)
    assert fp.area == pytest.approx(exact, rel=1e-4)


def test_footprint_cut_at_horizon():
    cam = EquiangularCamera(160, 128, 24.0)
    fp = frame_footprint(cam, CameraPose([0, 0, 10], 0.0, -5.0), max_range_m=200.0)
    assert fp.is_valid and not fp.is_empty
    assert fp.bounds[3] == pytest.approx(200.0, rel=1e-3)
    assert frame_footprint(cam, CameraPose([0, 0, 10], 0.0, 30.0)).is_empty


def test_viewing_geometry_maps():
    pose = CameraPose([0.0, 0.0, 10.0], 0.0, -45.0)
    g = GroundGrid(-0.5, 10.5, 1.0, 1, 1)  # one cell centred at (0, 10)
    assert slant_range_map(pose, g)[0, 0] == pytest.approx(math.hypot(10, 10), rel=1e-6)
    assert incidence_angle_map(pose, g)[0, 0] == pytest.approx(45.0, abs=1e-5)
    assert off_axis_angle_map(pose, g)[0, 0] == pytest.approx(0.0, abs=1e-2)
    g = GroundGrid(-0.5, 0.5, 1.0, 1, 1)  # straight below
    assert incidence_angle_map(pose, g)[0, 0] == pytest.approx(0.0, abs=1e-6)
    assert off_axis_angle_map(pose, g)[0, 0] == pytest.approx(45.0, abs=1e-5)


@given(st.floats(-50, 50), st.floats(-50, 50), st.floats(0.5, 30), st.floats(-1, 1))
@settings(max_examples=40, deadline=None)
def test_incidence_map_equals_its_definition(x, y, h, z):
    """Golden: the compiled map equals atan2(horizontal distance, height) in degrees."""
    pose = CameraPose([x, y, h + z], 0.0, -45.0)
    grid = GroundGrid.from_bounds(-20.0, -5.0, 20.0, 30.0, 0.7, 32636)
    xc, yc = grid.cell_centres()
    want = np.degrees(np.arctan2(np.hypot(xc - x, yc - y), h)).astype(np.float32)
    np.testing.assert_allclose(incidence_angle_map(pose, grid, z), want, atol=1e-4)


def test_far_reaching_outline_still_bounds_the_seen_cells():
    """Regression (found by hypothesis): a shallow view whose outline is cut at the grid's
    reach and crosses itself must still give the window of the seen cells."""
    camera = CAMERAS[0]
    pose = CameraPose([0.3, -0.7, 8.0], 0.0, -20.0)
    mx, _ = ground_maps(camera, pose, GRID)
    _, _, seen = _reference(camera, pose, GRID)
    assert seen.sum() > 10_000
    assert np.array_equal(mx >= 0, seen)


@given(st.floats(-180, 180), st.floats(-89, 10), st.floats(2, 20),
       st.tuples(st.floats(-4, 4), st.floats(-4, 4), st.floats(-5, 5)),
       st.sampled_from([9.0, 24.0, 120.0, 175.0]))
@settings(max_examples=40, deadline=None)
def test_equiangular_pretest_skips_only_unseen_cells(az, el, h, att, aperture):
    """The arctangent-free pretest of the compiled equiangular maps changes no map value:
    the same maps, bit for bit, as every cell computed exactly (wide apertures, poses near
    the vertical and the horizon, tilted platforms)."""
    from clearfast_gis.geometry._kernels import _equiangular_maps

    camera = EquiangularCamera(160, 128, aperture)
    pose = CameraPose([0.3, -0.7, h], az, el, att)
    xs = GRID.x_centres().astype(np.float64)
    ys = GRID.y_centres().astype(np.float64)
    maps = []
    for skip in (True, False):
        mx = np.empty(GRID.shape, np.float32)
        my = np.empty(GRID.shape, np.float32)
        _equiangular_maps(xs, ys, 0.0, np.asarray(pose.position_m, dtype=np.float64),
                          np.ascontiguousarray(pose.attitude()), math.radians(pose.azimuth_deg),
                          math.radians(pose.elevation_deg), camera.ifov_rad, camera.width,
                          camera.height, mx, my, skip)
        maps.append((mx, my))
    assert np.array_equal(maps[0][0], maps[1][0]) and np.array_equal(maps[0][1], maps[1][1])
