"""register_conformal on synthetic pairs with a known transform (<= 0.1 px RMS)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from clearfast_gis.errors import InvalidInput
from clearfast_gis.registration import ConformalTransform, register_conformal
from clearfast_gis.registration.synthetic import (
    make_pair,
    ragged_mask,
    rms_displacement,
    thermal_scene,
)

SHAPE = (192, 240)
CENTER = ((SHAPE[1] - 1) / 2.0, (SHAPE[0] - 1) / 2.0)


def _truth(angle_deg: float, tx: float, ty: float, scale: float = 1.0,
           shape: tuple[int, int] = SHAPE) -> ConformalTransform:
    c = ((shape[1] - 1) / 2.0, (shape[0] - 1) / 2.0)
    return ConformalTransform(math.radians(angle_deg), tx, ty, scale, center_px=c)


@pytest.mark.parametrize(
    ("angle_deg", "tx", "ty", "invert", "noise_k"),
    [
        (0.0, 0.37, -0.81, False, 0.05),   # sub-pixel shift
        (0.0, 12.6, -7.25, True, 0.1),     # day/night inversion
        (2.5, -4.3, 6.1, False, 0.1),
        (-4.8, 9.9, 3.3, True, 0.1),
        (5.0, -15.2, -11.7, True, 0.3),    # large angle, strong noise, inverted
        (-1.2, 0.0, 0.0, True, 0.05),
    ],
)
def test_recovers_shift_and_rotation(angle_deg: float, tx: float, ty: float, invert: bool,
                                     noise_k: float) -> None:
    truth = _truth(angle_deg, tx, ty)
    fixed, moving = make_pair(SHAPE, truth, seed=int(10 * abs(angle_deg + tx)), noise_k=noise_k,
                              invert=invert)
    result = register_conformal(fixed, moving)
    assert result.converged
    assert rms_displacement(truth, result, SHAPE) <= 0.1
    assert result.center_px == CENTER
    assert result.scale == 1.0
    assert result.n_samples > 0.8 * (SHAPE[0] * SHAPE[1]) / 4
    assert result.metric > 0.5


def test_recovers_scale() -> None:
    truth = _truth(-2.0, 3.5, -2.25, 1.07)
    fixed, moving = make_pair(SHAPE, truth, seed=5, noise_k=0.1, invert=True)
    result = register_conformal(fixed, moving, scale=True)
    assert result.converged
    assert result.scale == pytest.approx(1.07, abs=2e-3)
    assert rms_displacement(truth, result, SHAPE) <= 0.1


def test_full_size_frame_with_inversion() -> None:
    shape = (512, 640)
    truth = _truth(3.7, -22.4, 17.85, shape=shape)
    fixed, moving = make_pair(shape, truth, seed=11, noise_k=0.1, invert=True)
    result = register_conformal(fixed, moving)
    assert result.converged
    assert rms_displacement(truth, result, shape) <= 0.1


@pytest.mark.parametrize("seed", [0, 1])
def test_ragged_nan_footprints_with_partial_overlap(seed: int) -> None:
    truth = _truth(3.0, 40.5, -25.3)
    fixed, moving = make_pair(SHAPE, truth, seed=seed, noise_k=0.1, invert=True)
    fixed[~ragged_mask(SHAPE, seed, 0.65)] = np.nan
    moving[~ragged_mask(SHAPE, seed + 9, 0.65)] = np.nan
    result = register_conformal(fixed, moving)
    assert result.converged
    assert rms_displacement(truth, result, SHAPE) <= 0.1


def test_masks_exclude_corrupted_pixels() -> None:
    truth = _truth(1.0, 6.2, -3.1)
    fixed, moving = make_pair(SHAPE, truth, seed=21, noise_k=0.1)
    # a hot artefact (sun glint) on the moving image, masked out
    moving_mask = np.ones(moving.shape, bool)
    moving_mask[40:120, 60:160] = False
    moving[~moving_mask] = 80.0
    fixed_mask = np.ones(fixed.shape, bool)
    fixed_mask[:, :20] = False
    result = register_conformal(fixed, moving, fixed_mask=fixed_mask, moving_mask=moving_mask)
    assert result.converged
    assert rms_displacement(truth, result, SHAPE) <= 0.1


def test_moving_image_of_another_shape() -> None:
    truth = _truth(2.0, -30.2, 20.7)
    fixed, moving = make_pair(SHAPE, truth, seed=31, noise_k=0.1, invert=True,
                              moving_shape=(300, 360))
    result = register_conformal(fixed, moving)
    assert result.converged
    assert rms_displacement(truth, result, SHAPE) <= 0.1


def test_large_shift_half_the_field_of_view() -> None:
    truth = _truth(1.0, 110.2, 45.7)
    fixed, moving = make_pair(SHAPE, truth, seed=41, noise_k=0.1)
    result = register_conformal(fixed, moving)
    assert result.converged
    assert rms_displacement(truth, result, SHAPE) <= 0.1


def test_translation_only_and_init() -> None:
    truth = _truth(0.0, 2.3, -1.6)
    fixed, moving = make_pair(SHAPE, truth, seed=51, noise_k=0.1, invert=True)
    result = register_conformal(fixed, moving, max_angle_deg=0.0, max_shift_px=5.0)
    assert result.angle_rad == 0.0
    assert result.converged
    assert rms_displacement(truth, result, SHAPE) <= 0.05
    # a start from a geometric pose, with a different rotation centre
    init = ConformalTransform(0.0, 2.0, -1.0, center_px=(0.0, 0.0))
    result = register_conformal(fixed, moving, init=init, max_shift_px=3.0, max_angle_deg=1.0)
    assert result.converged
    assert rms_displacement(truth, result, SHAPE) <= 0.1


def test_sample_budget_and_the_final_polish() -> None:
    """A small sample budget (the attitude ties' 12,000 of ~30,000 cells) keeps the shift to
    hundredths of a pixel; when every cell is already a sample the polish is skipped (the
    same problem again) and the result is the same as with a larger polish budget."""
    from clearfast_gis.registration import _kernels

    truth = _truth(0.0, 3.4, -2.2)
    fixed, moving = make_pair(SHAPE, truth, seed=52, noise_k=0.1, invert=True)
    small = register_conformal(fixed, moving, max_angle_deg=0.0, max_shift_px=8.0,
                               max_samples=12_000, polish_samples=12_000)
    assert small.converged and rms_displacement(truth, small, SHAPE) <= 0.05
    level = _kernels._level_problem(fixed, moving, (0.0, 1.0), (0.0, 1.0), 24,
                                     fixed.size, 1.0)
    assert level.complete and level.us.size == fixed.size
    assert not _kernels._level_problem(fixed, moving, (0.0, 1.0), (0.0, 1.0), 24,
                                        fixed.size - 1, 1.0).complete
    every = register_conformal(fixed, moving, max_angle_deg=0.0, max_shift_px=8.0,
                               max_samples=fixed.size, polish_samples=2 * fixed.size)
    same = register_conformal(fixed, moving, max_angle_deg=0.0, max_shift_px=8.0,
                              max_samples=fixed.size, polish_samples=4 * fixed.size)
    assert (every.tx_px, every.ty_px) == (same.tx_px, same.ty_px)
    assert rms_displacement(truth, every, SHAPE) <= 0.05


def test_bounds_that_exclude_the_truth_are_reported() -> None:
    truth = _truth(0.0, 9.0, 0.0)
    fixed, moving = make_pair(SHAPE, truth, seed=61, noise_k=0.1)
    result = register_conformal(fixed, moving, max_shift_px=4.0, max_angle_deg=0.0)
    assert not result.converged
    assert abs(result.tx_px) <= 4.0 + 1e-9


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_unrelated_images_do_not_converge(seed: int) -> None:
    a = thermal_scene(SHAPE, seed).astype(np.float32)
    b = thermal_scene(SHAPE, seed + 50).astype(np.float32)
    result = register_conformal(a, b)
    assert not result.converged
    noise = np.random.default_rng(seed).normal(size=SHAPE).astype(np.float32)
    assert not register_conformal(a, noise).converged


def test_agrees_with_simpleitk_mattes_mi() -> None:
    sitk = pytest.importorskip("SimpleITK")
    truth = _truth(2.0, 3.4, -2.7)
    fixed, moving = make_pair(SHAPE, truth, seed=71, noise_k=0.1, invert=True)
    f_img = sitk.GetImageFromArray(fixed)
    m_img = sitk.GetImageFromArray(moving)
    reg = sitk.ImageRegistrationMethod()
    reg.SetMetricAsMattesMutualInformation(50)
    reg.SetInterpolator(sitk.sitkLinear)
    reg.SetOptimizerAsRegularStepGradientDescent(1.0, 1e-4, 300)
    reg.SetOptimizerScalesFromPhysicalShift()
    reg.SetShrinkFactorsPerLevel([4, 2, 1])
    reg.SetSmoothingSigmasPerLevel([2, 1, 0])
    reg.SetInitialTransform(sitk.CenteredTransformInitializer(
        f_img, m_img, sitk.Euler2DTransform(),
        sitk.CenteredTransformInitializerFilter.GEOMETRY), inPlace=False)
    out = sitk.Euler2DTransform(sitk.CompositeTransform(reg.Execute(f_img, m_img))
                                .GetNthTransform(0))
    a = np.array(out.GetMatrix()).reshape(2, 2)
    c = np.array(out.GetCenter())
    b = c + np.array(out.GetTranslation()) - a @ c
    reference = ConformalTransform.from_matrix(np.hstack([a, b[:, None]]), CENTER)
    ours = register_conformal(fixed, moving)
    assert rms_displacement(reference, ours, SHAPE) <= 0.05
    assert rms_displacement(truth, ours, SHAPE) <= rms_displacement(truth, reference, SHAPE) + 0.02


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"fixed": np.zeros((5, 5))}, "fixed"),
        ({"moving": np.zeros((10, 10, 3))}, "moving"),
        ({"moving": np.full(SHAPE, np.nan)}, "moving"),
        ({"bins": 4}, "bins"),
        ({"max_angle_deg": -1.0}, "max_angle_deg"),
        ({"max_shift_px": -2.0}, "max_shift_px"),
    ],
)
def test_bad_input_raises_invalid_input(kwargs: dict, field: str) -> None:
    args = {"fixed": thermal_scene(SHAPE, 0), "moving": thermal_scene(SHAPE, 1), **kwargs}
    with pytest.raises(InvalidInput) as err:
        register_conformal(**args)
    assert err.value.field == field


def test_featureless_image_is_not_converged() -> None:
    flat = np.full(SHAPE, 12.5, dtype=np.float32)
    result = register_conformal(flat, thermal_scene(SHAPE, 3))
    assert not result.converged
    assert np.isfinite([result.angle_rad, result.tx_px, result.ty_px]).all()
