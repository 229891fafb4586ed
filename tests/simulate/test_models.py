"""Unit checks of the simulator's models against known answers."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.geometry.cameras import EquiangularCamera, PinholeCamera
from clearfast_gis.geometry.pose import pose_from_ptu
from clearfast_gis.radiometry.table import BandTable
from clearfast_gis.simulate.config import preset
from clearfast_gis.simulate.detector import make_detector
from clearfast_gis.simulate.emissivity import band_emissivity
from clearfast_gis.simulate.objects import SceneObject
from clearfast_gis.simulate.platform import RTK_FIXED_SIGMA_M, gnss_epochs, lift_motion
from clearfast_gis.simulate.rays import FrameRays
from clearfast_gis.simulate.render import radiance_grid, surface_radiance_frame
from clearfast_gis.simulate.scene import GridSpec, build_scene, smooth_random_field
from clearfast_gis.simulate.sky import sky_band_emissivity
from clearfast_gis.simulate.thin_layers import leaf_temperature_k, plate_temperature_k
from clearfast_gis.units import STEFAN_BOLTZMANN as SIGMA

TABLE = BandTable(8.0, 9.2)


def test_sky_window_emissivity():
    t = np.array([285.0, 285.0])
    eps = sky_band_emissivity(np.array([1.0, 0.78]) * SIGMA * t**4, t)
    np.testing.assert_allclose(eps, [1.0, 1.0 - 2.5 * 0.22])


def test_leaf_energy_balance():
    solar, sky, air, wind, ground = (np.array([0.0, 580.0]), np.array([290.0, 315.0]),
                                     np.array([283.0, 295.0]), np.array([1.0, 3.0]),
                                     np.array([281.0, 310.0]))
    t = leaf_temperature_k(solar, sky, air, wind, ground)
    hc = 5.7 + 3.8 * wind
    residual = (0.5 * 0.65 * solar + 0.97 * (sky + SIGMA * ground**4)
                - 2 * 0.97 * SIGMA * t**4 - 2 * hc * (t - air))
    np.testing.assert_allclose(residual, 0.0, atol=1e-6)
    assert t[0] < air[0] and t[1] > air[1]  # cools below air at night, warms a little by day


def test_plate_energy_balance_and_markers():
    solar, sky, air, wind, ground = (np.array([0.0, 580.0]), np.array([290.0, 315.0]),
                                     np.array([283.0, 295.0]), np.array([1.0, 3.0]),
                                     np.array([281.0, 305.0]))
    black = plate_temperature_k(solar, sky, air, wind, ground, 0.05, 0.95)
    shiny = plate_temperature_k(solar, sky, air, wind, ground, 0.15, 0.07)
    hc = 5.7 + 3.8 * wind
    residual = (0.95 * solar + 0.95 * sky - 0.95 * SIGMA * black**4 - hc * (black - air)
                - 15.0 * (black - ground))
    np.testing.assert_allclose(residual, 0.0, atol=1e-6)
    assert black[1] > ground[1] + 5.0  # the hot marker is hot by day
    # the shiny plate is warm but reflects the cold sky: apparent temperature far below
    app = TABLE.temperature(0.08 * TABLE.radiance(shiny) + 0.92 * 0.45 * TABLE.radiance(air))
    assert np.all(app < ground - 10.0)


def test_quartz_reststrahlen_in_band_emissivity():
    assert band_emissivity("dry_soil", 8.0, 9.2) < band_emissivity("dry_soil", 10.4, 12.0) - 0.05
    assert band_emissivity("moist_soil", 8.0, 9.2) > band_emissivity("dry_soil", 8.0, 9.2)


def test_detector_linear_and_netd():
    rng = np.random.default_rng(0)
    det = make_detector(TABLE, (64, 80), 14, 0.05, 0.0, rng)
    l1, l2 = TABLE.radiance(np.array([290.0, 300.0]))
    c1 = det.counts(np.full((64, 80), l1, np.float32), 100.0, None).astype(float)
    c2 = det.counts(np.full((64, 80), l2, np.float32), 100.0, None).astype(float)
    g, o = det.gain_offset(100.0)
    np.testing.assert_allclose(c1, g * l1 + o, atol=0.51)
    np.testing.assert_allclose(c2 - c1, g * (l2 - l1), atol=1.01)
    frames = np.stack([det.counts(np.full((64, 80), l2, np.float32), 100.0, rng)
                       for _ in range(40)]).astype(float)
    slope = g * float(np.diff(TABLE.radiance(np.array([299.95, 300.05])))[0] / 0.1)
    netd = np.median(frames.std(axis=0) / slope)
    assert netd == pytest.approx(0.05, rel=0.1)
    # the raw drift over a 30-minute scan stays below 0.03 K (60 % of the NETD)
    g2, o2 = det.gain_offset(1900.0)
    drift_k = np.abs((g2 * l1 + o2) - (g * l1 + o)) / slope
    assert drift_k.max() < 0.03


def test_gnss_noise_and_fix_quality():
    cfg = preset("demo")
    motion = lift_motion(cfg, np.array([0.0, 0.0, 8.4]), 0.0, False, np.random.default_rng(1))
    ep = gnss_epochs(motion, 0.0, 86400.0, 1.0, np.random.default_rng(2))
    err = ep.position_m - motion.antenna_m(ep.time_s)
    fixed = ep.quality == 4
    assert np.std(err[fixed, 0]) == pytest.approx(RTK_FIXED_SIGMA_M[0], rel=0.05)
    assert np.std(err[fixed, 2]) == pytest.approx(RTK_FIXED_SIGMA_M[1], rel=0.05)
    assert np.std(err[ep.quality == 5, 0]) > 0.1
    assert np.all(np.isnan(ep.position_m[ep.quality == 0]))
    assert 60 <= np.sum(ep.quality == 0) <= 91


def test_smooth_field_is_standardised_and_smooth():
    f = smooth_random_field((400, 600), 0.01, 1.0, np.random.default_rng(0))
    assert abs(f.mean()) < 0.05 and abs(f.std() - 1.0) < 0.1
    assert np.abs(np.diff(f, axis=1)).max() < 0.1


@pytest.mark.parametrize("model", ["equiangular", "pinhole"])
def test_rendered_disc_lands_where_the_camera_projects_it(model):
    """A hot disc on the truth grid appears in the frame at the camera's projection of its
    centre (sub-pixel), and a uniform grid renders a uniform frame."""
    if model == "equiangular":
        cam = EquiangularCamera(96, 72, 24.0)
        ifov = cam.ifov_rad
    else:
        cam = PinholeCamera.from_aperture(96, 72, 24.0)
        ifov = 1.0 / cam.fx
    grid = GridSpec(-5.0, 15.0, 0.01, 1000, 1000, 32636)
    pose = pose_from_ptu([0.0, 0.0, 8.4], 10.0, -40.0, {"antenna_to_camera_m": [0, 0, -0.4]})
    centre = cam.ground_points(np.array([40.3]), np.array([30.7]), pose)[0]
    xs, ys = grid.cell_centres()
    xx, yy = np.meshgrid(xs, ys)
    disc = (np.hypot(xx - centre[0], yy - centre[1]) < 0.15).astype(np.float32)
    rad, rng_m = surface_radiance_frame(FrameRays(cam), pose,
                                        radiance_grid(5.0 + disc, grid, 1.0), ifov)
    w = rad - 5.0
    vv, uu = np.mgrid[0:72, 0:96]
    uc, vc = (w * uu).sum() / w.sum(), (w * vv).sum() / w.sum()
    assert uc == pytest.approx(40.3, abs=0.3) and vc == pytest.approx(30.7, abs=0.3)
    assert np.all(rng_m > 8.0)
    flat, _ = surface_radiance_frame(FrameRays(cam, (1.5, -0.5)), pose, radiance_grid(
        np.full((1000, 1000), 7.0, np.float32), grid, 1.0), ifov)
    np.testing.assert_allclose(flat, 7.0, rtol=1e-6)


@pytest.mark.parametrize("model", ["equiangular", "pinhole"])
@pytest.mark.parametrize("attitude", [(0.0, 0.0, 0.0), (-3.0, 1.5, 2.5)])
def test_frame_rays_match_camera_rays(model, attitude):
    """The whole-frame fast path equals the camera model's reference ``rays``."""
    if model == "equiangular":
        cam = EquiangularCamera(64, 48, 24.0)
    else:
        base = PinholeCamera.from_aperture(64, 48, 24.0)
        cam = PinholeCamera(64, 48, base.fx, base.fy, base.cx, base.cy,
                            (-0.06, 0.01, 0.001, -0.002, 0.0))
    pose = pose_from_ptu([1.0, 2.0, 8.4], -35.0, -50.0, {"antenna_to_camera_m": [0, 0, -0.4]},
                         attitude)
    shift = (0.7, -1.3)
    dx, dy, dz = FrameRays(cam, shift).directions(pose)
    vv, uu = np.mgrid[0:48, 0:64]
    ref = cam.rays(uu.ravel() + shift[0], vv.ravel() + shift[1], pose)
    np.testing.assert_allclose(np.stack([dx.ravel(), dy.ravel(), dz.ravel()], axis=1), ref,
                               atol=1e-12)


