"""The detector's fast kernels (``--kernels fast``, :mod:`clearfast_gis.kernels`).

- Grey-scale morphological reconstruction by Vincent's hybrid algorithm and binary
  reconstruction by a fill from the seeds (numba), behind
  :mod:`clearfast_gis.detection.reconstruction` (the module notes there give the
  conventions: 8-connectivity, NaN = no-data walls, identical to scikit-image);
- the registry's ``top_hat_by_reconstruction``, ``bottom_hat_by_reconstruction`` and
  ``binary_opening_by_reconstruction``: OpenCV disk erosion/dilation and these
  reconstructions; the public functions of the same names in
  :mod:`clearfast_gis.detection.morphology` check their input and call them through
  :func:`clearfast_gis.kernels.kernel`. Their references are in
  :mod:`clearfast_gis.detection._reference`.

Reference: L. Vincent, "Morphological grayscale reconstruction in image analysis: applications
and efficient algorithms", IEEE Trans. Image Processing 2(2), 176-201, 1993.
"""

from __future__ import annotations

import numba
import numpy as np

from clearfast_gis.detection._boxmean import box_mean_nearest
from clearfast_gis.detection._radix import radix_order_statistics
from clearfast_gis.detection.morphology import dilate_disk, erode_disk

EXTRA_PASSES = 1  # raster/anti-raster pairs before the queued one (see _hybrid_dilation)


@numba.njit(cache=True, nogil=True, inline="always")
def _row_max(row, other, best) -> None:  # pragma: no cover - compiled
    """``best[c] = max(row[c], other[c - 1], other[c], other[c + 1])`` inside the frame: the
    part of a pixel's neighbourhood that lies in an already final row (no carried
    dependency, so the loop vectorises)."""
    for c in range(1, row.size - 1):
        m = row[c]
        if other[c - 1] > m:
            m = other[c - 1]
        if other[c] > m:
            m = other[c]
        if other[c + 1] > m:
            m = other[c + 1]
        best[c] = m


@numba.njit(cache=True, nogil=True, inline="always")
def _raster_row(row, up, lim, best) -> None:  # pragma: no cover - compiled
    """One row of the raster scan: ``row[c] = min(lim[c], max(row[c], its N+ neighbours))``,
    left to right, ``up`` being the row above (already scanned)."""
    _row_max(row, up, best)
    left = row[0]
    for c in range(1, row.size - 1):
        m = best[c] if best[c] > left else left
        left = m if m < lim[c] else lim[c]
        row[c] = left


@numba.njit(cache=True, nogil=True, inline="always")
def _anti_raster_row(row, down, lim, best) -> None:  # pragma: no cover - compiled
    """One row of the anti-raster scan: as :func:`_raster_row` with the N- neighbours, right
    to left, ``down`` being the row below (already scanned)."""
    _row_max(row, down, best)
    w = row.size
    right = row[w - 1]
    for c in range(w - 2, 0, -1):
        m = best[c] if best[c] > right else right
        right = m if m < lim[c] else lim[c]
        row[c] = right


@numba.njit(cache=True, nogil=True, inline="always")
def _can_raise(row, lim, down, lim_down, rises) -> None:  # pragma: no cover - compiled
    """``rises[c]``: pixel ``c`` of a final ``row`` can still raise its right neighbour or
    one of its three neighbours in the row below (``down``), i.e. one of them lies below both
    the pixel and its own mask (``lim``, ``lim_down``). Written without short-circuits: the
    comparisons go either way at random, so branches would be mispredicted half the time."""
    for c in range(1, row.size - 1):
        v = row[c]
        rises[c] = (((row[c + 1] < v) & (row[c + 1] < lim[c + 1]))
                    | ((down[c - 1] < v) & (down[c - 1] < lim_down[c - 1]))
                    | ((down[c] < v) & (down[c] < lim_down[c]))
                    | ((down[c + 1] < v) & (down[c + 1] < lim_down[c + 1])))


