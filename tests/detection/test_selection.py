"""Exact order statistics by radix selection: the same values as np.partition and np.median,
to the last bit, on the data the detector meets (hats full of zeros, ties, negative values,
both zeros)."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis import kernels
from clearfast_gis.detection._radix import SORT_BELOW
from clearfast_gis.detection.selection import median, order_statistics
from clearfast_gis.detection.stretch import stretch_limits


def _values(n: int, dtype, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    v = rng.normal(5.0, 3.0, n).astype(dtype)
    if n > 10:
        v[: n // 3] = 0.0  # many equal values (a hat image's zeros)
        v[n // 3: n // 3 + 3] = -0.0
        v[n - n // 5:] = rng.integers(-3, 3, n // 5)  # ties among negative and positive values
    return v


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("n", [1, 2, 7, 300, SORT_BELOW + 1, 20_000, 70_000, 200_001])
def test_same_values_as_partition(n, dtype):
    v = _values(n, dtype, seed=n)
    before = v.copy()
    ranks = sorted({0, n - 1, n // 2, max(0, n // 2 - 1), int(0.01 * n), int(0.99 * n)})
    got = order_statistics(v, ranks)
    assert got.dtype == dtype
    np.testing.assert_array_equal(got, np.partition(v, ranks)[ranks])
    np.testing.assert_array_equal(v, before)  # not modified
    assert median(v) == np.median(v) and type(median(v)) is type(np.median(v))


def test_ranks_in_any_order_and_repeated():
    v = _values(10_000, np.float64, seed=3)
    got = order_statistics(v, [9_999, 0, 5_000, 5_000])
    s = np.sort(v)
    np.testing.assert_array_equal(got, s[[9_999, 0, 5_000, 5_000]])


def test_even_median_is_the_mean_of_the_middle_pair():
    assert median(np.array([4.0, 1.0, 3.0, 2.0])) == 2.5
    assert median(np.array([1.0, 2.0], dtype=np.float32)) == np.float32(1.5)
    big = np.array([1e308, 1e308, -1.0, 3.0])  # the mean in float64 overflows as np.median's
    with np.errstate(over="ignore"):
        assert median(big) == np.median(big)


def test_narrowing_to_the_last_bits():
    """More than SORT_BELOW values sharing their top 32 bits: resolved by the low bits."""
    base = np.float64(1.0)
    v = base + np.arange(3 * SORT_BELOW) * np.finfo(np.float64).eps
    np.random.default_rng(0).shuffle(v)
    ranks = [0, 17, 2 * SORT_BELOW, 3 * SORT_BELOW - 1]
    np.testing.assert_array_equal(order_statistics(v, ranks), np.sort(v)[ranks])


def test_stretch_limits_same_on_both_kernel_sets():
    rng = np.random.default_rng(8)
    hat = np.maximum(rng.normal(0.0, 0.3, (300, 400)), 0.0).astype(np.float32)
    hat[:20] = np.nan
    fast = stretch_limits(hat, 0.01)
    with kernels.use("reference"):
        ref = stretch_limits(hat, 0.01)
    assert fast == ref and fast[0] == 0.0 and fast[1] > 0.5


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_zeros_alone_and_beside_subnormals(dtype):
    """A rank on zeros is answered from the counts alone when the zeros' bucket holds nothing
    else; subnormals share that bucket, and are then gathered and ordered."""
    tiny = np.finfo(dtype).smallest_subnormal
    for extra in ([], [tiny, 3 * tiny, -tiny]):
        v = np.concatenate([np.zeros(30_000, dtype), np.array(extra, dtype),
                            np.linspace(-1, 1, 9_999).astype(dtype)])
        np.random.default_rng(5).shuffle(v)
        ranks = list(range(0, v.size, 997)) + [v.size - 1]
        np.testing.assert_array_equal(order_statistics(v, ranks), np.sort(v)[ranks])


def test_other_dtypes_are_refused():
    with pytest.raises(TypeError):
        order_statistics(np.arange(10, dtype=np.int32), [3])