@given(st.floats(0.0, 1.0), st.floats(0.0, 1.0), st.sampled_from([0.3, 0.5]))
@settings(max_examples=25, deadline=None)
def test_marker_plate_is_rasterised_where_the_truth_says(fx, fy, side_m):
    """The plate's cover-weighted centroid and area are the object's, wherever its edges fall
    on the grid (also exactly on a row of cell centres, as with 0.3 m plates on a 2 cm grid
    whose centres are at odd centimetres)."""
    grid = GridSpec(532760.0, 3891970.0, 0.02, 150, 150, 32636)
    obj = SceneObject(id="MK01", kind="marker", x_m=1.0 + 0.02 * fx, y_m=1.0 + 0.02 * fy,
                      depth_m=0.0, diameter_m=side_m, variant="cold")
    origin = (532760.0, 3891967.0)
    fields = build_scene(grid, [obj], origin, np.random.default_rng(0))
    cover = fields.marker_cold.astype(np.float64)
    xs, ys = grid.cell_centres()
    area = cover.sum() * grid.pixel_size ** 2
    assert area == pytest.approx(side_m ** 2, rel=1e-5)
    assert (cover * xs[None, :]).sum() / cover.sum() == pytest.approx(origin[0] + obj.x_m,
                                                                       abs=1e-6)
    assert (cover * ys[:, None]).sum() / cover.sum() == pytest.approx(origin[1] + obj.y_m,
                                                                       abs=1e-6)