@numba.njit(cache=True, nogil=True)
def _hybrid_dilation(f: np.ndarray, g: np.ndarray) -> None:
    """In-place reconstruction by dilation of ``f`` under ``g`` (2-D, same dtype).

    Both arrays carry a one-pixel frame, and the pixels that are not part of the image, at
    the lowest value of the dtype in ``f`` and ``g`` alike: such a pixel can neither rise
    nor raise a neighbour, so the scans need no bounds or validity tests. The frame is not
    written.
    """
    h, w = f.shape
    n = h * w
    best = np.empty(w, dtype=f.dtype)  # per row: max over the neighbours of the row before
    # raster scan: N+ = the four neighbours already visited (up-left, up, up-right, left); the
    # row above is final, so its part is taken for the whole row first (a loop without a
    # carried dependency), then the left neighbour in a short sequential pass. Anti-raster
    # scan: N- = right, down-left, down, down-right (same split). A first pair of scans
    # raises most pixels to their final value (a pair costs about a quarter of the queue
    # phase it saves); the second anti-raster scan queues the pixels that can still raise a
    # later neighbour, in the scan's order
    for _ in range(EXTRA_PASSES):
        for r in range(1, h - 1):
            _raster_row(f[r], f[r - 1], g[r], best)
        for r in range(h - 2, 0, -1):
            _anti_raster_row(f[r], f[r + 1], g[r], best)
    for r in range(1, h - 1):
        _raster_row(f[r], f[r - 1], g[r], best)
    queue = np.empty(n, dtype=np.int64)  # circular, n slots
    rises = np.zeros(w, dtype=np.bool_)
    inq = np.zeros(n, dtype=np.uint8)
    head = 0
    tail = 0  # next free slot
    count = 0
    for r in range(h - 2, 0, -1):
        down, row, lim, lim_down = f[r + 1], f[r], g[r], g[r + 1]
        _anti_raster_row(row, down, lim, best)
        _can_raise(row, lim, down, lim_down, rises)
        for c in range(w - 2, 0, -1):
            if rises[c]:
                p = r * w + c
                queue[tail] = p
                tail += 1  # fewer than n pixels are queued here: no wrap
                inq[p] = 1
                count += 1
    # FIFO propagation; a pixel is in the queue at most once at a time, so n slots suffice
    while count > 0:
        p = queue[head]
        head += 1
        if head == n:
            head = 0
        count -= 1
        inq[p] = 0
        r = p // w
        c = p - r * w
        v = f[r, c]
        for dr in (-1, 0, 1):
            rr = r + dr
            for dc in (-1, 0, 1):
                cc = c + dc
                fq = f[rr, cc]
                gq = g[rr, cc]
                if fq < v and fq != gq:  # False on the frame and on no-data (f = g there)
                    f[rr, cc] = v if v < gq else gq
                    q = rr * w + cc
                    if not inq[q]:
                        queue[tail] = q
                        tail += 1
                        if tail == n:
                            tail = 0
                        inq[q] = 1
                        count += 1

_KERNEL_DTYPES = (np.uint8, np.uint16, np.int32, np.float32, np.float64)


def _lowest(dtype: np.dtype) -> float | int:
    return -np.inf if dtype.kind == "f" else np.iinfo(dtype).min


def _prepare(seed: np.ndarray, mask: np.ndarray) -> tuple[np.ndarray, np.ndarray,
                                                          np.ndarray | None]:
    """Framed copies of seed and mask for :func:`_hybrid_dilation`, and the no-data mask."""
    seed = np.asarray(seed)
    mask = np.asarray(mask)
    if seed.shape != mask.shape or seed.ndim != 2:
        raise ValueError(f"seed and mask must be 2-D arrays of one shape, got {seed.shape} "
                         f"and {mask.shape}")
    dtype = np.result_type(seed.dtype, mask.dtype)
    if dtype == np.bool_:
        dtype = np.dtype(np.uint8)
    elif dtype.type not in _KERNEL_DTYPES:
        dtype = np.dtype(np.float64)
    low = _lowest(dtype)
    h, w = seed.shape
    f = np.full((h + 2, w + 2), low, dtype=dtype)
    g = np.full((h + 2, w + 2), low, dtype=dtype)
    f[1:-1, 1:-1] = seed
    g[1:-1, 1:-1] = mask
    nodata = None
    if dtype.kind == "f":
        nodata = np.isnan(f) | np.isnan(g)
        if nodata.any():
            f[nodata] = low
            g[nodata] = low
            nodata = nodata[1:-1, 1:-1]
        else:
            nodata = None
    return f, g, nodata


