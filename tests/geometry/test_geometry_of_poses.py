"""The frames' geometry computed for many poses at once is that of one pose at a time, bit for
bit (the mosaics do not depend on how a scan's frames are grouped)."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.geometry import CameraPose, EquiangularCamera, PinholeCamera
from clearfast_gis.geometry.projection import frame_footprint, frame_footprints
from clearfast_gis.mosaic.frames import path_length_map, path_length_maps
from clearfast_gis.mosaic.project import antialias_sigma_px, frame_geometry

CAMERAS = [EquiangularCamera(160, 128, 24.0),
           PinholeCamera(160, 128, 380.0, 375.0, 80.3, 62.9, (-0.2, 0.05, 0.001, -0.001, 0.0))]

POSE = st.builds(
    lambda x, y, h, az, el, att: CameraPose([x, y, h], az, el, att),
    st.floats(-50, 50), st.floats(-50, 50),
    st.one_of(st.floats(-1, 0), st.floats(0.5, 20)),  # some cameras below the ground
    st.floats(-180, 180), st.floats(-89, 30),  # some frames see the horizon or only sky
    st.tuples(st.floats(-5, 5), st.floats(-5, 5), st.floats(-10, 10)))


@pytest.mark.parametrize("camera", CAMERAS, ids=["equiangular", "pinhole"])
@given(st.lists(POSE, min_size=1, max_size=12))
@settings(max_examples=30, deadline=None)
def test_many_poses_equal_one_at_a_time(camera, poses):
    u = np.array([0.0, 17.5, camera.width - 1.0, 3.25])
    v = np.array([0.0, 99.0, camera.height - 1.0, 64.5])
    many = camera.ground_points_of_poses(u, v, poses)
    rays = camera.rays_of_poses(u, v, poses)
    assert many.shape == rays.shape == (len(poses), u.size, 3)
    for k, pose in enumerate(poses):
        assert np.array_equal(many[k], camera.ground_points(u, v, pose), equal_nan=True)
        assert np.array_equal(rays[k], camera.rays(u, v, pose))
    fps = frame_footprints(camera, poses)
    assert [shapely.to_wkb(f) for f in fps] == [shapely.to_wkb(frame_footprint(camera, p))
                                                 for p in poses]
    assert all(f.geom_type in ("Polygon", "MultiPolygon") and (f.is_empty or f.is_valid)
               for f in fps)
    paths = path_length_maps(camera, poses)
    assert paths.dtype == np.float32 and paths.shape == (len(poses), 17, 17)
    for k, pose in enumerate(poses):
        assert np.array_equal(paths[k], path_length_map(camera, pose), equal_nan=True)
    footprints, sigmas = frame_geometry(camera, poses, 0.02)
    assert sigmas == [antialias_sigma_px(camera, p, 0.02) for p in poses]
    assert [shapely.to_wkb(f) for f in footprints] == [shapely.to_wkb(f) for f in fps]


def test_path_length_is_the_slant_range_to_the_ground():
    camera = EquiangularCamera(160, 128, 24.0)
    pose = CameraPose([0.0, 0.0, 10.0], 30.0, -90.0 + 1e-9, (0.0, 0.0, 0.0))
    # looking straight down, the central lattice point is 10 m below the camera
    assert path_length_maps(camera, [pose])[0, 8, 8] == pytest.approx(10.0, rel=1e-6)
    # a frame that sees no ground gets 20 m everywhere
    sky = CameraPose([0.0, 0.0, 10.0], 30.0, 60.0, (0.0, 0.0, 0.0))
    assert np.all(path_length_maps(camera, [sky, pose])[0] == 20.0)


def test_no_frames():
    camera = CAMERAS[0]
    assert frame_footprints(camera, []) == []
    assert frame_geometry(camera, [], 0.02) == ([], [])


def test_path_lengths_beyond_float32_count_as_sky():
    """A lattice ray that meets the ground farther than float32 can hold (grazing the
    horizon) is treated as seeing sky: the frame's largest finite range, not inf, and no
    overflow in the cast."""
    import warnings
    from types import SimpleNamespace

    def ground_points_of_poses(u, v, poses):
        far = np.where(u[None, :] == u.max(), 1e39, 10.0 + u[None, :])  # last column: far
        pts = np.zeros((len(poses), u.size, 3))
        pts[..., 0] = far
        pts[..., 2] = 0.0
        pts[:, v == v.max(), :] = np.nan  # bottom row: sky
        return pts

    camera = SimpleNamespace(width=5, height=4, ground_points_of_poses=ground_points_of_poses)
    pose = SimpleNamespace(position_m=np.array([0.0, 0.0, 0.0]))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        got = path_length_maps(camera, [pose], lattice=4)[0]
    assert got.dtype == np.float32 and np.all(np.isfinite(got))
    largest = np.float32(10.0 + 8.0 / 3.0)  # the farthest column still on the ground
    np.testing.assert_array_equal(got[:, -1], largest)  # beyond float32: as sky
    np.testing.assert_array_equal(got[-1], largest)  # sky
