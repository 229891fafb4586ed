"""Golden tests: the reconstruction kernels against scikit-image (bit-identical)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy import ndimage
from skimage.morphology import dilation, disk, erosion
from skimage.morphology import reconstruction as sk_reconstruction

from clearfast_gis.detection import (
    binary_opening_by_reconstruction,
    binary_reconstruction,
    bottom_hat_by_reconstruction,
    dilate_disk,
    disk_footprint,
    erode_disk,
    reconstruction,
    top_hat_by_reconstruction,
)


def _images(dtype, rng):
    """Random and structured (seed, mask) pairs for reconstruction by dilation."""
    out = []
    for shape in [(1, 1), (1, 17), (23, 1), (31, 29), (64, 80)]:
        noise = rng.random(shape)
        smooth = ndimage.gaussian_filter(rng.random(shape), 2.0)
        for base in (noise, smooth):
            mask = (base * 200).astype(dtype)
            out.append((np.minimum(mask, (mask * rng.random(shape)).astype(dtype)), mask))
            out.append((erosion(mask, disk(2)), mask))
    # structured: plateaus, a ring, a checkerboard and a spiral corridor
    yy, xx = np.mgrid[:48, :48]
    ring = ((np.hypot(yy - 24, xx - 24) > 10) & (np.hypot(yy - 24, xx - 24) < 14)) * 100
    checker = ((yy // 4 + xx // 4) % 2) * 50 + 10
    spiral = np.zeros((48, 48))
    spiral[2:46:4, 2:46] = 90
    spiral[2:46, 2:4] = 90
    for mask in (ring, checker, spiral):
        mask = mask.astype(dtype)
        seed = np.zeros_like(mask)
        seed[24, 24] = mask[24, 24]
        seed[2, 2] = mask[2, 2]
        out.append((seed, mask))
    return out


@pytest.mark.parametrize("dtype", [np.uint8, np.float32, np.float64])
def test_dilation_matches_skimage(dtype):
    rng = np.random.default_rng(1)
    for seed, mask in _images(dtype, rng):
        ours = reconstruction(seed, mask, "dilation")
        ref = sk_reconstruction(seed, mask, "dilation")
        assert ours.dtype == np.dtype(dtype)
        np.testing.assert_array_equal(ours, ref.astype(ours.dtype))


@pytest.mark.parametrize("dtype", [np.uint8, np.float32, np.float64])
def test_erosion_matches_skimage(dtype):
    rng = np.random.default_rng(2)
    for _seed, mask in _images(dtype, rng):
        # reconstruction by erosion wants seed >= mask: use the dual pair
        hi = dilation(mask, disk(2))
        ours = reconstruction(hi, mask, "erosion")
        ref = sk_reconstruction(hi, mask, "erosion")
        np.testing.assert_array_equal(ours, ref.astype(ours.dtype))


def test_bool_reconstruction_and_binary_labels():
    rng = np.random.default_rng(3)
    mask = rng.random((60, 70)) > 0.45
    seed = (rng.random((60, 70)) > 0.97) & mask
    ref = sk_reconstruction(seed.astype(np.uint8), mask.astype(np.uint8)).astype(bool)
    np.testing.assert_array_equal(reconstruction(seed, mask), ref)
    np.testing.assert_array_equal(binary_reconstruction(seed, mask), ref)


@given(st.integers(1, 40), st.integers(1, 40), st.floats(0.2, 0.8), st.floats(0.0, 0.2),
       st.integers(0, 2**32 - 1))
@settings(max_examples=60, deadline=None)
def test_binary_reconstruction_property_matches_skimage(h, w, density, seed_share, rs):
    """The seeded fill against scikit-image (8-connectivity), seeds inside and outside the
    mask, empty seeds and masks included."""
    rng = np.random.default_rng(rs)
    mask = rng.random((h, w)) < density
    seed = rng.random((h, w)) < seed_share
    ref = sk_reconstruction((seed & mask).astype(np.uint8), mask.astype(np.uint8),
                            footprint=np.ones((3, 3), bool)).astype(bool)
    np.testing.assert_array_equal(binary_reconstruction(seed, mask), ref)


@settings(max_examples=40, deadline=None)
@given(arrays(np.float32, st.tuples(st.integers(1, 20), st.integers(1, 20)),
              elements=st.floats(-1e3, 1e3, width=32)),
       st.integers(0, 2**31 - 1))
def test_property_matches_skimage(mask, seed_int):
    rng = np.random.default_rng(seed_int)
    seed = np.minimum(mask, mask - np.float32(rng.random()) * 100).astype(np.float32)
    np.testing.assert_array_equal(reconstruction(seed, mask),
                                  sk_reconstruction(seed, mask).astype(np.float32))


def test_nan_is_a_wall():
    mask = np.full((5, 9), 10.0, dtype=np.float32)
    mask[:, 4] = np.nan  # a no-data column splits the image
    seed = np.zeros_like(mask)
    seed[2, 0] = 10.0
    out = reconstruction(seed, mask)
    assert np.all(out[:, :4] == 10.0)
    assert np.all(np.isnan(out[:, 4]))
    assert np.all(out[:, 5:] == 0.0)
    # equal to skimage with -inf in place of NaN
    wall = np.isnan(mask)
    ref = sk_reconstruction(np.where(wall, -np.inf, seed), np.where(wall, -np.inf, mask))
    np.testing.assert_array_equal(out[:, :4], ref[:, :4])
    np.testing.assert_array_equal(out[:, 5:], ref[:, 5:])


def test_rejects_seed_above_mask():
    with pytest.raises(ValueError):
        reconstruction(np.ones((3, 3)), np.zeros((3, 3)))


@pytest.mark.parametrize("diameter", [1, 3, 5, 8, 11, 21])
def test_disk_erosion_matches_skimage(diameter):
    rng = np.random.default_rng(diameter)
    image = rng.random((40, 50)).astype(np.float32)
    fp = disk_footprint(diameter)
    assert fp.shape[0] % 2 == 1
    np.testing.assert_array_equal(erode_disk(image, diameter), erosion(image, fp))
    np.testing.assert_array_equal(dilate_disk(image, diameter), dilation(image, fp))


def test_tophat_and_bottomhat_equal_skimage_composition():
    rng = np.random.default_rng(5)
    f = ndimage.gaussian_filter(rng.random((64, 72)), 1.5).astype(np.float32)
    fp = disk_footprint(9)
    ref_top = f - sk_reconstruction(erosion(f, fp), f)
    ref_bot = sk_reconstruction(dilation(f, fp), f, "erosion") - f
    np.testing.assert_array_equal(top_hat_by_reconstruction(f, 9), ref_top.astype(np.float32))
    np.testing.assert_array_equal(bottom_hat_by_reconstruction(f, 9),
                                  ref_bot.astype(np.float32))


def test_tophat_keeps_small_peak_and_drops_plateau():
    f = np.zeros((60, 60), np.float32)
    yy, xx = np.mgrid[:60, :60]
    f[np.hypot(yy - 15, xx - 15) <= 3] = 2.0  # small: kept
    f[30:55, 30:55] = 5.0  # bigger than D1: removed
    t = top_hat_by_reconstruction(f, 11)
    assert t[15, 15] == pytest.approx(2.0)
    assert np.all(t[30:55, 30:55] == 0.0)


def test_binary_opening_by_reconstruction_keeps_whole_shapes():
    g = np.zeros((40, 40), bool)
    g[5:15, 5:15] = True
    g[15, 15:30] = True  # a thin tail attached to the square: kept whole
    g[30, 30] = True  # speck: removed
    o = binary_opening_by_reconstruction(g, 5)
    assert o[15, 29] and o[5, 5] and not o[30, 30]
