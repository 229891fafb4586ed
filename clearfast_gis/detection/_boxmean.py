"""The mean over a square window with the edges extended (numba), behind the fast
``box_mean`` kernel (:func:`clearfast_gis.detection._kernels.box_mean`).

scipy's ``uniform_filter(mode="nearest")`` runs a sum along each axis in turn (the rows' axis
first) and divides each running sum by the window: ``sum += in[i + s2] - in[i - s1 - 1]``,
``out[i] = sum / size``, the window's first sum added up from its first value on. This is that
arithmetic, operation for operation, so the values are the same bit for bit (tested against
scipy): down the columns with the running sums of a whole row of columns at once (contiguous
rows, independent sums), and along the rows in blocks of :data:`ROWS_PER_BLOCK` rows whose
running sums advance together. 7 ms against scipy's 12-38 ms on a 1097 x 1600 float64 image
and a 15-cell window.
"""

from __future__ import annotations

import numba
import numpy as np

ROWS_PER_BLOCK = 8
"""Rows whose running sums along the row advance together (independent additions)."""


@numba.njit(cache=True, nogil=True, inline="always")
def _halves(size):  # pragma: no cover - compiled
    """Cells of a ``size`` window before and after its centre (scipy's, origin 0)."""
    before = size // 2
    return before, size - before - 1


@numba.njit(cache=True, nogil=True)
def _down_columns(a, size, out):  # pragma: no cover - compiled
    """Running means of ``a`` (H, W) down each column into ``out``, edges extended."""
    h, w = a.shape
    s1, s2 = _halves(size)
    acc = np.zeros(w)
    for k in range(-s1, s2 + 1):
        row = a[min(max(k, 0), h - 1)]
        for c in range(w):
            acc[c] += row[c]
    for c in range(w):
        out[0, c] = acc[c] / size
    for i in range(1, h):
        come = a[min(i + s2, h - 1)]
        go = a[max(i - s1 - 1, 0)]
        dst = out[i]
        for c in range(w):
            acc[c] += come[c] - go[c]
            dst[c] = acc[c] / size


@numba.njit(cache=True, nogil=True)
def _along_rows(a, size, out):  # pragma: no cover - compiled
    """Running means of ``a`` (H, W) along each row into ``out``, edges extended."""
    h, w = a.shape
    s1, s2 = _halves(size)
    acc = np.zeros(ROWS_PER_BLOCK)
    for r0 in range(0, h, ROWS_PER_BLOCK):
        nb = min(ROWS_PER_BLOCK, h - r0)
        for k in range(nb):
            s = 0.0
            for q in range(-s1, s2 + 1):
                s += a[r0 + k, min(max(q, 0), w - 1)]
            acc[k] = s
            out[r0 + k, 0] = s / size
        for j in range(1, w):
            come = min(j + s2, w - 1)
            go = max(j - s1 - 1, 0)
            for k in range(nb):
                acc[k] += a[r0 + k, come] - a[r0 + k, go]
                out[r0 + k, j] = acc[k] / size


def box_mean_nearest(image: np.ndarray, size: int) -> np.ndarray:
    """Mean of ``image`` (H, W) over a ``size`` x ``size`` window centred on each cell (the
    window's extra cell, for an even size, before the centre), the image's edge values
    extended beyond it; float64 (H, W)."""
    a = np.ascontiguousarray(image, dtype=np.float64)
    if size <= 1:  # scipy leaves the image as it is
        return a.copy()
    down = np.empty_like(a)
    _down_columns(a, int(size), down)
    out = np.empty_like(a)
    _along_rows(down, int(size), out)
    return out
