"""Camera models: round trips, the paper's Eq. 6, OpenCV golden comparisons, manifests."""

from __future__ import annotations

import math

import cv2
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.geometry import (
    CameraPose,
    EquiangularCamera,
    PinholeCamera,
    camera_from_manifest,
    undistort_normalized,
)

DIST = (-0.25, 0.08, 0.0012, -0.0008, -0.01)

poses = st.builds(
    lambda x, y, h, az, el, roll, pitch, yaw: CameraPose([x, y, h], az, el, (roll, pitch, yaw)),
    st.floats(-1e3, 1e3), st.floats(-1e3, 1e3), st.floats(2.0, 40.0),
    st.floats(-180, 180), st.floats(-80, -15),
    st.floats(-3, 3), st.floats(-3, 3), st.floats(-10, 10))

def _pinhole(w: int, aspect: float, f: float, k: float) -> PinholeCamera:
    h = max(2, int(round(w * aspect)))
    return PinholeCamera(w, h, f * w, f * w, (w - 1) / 2 + 3.3, (h - 1) / 2 - 2.1,
                         tuple(k * np.array(DIST)))


cameras = st.one_of(
    st.builds(lambda w, aspect, ap: EquiangularCamera(w, max(2, int(round(w * aspect))), ap),
              st.integers(64, 1024), st.floats(0.5, 1.0), st.floats(3.0, 40.0)),
    st.builds(_pinhole, st.integers(64, 1024), st.floats(0.5, 1.0), st.floats(1.0, 8.0),
              st.floats(0.0, 1.0)),
)


def _in_domain(camera, pose) -> bool:
    """The equiangular model maps elevations in (-90, 90) only: its frame must not reach past
    the nadir (a row beyond -90 deg would look backwards)."""
    if not isinstance(camera, EquiangularCamera):
        return True
    half_v = math.degrees((camera.height - 1) / 2 * camera.ifov_rad)
    return pose.elevation_deg - half_v > -89.0


@given(cameras, poses, st.integers(0, 2**31 - 1))
@settings(max_examples=150, deadline=None)
def test_world_pixel_ground_round_trip(camera, pose, seed):
    """World point on z = 0 -> pixel -> ground point returns the point within 1e-6 m."""
    assume(_in_domain(camera, pose))
    rng = np.random.default_rng(seed)
    u = rng.uniform(0, camera.width - 1, 200)
    v = rng.uniform(0, camera.height - 1, 200)
    truth = camera.ground_points(u, v, pose)
    ok = np.isfinite(truth[:, 0])
    ok &= np.hypot(*(truth[:, :2] - pose.position_m[:2]).T) < 300.0
    truth = truth[ok]
    uv = camera.project(truth, pose)
    np.testing.assert_allclose(uv, np.column_stack([u[ok], v[ok]]), atol=1e-7)
    back = camera.ground_points(uv[:, 0], uv[:, 1], pose)
    assert np.all(np.linalg.norm(back - truth, axis=1) < 1e-6)


@given(cameras, poses)
@settings(max_examples=60, deadline=None)
def test_rays_are_unit_and_project_back(camera, pose):
    assume(_in_domain(camera, pose))
    u = np.array([0.0, camera.width - 1.0, (camera.width - 1) / 2.0])
    v = np.array([0.0, camera.height - 1.0, (camera.height - 1) / 2.0])
    d = camera.rays(u, v, pose)
    np.testing.assert_allclose(np.linalg.norm(d, axis=1), 1.0, atol=1e-12)
    uv = camera.project(pose.position_m + 7.0 * d, pose)
    np.testing.assert_allclose(uv, np.column_stack([u, v]), atol=1e-7)


def test_equiangular_eq6_worked_example():
    """Paper Eq. 6 by hand: x north, y east, camera C = (l, d, h) = (0, 0, 10) m, pan 30 deg
    from x, tilt 40 deg down, 2 alpha = 20 deg, n = 101, ground point (x, y) = (12, 8) m.

    gamma = atan(8/12) = 33.6900675 deg; atan(h sin gamma / (y - d)) = atan(10 / 14.4222051)
    = 34.7364813 deg; ifov = 2 alpha / (n - 1) = 0.2 deg;
    row u_paper = (34.7364813 - (40 - 10)) / 0.2 = 23.682406; column v_paper =
    (33.6900675 - (30 - 10)) / 0.2 = 68.450338.
    """
    cam = EquiangularCamera(101, 101, 20.0)
    pose = CameraPose([0.0, 0.0, 10.0], 30.0, -40.0)  # world (E, N) = paper (y, x)
    uv = cam.project(np.array([[8.0, 12.0, 0.0]]), pose)[0]
    assert uv[0] == pytest.approx(68.450338, abs=1e-6)  # our column = paper's v
    assert uv[1] == pytest.approx(23.682406, abs=1e-6)  # our row = paper's u
    # and the formula itself for a grid of ground points
    x, y = np.meshgrid(np.linspace(8, 20, 7), np.linspace(3, 14, 6))
    x, y = x.ravel(), y.ravel()
    gamma = np.arctan((y - 0.0) / (x - 0.0))
    alpha, n, h = math.radians(10.0), 101, 10.0
    ifov = 2 * alpha / (n - 1)
    u_paper = (np.arctan(h * np.sin(gamma) / y) - (math.radians(40) - alpha)) / ifov
    v_paper = (gamma - (math.radians(30) - alpha)) / ifov
    uv = cam.project(np.column_stack([y, x, np.zeros_like(x)]), pose)
    np.testing.assert_allclose(uv[:, 0], v_paper, atol=1e-9)
    np.testing.assert_allclose(uv[:, 1], u_paper, atol=1e-9)


