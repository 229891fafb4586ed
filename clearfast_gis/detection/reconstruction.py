"""Grey-scale and binary morphological reconstruction (Vincent 1993, hybrid algorithm).

Reconstruction by dilation of a *seed* under a *mask* (``seed <= mask``) is the limit of
geodesic dilations of the seed inside the mask with the 3x3 element B (8-connectivity).
Vincent's hybrid algorithm does one raster scan, one anti-raster scan that also queues the
pixels that can still propagate, and then a FIFO-queue propagation; it gives exactly the values
of :func:`skimage.morphology.reconstruction` (only min and max are used, so no rounding) and is
several times faster on thermal images.

No-data: NaN pixels of a floating-point mask (or seed) are not part of the image. They neither
receive nor pass on values, so they behave like walls, and they are NaN in the result. This is
the same as giving them the value -inf in both seed and mask for reconstruction by dilation (and
+inf for reconstruction by erosion).

Reference: L. Vincent, "Morphological grayscale reconstruction in image analysis: applications
and efficient algorithms", IEEE Trans. Image Processing 2(2), 176-201, 1993.
"""

from __future__ import annotations

import numba
import numpy as np
from scipy import ndimage

__all__ = ["binary_reconstruction", "reconstruction", "reconstruction_by_dilation",
           "reconstruction_by_erosion"]


@numba.njit(cache=True, nogil=True)
def _hybrid_dilation(f: np.ndarray, g: np.ndarray, valid: np.ndarray) -> None:
    """In-place reconstruction by dilation of ``f`` under ``g`` (2-D, same dtype).

    ``valid`` (uint8, same shape) is 0 on pixels that are not part of the image.
    """
    h, w = f.shape
    n = h * w
    # raster scan: N+ = the four neighbours already visited (up-left, up, up-right, left)
    for r in range(h):
        for c in range(w):
            if not valid[r, c]:
                continue
            m = f[r, c]
            if r > 0:
                for dc in (-1, 0, 1):
                    cc = c + dc
                    if 0 <= cc < w and valid[r - 1, cc] and f[r - 1, cc] > m:
                        m = f[r - 1, cc]
            if c > 0 and valid[r, c - 1] and f[r, c - 1] > m:
                m = f[r, c - 1]
            f[r, c] = m if m < g[r, c] else g[r, c]
    # anti-raster scan: N- = right, down-left, down, down-right; queue pixels that can propagate
    queue = np.empty(n, dtype=np.int64)
    inq = np.zeros(n, dtype=np.uint8)
    head = 0
    count = 0
    for r in range(h - 1, -1, -1):
        for c in range(w - 1, -1, -1):
            if not valid[r, c]:
                continue
            m = f[r, c]
            if c + 1 < w and valid[r, c + 1] and f[r, c + 1] > m:
                m = f[r, c + 1]
            if r + 1 < h:
                for dc in (-1, 0, 1):
                    cc = c + dc
                    if 0 <= cc < w and valid[r + 1, cc] and f[r + 1, cc] > m:
                        m = f[r + 1, cc]
            v = m if m < g[r, c] else g[r, c]
            f[r, c] = v
            push = False
            if c + 1 < w and valid[r, c + 1] and f[r, c + 1] < v and f[r, c + 1] < g[r, c + 1]:
                push = True
            if not push and r + 1 < h:
                for dc in (-1, 0, 1):
                    cc = c + dc
                    if (0 <= cc < w and valid[r + 1, cc] and f[r + 1, cc] < v
                            and f[r + 1, cc] < g[r + 1, cc]):
                        push = True
                        break
            if push:
                p = r * w + c
                queue[(head + count) % n] = p
                inq[p] = 1
                count += 1
    # FIFO propagation; a pixel is in the queue at most once at a time, so n slots suffice
    while count > 0:
        p = queue[head]
        head = (head + 1) % n
        count -= 1
        inq[p] = 0
        r = p // w
        c = p - r * w
        v = f[r, c]
        for dr in (-1, 0, 1):
            rr = r + dr
            if rr < 0 or rr >= h:
                continue
            for dc in (-1, 0, 1):
                cc = c + dc
                if (dr == 0 and dc == 0) or cc < 0 or cc >= w or not valid[rr, cc]:
                    continue
                fq = f[rr, cc]
                gq = g[rr, cc]
                if fq < v and fq != gq:
                    f[rr, cc] = v if v < gq else gq
                    q = rr * w + cc
                    if not inq[q]:
                        queue[(head + count) % n] = q
                        inq[q] = 1
                        count += 1


_KERNEL_DTYPES = (np.uint8, np.uint16, np.int32, np.float32, np.float64)


def _prepare(seed: np.ndarray, mask: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray,
                                                          np.ndarray | None]:
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
    f = np.ascontiguousarray(seed, dtype=dtype).copy()
    g = np.ascontiguousarray(mask, dtype=dtype)
    nodata = None
    if dtype.kind == "f":
        nodata = np.isnan(f) | np.isnan(g)
        valid = (~nodata).view(np.uint8)
        if not nodata.any():
            nodata = None
    else:
        valid = np.ones(f.shape, dtype=np.uint8)
    return f, g, np.ascontiguousarray(valid), nodata


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
    f, g, valid, nodata = _prepare(seed, mask)
    if np.any((f > g) & valid.astype(bool)):
        raise ValueError("reconstruction by dilation needs seed <= mask everywhere")
    _hybrid_dilation(f, g, valid)
    if nodata is not None:
        f[nodata] = np.nan
    return f.astype(bool) if is_bool else f


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


def reconstruction(seed: np.ndarray, mask: np.ndarray, method: str = "dilation") -> np.ndarray:
    """Reconstruction by ``'dilation'`` or ``'erosion'`` (skimage's calling convention)."""
    if method == "dilation":
        return reconstruction_by_dilation(seed, mask)
    if method == "erosion":
        return reconstruction_by_erosion(seed, mask)
    raise ValueError(f"method must be 'dilation' or 'erosion', got {method!r}")


_EIGHT = np.ones((3, 3), dtype=bool)


def binary_reconstruction(seed: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """Binary reconstruction R_B(seed | mask): the 8-connected components of ``mask`` that
    touch ``seed``.

    Parameters
    ----------
    seed, mask : ndarray of bool (H, W)

    Returns
    -------
    ndarray of bool (H, W)
        Equal to ``skimage.morphology.reconstruction(seed & mask, mask)`` cast to bool.
    """
    mask = np.asarray(mask, dtype=bool)
    seed = np.asarray(seed, dtype=bool) & mask
    labels, n = ndimage.label(mask, structure=_EIGHT)
    if n == 0:
        return np.zeros_like(mask)
    keep = np.zeros(n + 1, dtype=bool)
    keep[labels[seed]] = True
    keep[0] = False
    return keep[labels]
