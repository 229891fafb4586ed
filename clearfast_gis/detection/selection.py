"""Exact order statistics of large arrays: the detector's stretch limits and the clutter's
medians.

:func:`order_statistics` is the registry's ``order_statistics``
(:mod:`clearfast_gis.kernels`): radix selection (numba) on the fast kernels, ``np.partition``
on the reference ones; both return the array's own values at the ranks, so every result is
the same to the last bit. :func:`median` is ``np.median`` on them.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from clearfast_gis import kernels


def order_statistics(values: np.ndarray, ranks: Sequence[int]) -> np.ndarray:
    """The values at ``ranks`` in sorted order: ``np.partition(values, ranks)[ranks]``.

    Parameters
    ----------
    values : float32 or float64, any shape (flattened)
        Finite values (no NaN), at least one.
    ranks : sequence of int
        0-based ranks in ascending sorted order, each in ``[0, values.size)``.

    Returns
    -------
    ndarray (R,) of the values' dtype, in the order of ``ranks``
        A rank that falls on zeros of both signs gives one of them (they compare equal).
    """
    return kernels.kernel("order_statistics")(values, ranks)


def median(values: np.ndarray, dtype: type | None = None) -> np.floating:
    """``np.median(values.astype(dtype))`` of finite float32 or float64 values (any shape, at
    least one): the middle value, or for an even count the mean of the two middle ones,
    computed as ``np.median`` computes it (``np.mean`` of the two, in ``dtype``, default the
    values' own). The order statistics are found in the values' dtype (float32 values are
    selected as float32, half the bytes of their float64 copy: the same ones, as the
    conversion keeps the order). ``values`` is not modified."""
    n = np.asarray(values).size
    ranks = [(n - 1) // 2] if n % 2 else [n // 2 - 1, n // 2]
    middle = order_statistics(values, ranks)
    return np.mean(middle if dtype is None else middle.astype(dtype))
