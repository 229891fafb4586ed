"""Mutual information: golden values against numpy and scikit-image, kernel gradient."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from skimage.metrics import normalized_mutual_information as sk_nmi

from clearfast_gis.registration import (
    ConformalTransform,
    mutual_information,
    normalized_mutual_information,
)
from clearfast_gis.registration._kernels import mi_from_histogram, parzen_joint_histogram
from clearfast_gis.registration.synthetic import make_pair, thermal_scene


def _reference_mi(a: np.ndarray, b: np.ndarray, bins: int) -> float:
    """Textbook MI from numpy.histogram2d."""
    hist, _, _ = np.histogram2d(a.ravel(), b.ravel(), bins=bins)
    p = hist / hist.sum()
    pa = p.sum(axis=1, keepdims=True)
    pb = p.sum(axis=0, keepdims=True)
    nz = p > 0
    return float((p[nz] * np.log(p[nz] / (pa @ pb)[nz])).sum())


@pytest.mark.parametrize("bins", [8, 32, 50])
def test_mi_matches_numpy_histogram(bins: int) -> None:
    a = thermal_scene((120, 150), 1)
    b = 40.0 - 3.0 * np.exp(thermal_scene((120, 150), 2) / 12.0) + 0.3 * a
    assert mutual_information(a, b, bins=bins) == pytest.approx(_reference_mi(a, b, bins),
                                                                rel=1e-10)


@pytest.mark.parametrize("bins", [10, 32, 100])
def test_nmi_matches_skimage(bins: int) -> None:
    a = thermal_scene((100, 130), 3)
    b = np.sqrt(a - a.min() + 1.0) + np.random.default_rng(0).normal(0, 0.2, a.shape)
    assert normalized_mutual_information(a, b, bins=bins) == pytest.approx(
        sk_nmi(a, b, bins=bins), rel=1e-10)


def test_mi_of_image_with_itself_is_its_entropy_and_polarity_blind() -> None:
    a = thermal_scene((80, 90), 4)
    hist, _ = np.histogram(a, bins=32)
    p = hist[hist > 0] / a.size
    entropy = float(-(p * np.log(p)).sum())
    assert mutual_information(a, a) == pytest.approx(entropy, rel=1e-12)
    assert mutual_information(a, 50.0 - 2.0 * a) == pytest.approx(entropy, rel=1e-12)
    assert normalized_mutual_information(a, a) == pytest.approx(2.0)


def test_mask_and_nan_select_the_same_pixels() -> None:
    a = thermal_scene((90, 100), 5)
    b = a ** 1.5 + np.random.default_rng(1).normal(0, 5, a.shape)
    mask = np.zeros(a.shape, bool)
    mask[10:70, 20:90] = True
    b_nan = b.copy()
    b_nan[~mask] = np.nan
    assert mutual_information(a, b, mask=mask) == pytest.approx(
        _reference_mi(a[mask], b[mask], 32), rel=1e-10)
    assert mutual_information(a, b_nan) == pytest.approx(mutual_information(a, b, mask=mask))


def test_independent_images_have_small_mi() -> None:
    rng = np.random.default_rng(2)
    a = rng.normal(size=(300, 300))
    b = rng.normal(size=(300, 300))
    # plug-in bias ~ (bins - 1)^2 / (2 N) = 0.0053 nats
    assert mutual_information(a, b) < 0.01
    assert mutual_information(a, a) > 2.0


def test_empty_overlap_gives_zero() -> None:
    a = np.full((10, 10), np.nan)
    assert mutual_information(a, a) == 0.0
    assert normalized_mutual_information(a, a) == 1.0


def _kernel_mi(fixed: np.ndarray, mov_bin: np.ndarray, t: ConformalTransform,
               want_grad: bool = True) -> tuple[float, np.ndarray]:
    h, w = fixed.shape
    vv, uu = np.mgrid[8:h - 8:2, 8:w - 8:2]  # all samples stay inside the moving image
    fb = np.clip(((fixed[vv, uu] - fixed.min()) / np.ptp(fixed) * 24).astype(np.int32), 0, 23)
    gy, gx = np.gradient(mov_bin)
    hist = np.zeros((24, 24))
    dhist = np.zeros((24, 24, 4))
    grad = np.zeros(4)
    parzen_joint_histogram(uu.ravel().astype(float), vv.ravel().astype(float), fb.ravel(),
                           mov_bin, gx.astype(np.float32), gy.astype(np.float32),
                           t.angle_rad, t.tx_px, t.ty_px, t.scale, t.center_px[0],
                           t.center_px[1], hist, dhist, want_grad)
    return mi_from_histogram(hist, dhist, want_grad, grad), grad


def test_parzen_mi_gradient_matches_finite_differences() -> None:
    shape = (96, 120)
    c = ((shape[1] - 1) / 2, (shape[0] - 1) / 2)
    truth = ConformalTransform(0.03, 1.7, -2.2, center_px=c)
    fixed, moving = make_pair(shape, truth, seed=3, noise_k=0.0, invert=True)
    mov_bin = (2.0 + (moving - moving.min()) / np.ptp(moving) * 19.0).astype(np.float32)
    # away from the optimum so the gradient is not ~0
    t = ConformalTransform(0.01, 1.0, -1.5, 1.02, center_px=c)
    mi, grad = _kernel_mi(fixed, mov_bin, t)
    steps = [1e-4, 1e-3, 1e-3, 1e-4]
    for k, name in enumerate(["angle_rad", "tx_px", "ty_px", "scale"]):
        def shifted(sign: float, k: int = k, name: str = name) -> ConformalTransform:
            val = getattr(t, name)
            new = val * math.exp(sign * steps[k]) if name == "scale" else val + sign * steps[k]
            return ConformalTransform(**{**t.__dict__, name: new})

        fd = (_kernel_mi(fixed, mov_bin, shifted(1))[0]
              - _kernel_mi(fixed, mov_bin, shifted(-1))[0]) / (2 * steps[k])
        # the analytic gradient interpolates the image gradient bilinearly: a few % off
        assert grad[k] == pytest.approx(fd, rel=0.08, abs=1e-3 * abs(grad).max())
    assert 0.2 < mi < 3.0


def test_parzen_mi_peaks_at_the_truth() -> None:
    shape = (96, 120)
    c = ((shape[1] - 1) / 2, (shape[0] - 1) / 2)
    truth = ConformalTransform(0.02, 3.3, -1.2, center_px=c)
    fixed, moving = make_pair(shape, truth, seed=4, noise_k=0.0, invert=True)
    mov_bin = (2.0 + (moving - moving.min()) / np.ptp(moving) * 19.0).astype(np.float32)
    best = _kernel_mi(fixed, mov_bin, truth, False)[0]
    for dx, dy in [(0.5, 0), (-0.5, 0), (0, 0.5), (0, -0.5)]:
        off = ConformalTransform(truth.angle_rad, truth.tx_px + dx, truth.ty_px + dy,
                                 center_px=c)
        assert _kernel_mi(fixed, mov_bin, off, False)[0] < best


def _bspline3_np(x: np.ndarray) -> np.ndarray:
    ax = np.abs(x)
    return np.where(ax < 1, 2 / 3 - ax**2 + 0.5 * ax**3, np.where(ax < 2, (2 - ax) ** 3 / 6, 0))


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-1.5, 25.5), min_size=2, max_size=40), st.booleans())
def test_parzen_histogram_equals_the_bspline_definition(values, shift_only) -> None:
    """Golden: the histogram is the cubic B-spline Parzen window of each sample's moving bin,
    wherever the bin lies (including next to and beyond the histogram edges), with and
    without the translation-only gradient."""
    nb = 24
    n = len(values)
    mov = np.array(values, dtype=np.float32)[None, :].repeat(2, axis=0)  # (2, n)
    us = np.arange(n, dtype=float)
    vs = np.zeros(n)
    fb = (np.arange(n) % nb).astype(np.int32)
    zero = np.zeros_like(mov)
    hist = np.zeros((nb, nb))
    dhist = np.zeros((nb, nb, 4))
    got = parzen_joint_histogram(us, vs, fb, mov, zero, zero, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                                 hist, dhist, True, shift_only)
    assert got == n
    want = np.zeros((nb, nb))
    for k, v in enumerate(mov[0].astype(float)):
        want[fb[k]] += _bspline3_np(v - np.arange(nb))
    np.testing.assert_allclose(hist, want, atol=1e-12)


def test_translation_only_gradient_is_the_full_gradients_shift_part() -> None:
    shape = (96, 120)
    c = ((shape[1] - 1) / 2, (shape[0] - 1) / 2)
    fixed, moving = make_pair(shape, ConformalTransform(0.02, 1.3, -0.7, center_px=c), seed=5,
                              noise_k=0.0, invert=False)
    mov_bin = (2.0 + (moving - moving.min()) / np.ptp(moving) * 19.0).astype(np.float32)
    gy, gx = np.gradient(mov_bin)
    h, w = fixed.shape
    vv, uu = np.mgrid[8:h - 8:2, 8:w - 8:2]
    fb = np.clip(((fixed[vv, uu] - fixed.min()) / np.ptp(fixed) * 24).astype(np.int32), 0, 23)
    out = {}
    for shift_only in (False, True):
        hist = np.zeros((24, 24))
        dhist = np.zeros((24, 24, 4))
        parzen_joint_histogram(uu.ravel().astype(float), vv.ravel().astype(float), fb.ravel(),
                               mov_bin, gx.astype(np.float32), gy.astype(np.float32),
                               0.01, 0.6, -0.4, 1.0, c[0], c[1], hist, dhist, True,
                               shift_only)
        out[shift_only] = (hist, dhist)
    np.testing.assert_array_equal(out[True][0], out[False][0])
    np.testing.assert_array_equal(out[True][1][..., 1:3], out[False][1][..., 1:3])
    assert not out[True][1][..., [0, 3]].any() and out[False][1][..., [0, 3]].any()
