"""Pose conventions (docs/contracts.md §1) and pose_from_ptu."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.geometry import CameraPose, attitude_matrix, pose_from_ptu


def test_axes_level_north():
    r = CameraPose([0, 0, 10], 0.0, 0.0).rotation()
    np.testing.assert_allclose(r[:, 0], [1, 0, 0], atol=1e-15)  # right = east
    np.testing.assert_allclose(r[:, 1], [0, 0, -1], atol=1e-15)  # down = down
    np.testing.assert_allclose(r[:, 2], [0, 1, 0], atol=1e-15)  # forward = north


def test_axes_east_looking_down():
    r = CameraPose([0, 0, 10], 90.0, -30.0).rotation()
    c, s = np.cos(np.radians(30)), np.sin(np.radians(30))
    np.testing.assert_allclose(r[:, 2], [c, 0, -s], atol=1e-15)
    np.testing.assert_allclose(r[:, 0], [0, -1, 0], atol=1e-15)  # right = south
    np.testing.assert_allclose(r[:, 1], np.cross(r[:, 2], r[:, 0]), atol=1e-15)


@given(st.floats(-360, 360), st.floats(-90, 90), st.floats(-5, 5), st.floats(-5, 5),
       st.floats(-180, 180))
@settings(max_examples=100, deadline=None)
def test_rotation_is_proper(az, el, roll, pitch, yaw):
    r = CameraPose([1, 2, 3], az, el, (roll, pitch, yaw)).rotation()
    np.testing.assert_allclose(r.T @ r, np.eye(3), atol=1e-12)
    assert np.linalg.det(r) == pytest.approx(1.0, abs=1e-12)


def test_yaw_turns_clockwise_like_azimuth():
    a = CameraPose([0, 0, 5], 30.0, -20.0, (0, 0, 15)).rotation()
    b = CameraPose([0, 0, 5], 45.0, -20.0).rotation()
    np.testing.assert_allclose(a, b, atol=1e-12)


def test_roll_and_pitch_axes():
    # pitch about north tilts east-pointing vectors up or down, roll about east tilts north
    east = attitude_matrix(0, 10, 0) @ [1, 0, 0]
    assert east[2] == pytest.approx(-np.sin(np.radians(10)))
    north = attitude_matrix(10, 0, 0) @ [0, 1, 0]
    assert north[2] == pytest.approx(np.sin(np.radians(10)))


def test_pose_from_ptu_offsets():
    platform = {"antenna_to_camera_m": [0.1, 0.0, -0.4], "pan_zero_azimuth_deg": 12.0,
                "tilt_zero_deg": -1.5}
    p = pose_from_ptu([100.0, 200.0, 14.0], 30.0, -40.0, platform)
    assert p.azimuth_deg == 42.0 and p.elevation_deg == -41.5
    np.testing.assert_allclose(p.position_m, [100.1, 200.0, 13.6])
    # a yawed base rotates the mount offset too
    p = pose_from_ptu([0, 0, 10], 0, 0, platform, (0, 0, 90))
    np.testing.assert_allclose(p.position_m, [0.0, -0.1, 9.6], atol=1e-12)


@pytest.mark.parametrize("platform,field", [
    ({"antenna_to_camera_m": [0, 0]}, "platform.antenna_to_camera_m"),
    ({"pan_zero_azimuth_deg": "x"}, "platform.pan_zero_azimuth_deg"),
    ({"tilt_zero_deg": None}, "platform.tilt_zero_deg"),
])
def test_pose_from_ptu_bad_platform(platform, field):
    with pytest.raises(InvalidInput) as exc:
        pose_from_ptu([0, 0, 10], 0, 0, platform)
    assert exc.value.one_line().startswith(f"survey.json: {field}: expected")


def test_pose_from_ptu_elevation_out_of_range():
    with pytest.raises(InvalidInput, match="tilt_deg"):
        pose_from_ptu([0, 0, 10], 0, -95, {"tilt_zero_deg": 0})


def test_attitude_matrix_remembered_exactly():
    """The remembered matrices are those computed afresh, bit for bit (signed zeros too), and
    each call gets its own copy."""
    from clearfast_gis.geometry.pose import _rx, _ry, _rz, attitude_matrix

    rng = np.random.default_rng(3)
    angles = [tuple(a) for a in rng.normal(0.0, 3.0, (50, 3))]
    angles += [(0.0, -0.0, 0.0), (-0.0, 0.0, -0.0), (0.0, 0.0, 0.0)]
    for _ in range(2):  # the second pass is answered from memory
        for r, p, y in angles:
            fresh = _rz(-np.radians(y)) @ _ry(np.radians(p)) @ _rx(np.radians(r))
            got = attitude_matrix(r, p, y)
            assert np.array_equal(got, fresh)
            assert np.array_equal(np.signbit(got), np.signbit(fresh))
    a = attitude_matrix(1.0, 2.0, 3.0)
    a[0, 0] = 99.0
    assert attitude_matrix(1.0, 2.0, 3.0)[0, 0] != 99.0