def reconstruction_by_dilation(seed: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """Grey-scale reconstruction by dilation of ``seed`` under ``mask`` (8-connectivity).

    Parameters
    ----------
    seed, mask : ndarray (H, W)
        bool, uint8, uint16, int32, float32 or float64 (other types are computed in float64).
        ``seed <= mask`` where both are valid; NaN marks no-data (see the module notes).

    Returns
    -------
    ndarray (H, W)
        The reconstruction, in the common dtype of the inputs (bool for bool inputs), NaN on
        no-data pixels. Identical to ``skimage.morphology.reconstruction(seed, mask,
        'dilation')`` on valid data.
    """
    is_bool = np.asarray(seed).dtype == np.bool_ and np.asarray(mask).dtype == np.bool_
    f, g, nodata = _prepare(seed, mask)
    if np.any(f > g):
        raise ValueError("reconstruction by dilation needs seed <= mask everywhere")
    _hybrid_dilation(f, g)
    out = f[1:-1, 1:-1]
    if nodata is not None:
        out[nodata] = np.nan
    return out.astype(bool) if is_bool else np.ascontiguousarray(out)


def reconstruction_by_erosion(seed: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """Grey-scale reconstruction by erosion (``seed >= mask``), by duality with dilation.

    Same conventions as :func:`reconstruction_by_dilation`; identical to
    ``skimage.morphology.reconstruction(seed, mask, 'erosion')`` on valid data.
    """
    seed = np.asarray(seed)
    mask = np.asarray(mask)
    if seed.dtype == np.bool_ and mask.dtype == np.bool_:
        return ~reconstruction_by_dilation(~seed, ~mask)
    dtype = np.result_type(seed.dtype, mask.dtype)
    if dtype.kind == "u":
        top = np.iinfo(dtype).max
        return (top - reconstruction_by_dilation(top - seed.astype(dtype),
                                                 top - mask.astype(dtype))).astype(dtype)
    return -reconstruction_by_dilation(-seed, -mask)

@numba.njit(cache=True, nogil=True)
def _flood(mask: np.ndarray, seeds: np.ndarray, out: np.ndarray) -> None:
    """Set ``out`` on the 8-connected components of ``mask`` (bool (H, W)) that hold a pixel
    of ``seeds`` (flat indices of pixels of ``mask``), by a depth-first fill from each seed:
    the work is that of the pixels reached, not of the image."""
    h, w = mask.shape
    stack = np.empty(h * w, dtype=np.int64)  # a pixel is pushed once (``out`` set at the push)
    for seed in seeds:
        r0, c0 = seed // w, seed % w
        if out[r0, c0]:
            continue
        out[r0, c0] = True
        stack[0] = seed
        top = 1
        while top > 0:
            top -= 1
            p = stack[top]
            r, c = p // w, p % w
            for rr in range(max(r - 1, 0), min(r + 2, h)):
                for cc in range(max(c - 1, 0), min(c + 2, w)):
                    if mask[rr, cc] and not out[rr, cc]:
                        out[rr, cc] = True
                        stack[top] = rr * w + cc
                        top += 1


def binary_reconstruction(seed: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """Binary reconstruction R_B(seed | mask): the 8-connected components of ``mask`` that
    touch ``seed``.

    Parameters
    ----------
    seed, mask : ndarray of bool (H, W)

    Returns
    -------
    ndarray of bool (H, W)
        Equal to ``skimage.morphology.reconstruction(seed & mask, mask)`` cast to bool; filled
        from the seeds (:func:`_flood`), so that sparse masks cost little.
    """
    mask = np.ascontiguousarray(mask, dtype=bool)
    seed = np.asarray(seed, dtype=bool)
    if seed.shape != mask.shape or mask.ndim != 2:
        raise ValueError(f"seed and mask must be 2-D arrays of one shape, got {seed.shape} "
                         f"and {mask.shape}")
    out = np.zeros(mask.shape, dtype=bool)
    _flood(mask, np.flatnonzero(seed & mask), out)
    return out


def top_hat_by_reconstruction(f: np.ndarray, d1_px: float) -> np.ndarray:
    """:func:`clearfast_gis.detection.morphology.top_hat_by_reconstruction` on the fast kernels
    (float ``f``)."""
    return f - reconstruction_by_dilation(erode_disk(f, d1_px), f)


def bottom_hat_by_reconstruction(f: np.ndarray, d1_px: float) -> np.ndarray:
    """:func:`clearfast_gis.detection.morphology.bottom_hat_by_reconstruction` on the fast kernels
    (float ``f``)."""
    return reconstruction_by_erosion(dilate_disk(f, d1_px), f) - f


def binary_opening_by_reconstruction(g: np.ndarray, d2_px: float) -> np.ndarray:
    """:func:`clearfast_gis.detection.morphology.binary_opening_by_reconstruction` on the fast
    kernels (bool ``g``)."""
    return binary_reconstruction(erode_disk(g, d2_px), g)


def order_statistics(values: np.ndarray, ranks) -> np.ndarray:
    """:func:`clearfast_gis.detection.selection.order_statistics` on the fast kernels: radix
    selection over the values' bits (:mod:`clearfast_gis.detection._radix`), no copy of the
    values."""
    return radix_order_statistics(values, ranks)


def box_mean(image: np.ndarray, size: int) -> np.ndarray:
    """:func:`clearfast_gis.detection.clutter.box_mean` on the fast kernels: running sums
    along each axis (numba, :mod:`clearfast_gis.detection._boxmean`), scipy's arithmetic
    operation for operation."""
    return box_mean_nearest(image, size)