def test_equiangular_linear_in_angles():
    cam = EquiangularCamera(321, 241, 24.0)
    pose = CameraPose([0, 0, 12], 0.0, -30.0)
    ifov = math.radians(24.0) / 320
    d = cam.rays([160.0, 260.0, 160.0], [120.0, 120.0, 20.0], pose)
    az = np.degrees(np.arctan2(d[:, 0], d[:, 1]))
    el = np.degrees(np.arcsin(d[:, 2]))
    np.testing.assert_allclose(az, [0.0, math.degrees(100 * ifov), 0.0], atol=1e-12)
    np.testing.assert_allclose(el, [-30.0, -30.0, -30.0 + math.degrees(100 * ifov)], atol=1e-12)


def test_pinhole_matches_cv2_project_points():
    rng = np.random.default_rng(1)
    cam = PinholeCamera(640, 512, 1100.0, 1080.0, 322.5, 250.25, DIST)
    pose = CameraPose([10.0, -4.0, 13.0], 37.0, -42.0, (1.0, -0.5, 2.0))
    pts = cam.ground_points(rng.uniform(0, 639, 500), rng.uniform(0, 511, 500), pose)
    r = pose.rotation()
    rvec, _ = cv2.Rodrigues(r.T)
    tvec = -r.T @ pose.position_m
    ref, _ = cv2.projectPoints(pts.reshape(-1, 1, 3), rvec, tvec, cam.matrix, np.array(DIST))
    np.testing.assert_allclose(cam.project(pts, pose), ref.reshape(-1, 2), atol=1e-8)


def test_undistort_beats_and_matches_cv2():
    rng = np.random.default_rng(2)
    xd = rng.uniform(-0.3, 0.3, 2000)
    yd = rng.uniform(-0.25, 0.25, 2000)
    x, y = undistort_normalized(xd, yd, DIST)
    crit = (cv2.TERM_CRITERIA_COUNT | cv2.TERM_CRITERIA_EPS, 100, 1e-14)
    ref = cv2.undistortPoints(np.column_stack([xd, yd]).reshape(-1, 1, 2), np.eye(3),
                                  np.array(DIST), None, None, criteria=crit).reshape(-1, 2)
    np.testing.assert_allclose(np.column_stack([x, y]), ref, atol=1e-9)
    from clearfast_gis.geometry import distort_normalized
    rx, ry = distort_normalized(x, y, DIST)
    assert np.max(np.hypot(rx - xd, ry - yd)) < 1e-14


def test_pinhole_behind_camera_is_nan():
    cam = PinholeCamera.from_aperture(320, 240, 30.0)
    pose = CameraPose([0, 0, 10], 0.0, -10.0)
    uv = cam.project(np.array([[0.0, -20.0, 0.0], [0.0, 20.0, 0.0]]), pose)
    assert np.all(np.isnan(uv[0])) and np.all(np.isfinite(uv[1]))
    g = cam.ground_points([159.5], [0.0], CameraPose([0, 0, 10], 0.0, 20.0))
    assert np.all(np.isnan(g))


def test_from_aperture_spans_aperture():
    cam = PinholeCamera.from_aperture(641, 481, 30.0)
    d = cam.rays([0.0, 640.0], [240.0, 240.0], CameraPose([0, 0, 1], 0.0, 0.0))
    ang = math.degrees(math.acos(float(d[0] @ d[1])))
    assert ang == pytest.approx(30.0, abs=1e-9)


MANIFEST = {"model": "equiangular", "resolution": [160, 128], "aperture_deg": 24.0,
            "intrinsics": {"fx": 400.0, "fy": 400.0, "cx": 79.5, "cy": 63.5,
                           "distortion": [0.0, 0.0, 0.0, 0.0, 0.0]}}


def test_camera_from_manifest():
    cam = camera_from_manifest(MANIFEST)
    assert cam == EquiangularCamera(160, 128, 24.0)
    ph = camera_from_manifest({**MANIFEST, "model": "pinhole"})
    assert ph == PinholeCamera(160, 128, 400.0, 400.0, 79.5, 63.5, (0.0,) * 5)


@pytest.mark.parametrize("change,line", [
    ({"resolution": [160]}, "survey.json: camera.resolution: expected 2 integers"),
    ({"resolution": [160.5, 128]}, "survey.json: camera.resolution: expected 2 integers"),
    ({"aperture_deg": 190}, "survey.json: camera.aperture_deg: expected an aperture"),
    ({"model": "fisheye"}, "survey.json: camera.model: expected"),
    ({"model": "pinhole", "intrinsics": {"fx": -1, "fy": 1, "cx": 0, "cy": 0}},
     "survey.json: camera.intrinsics.fx: expected a positive"),
    ({"model": "pinhole", "intrinsics": {**MANIFEST["intrinsics"], "distortion": [0, 0]}},
     "survey.json: camera.intrinsics.distortion: expected 5 numbers"),
])
def test_camera_from_manifest_errors(change, line):
    with pytest.raises(InvalidInput) as exc:
        camera_from_manifest({**MANIFEST, **change})
    assert exc.value.one_line().startswith(line)
