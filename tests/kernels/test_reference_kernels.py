"""The reference kernels (``--kernels reference``) against ours: same answers, golden checks."""

from __future__ import annotations

import math

import cv2
import numpy as np
import pytest

from clearfast_gis import kernels
from clearfast_gis.detection.morphology import (
    binary_opening_by_reconstruction,
    bottom_hat_by_reconstruction,
    top_hat_by_reconstruction,
)
from clearfast_gis.registration import ConformalTransform, register_conformal
from clearfast_gis.registration.synthetic import make_pair, rms_displacement
from tests.kernels.scenes import scene


def test_use_restores_and_rejects_unknown_names():
    assert kernels.active() == "fast"
    with kernels.use("reference"):
        assert kernels.reference()
        with kernels.use("fast"):
            assert kernels.active() == "fast"
        assert kernels.active() == "reference"
    assert kernels.active() == "fast"
    with pytest.raises(ValueError, match="unknown kernel set"):
        with kernels.use("numpy"):
            pass


@pytest.mark.parametrize("hat", [top_hat_by_reconstruction, bottom_hat_by_reconstruction])
def test_reconstruction_hats_identical_to_scikit_image(hat):
    f = scene()
    ours = hat(f, 15)
    with kernels.use("reference"):
        ref = hat(f, 15)
    assert np.array_equal(np.isnan(ours), np.isnan(ref))
    np.testing.assert_array_equal(ours[~np.isnan(ours)], ref[~np.isnan(ref)])
    assert np.nanmax(ours) > 0.1  # not a trivial image


def test_binary_opening_identical_to_scikit_image():
    g = np.nan_to_num(scene(3)) > 0.2
    ours = binary_opening_by_reconstruction(g, 5)
    with kernels.use("reference"):
        ref = binary_opening_by_reconstruction(g, 5)
    assert 0 < ours.sum() < g.sum()
    np.testing.assert_array_equal(ours, ref)


@pytest.mark.parametrize("invert", [False, True])
def test_simpleitk_registration_recovers_the_transform(invert):
    shape = (256, 320)
    truth = ConformalTransform(math.radians(1.5), 6.3, -4.1,
                               center_px=((shape[1] - 1) / 2, (shape[0] - 1) / 2))
    fixed, moving = make_pair(shape, truth, seed=7, noise_k=0.1, invert=invert)
    with kernels.use("reference"):
        t = register_conformal(fixed, moving, max_shift_px=20, max_angle_deg=4)
    assert t.converged
    assert rms_displacement(t, truth, shape) < 0.05  # pixels
    assert t.metric > 0.5  # nats


def test_simpleitk_translation_only_and_bound():
    shape = (200, 240)
    truth = ConformalTransform(0.0, 3.2, 1.7, center_px=((shape[1] - 1) / 2,
                                                         (shape[0] - 1) / 2))
    fixed, moving = make_pair(shape, truth, seed=3, noise_k=0.05)
    with kernels.use("reference"):
        t = register_conformal(fixed, moving, max_shift_px=10, max_angle_deg=0)
        far = register_conformal(fixed, moving, max_shift_px=1.0, max_angle_deg=0)
    assert t.angle_rad == 0.0 and t.converged
    assert math.hypot(t.tx_px - 3.2, t.ty_px - 1.7) < 0.05
    assert not far.converged  # the optimum lies beyond the bound


def test_simpleitk_registration_in_the_chain_is_the_same_bits_every_time():
    """Inside the chain (``serial_kernels``) SimpleITK runs on one thread: its threads' partial
    metric sums, added as they finish, made repeated registrations differ in the last bits."""
    import SimpleITK as sitk

    from clearfast_gis.parallel import serial_kernels

    shape = (120, 150)
    truth = ConformalTransform(0.0, 0.41, -0.27, center_px=((shape[1] - 1) / 2,
                                                           (shape[0] - 1) / 2))
    fixed, moving = make_pair(shape, truth, seed=5, noise_k=0.1)
    before = sitk.ProcessObject.GetGlobalDefaultNumberOfThreads()
    with kernels.use("reference"), serial_kernels():
        assert sitk.ProcessObject.GetGlobalDefaultNumberOfThreads() == 1
        runs = {repr(register_conformal(fixed, moving, max_shift_px=4, max_angle_deg=0))
                for _ in range(4)}
    assert sitk.ProcessObject.GetGlobalDefaultNumberOfThreads() == before
    assert len(runs) == 1, runs
    with serial_kernels():  # the fast kernels leave SimpleITK alone
        assert sitk.ProcessObject.GetGlobalDefaultNumberOfThreads() == before


def test_sitk_transform_conversion_round_trip():
    from clearfast_gis.registration._reference import _from_sitk, _to_sitk

    t = ConformalTransform(0.03, 2.5, -1.25, center_px=(50.0, 40.0))
    back = _from_sitk(_to_sitk(t, False, False), t.center_px, False, False)
    pts = np.array([[0.0, 0.0], [99.0, 79.0], [10.0, 70.0]])
    np.testing.assert_allclose(back.apply(pts), t.apply(pts), atol=1e-9)
    # SimpleITK maps fixed points exactly as the ConformalTransform does
    st = _to_sitk(t, False, False)
    np.testing.assert_allclose([st.TransformPoint(tuple(p)) for p in pts], t.apply(pts),
                               atol=1e-9)


def test_projection_maps_and_resampling_agree():
    from clearfast_gis.geometry import CameraPose, EquiangularCamera, GroundGrid
    from clearfast_gis.geometry.projection import ground_maps
    from clearfast_gis.mosaic.project import resample

    cam = EquiangularCamera(160, 128, aperture_deg=9.0)
    pose = CameraPose(np.array([0.0, 0.0, 12.0]), azimuth_deg=20.0, elevation_deg=-35.0)
    grid = GroundGrid.from_bounds(-5.0, 5.0, 20.0, 25.0, 0.05, epsg=32636)
    mx, my = ground_maps(cam, pose, grid)
    with kernels.use("reference"):
        rx, ry = ground_maps(cam, pose, grid)
    seen = mx >= 0
    assert seen.sum() > 1000
    assert np.array_equal(seen, rx >= 0) or np.mean(seen != (rx >= 0)) < 1e-3
    both = seen & (rx >= 0)
    assert np.max(np.abs(mx[both] - rx[both])) < 1e-3  # pixels (float32 rounding)
    assert np.max(np.abs(my[both] - ry[both])) < 1e-3
    frame = scene(5, (128, 160))[:, ::-1].copy()
    frame = np.nan_to_num(frame, nan=0.5) + 20.0
    ours = resample(frame, mx, my, 1.2)
    with kernels.use("reference"):
        ref = resample(frame, mx, my, 1.2)
    inner = cv2.erode(both.astype(np.uint8), np.ones((9, 9), np.uint8)).astype(bool)
    assert np.all(np.isfinite(ref[inner]))
    # cv2 works in fixed point (1/32 pixel) and truncates its Gaussian differently
    assert np.nanmax(np.abs(ours[inner] - ref[inner])) < 0.02  # K


def test_inverse_planck_reference_is_the_paper_table():
    from clearfast_gis.radiometry.table import BandTable

    table = BandTable(8.0, 9.2)
    t = np.linspace(240.0, 340.0, 1001)
    rad = table.radiance(t)
    fast = table.temperature(rad, dtype=np.float64)
    with kernels.use("reference"):
        ref = table.temperature(rad, dtype=np.float64)
    assert np.max(np.abs(fast - t)) < 1e-3
    assert np.max(np.abs(ref - t)) < 0.03  # linear interpolation on the 0.1 K table
