"""The detector's reference kernels (scikit-image), for ``--kernels reference``.

The registry's (:mod:`clearfast_gis.kernels`) references of the fast kernels of
:mod:`clearfast_gis.detection._kernels`, under the same names.

Same conventions as :mod:`clearfast_gis.detection.morphology`: NaN (no-data) pixels are
ignored by the erosion/dilation and are walls for the reconstruction; pixels outside the image
are ignored (``mode="max"`` / ``"min"``).
"""

from __future__ import annotations

import numpy as np
from skimage.morphology import dilation, disk, erosion, reconstruction

from clearfast_gis.detection.morphology import disk_radius_px


def _walled(seed: np.ndarray, mask: np.ndarray, nodata: np.ndarray, wall: float
            ) -> tuple[np.ndarray, np.ndarray]:
    """Seed and mask with the no-data pixels set to ``wall`` (the value that propagates
    nothing)."""
    return np.where(nodata, wall, seed), np.where(nodata, wall, mask)


def _hat(image: np.ndarray, d1_px: float, dark: bool) -> np.ndarray:
    """White (``dark=False``: ``f - R(f eroded | f)``) or black (``R*(f dilated | f) - f``)
    top-hat by reconstruction with scikit-image; float (H, W), NaN on no-data."""
    f = np.asarray(image)
    f = f if f.dtype.kind == "f" else f.astype(np.float32)
    nodata = np.isnan(f)
    footprint = disk(disk_radius_px(d1_px))
    if dark:
        seed0 = dilation(np.where(nodata, -np.inf, f), footprint, mode="min")
        wall = float(np.nanmax(f)) + 1.0 if not nodata.all() else 0.0
    else:
        seed0 = erosion(np.where(nodata, np.inf, f), footprint, mode="max")
        wall = float(np.nanmin(f)) - 1.0 if not nodata.all() else 0.0
    seed, mask = _walled(seed0, f, nodata, wall)
    rec = reconstruction(seed, mask, method="erosion" if dark else "dilation").astype(f.dtype)
    out = rec - f if dark else f - rec
    out[nodata] = np.nan
    return out


def top_hat_by_reconstruction(image: np.ndarray, d1_px: float) -> np.ndarray:
    """``f - R_B(f eroded by D1 | f)`` with :func:`skimage.morphology.erosion` and
    :func:`skimage.morphology.reconstruction`; float (H, W), NaN on no-data."""
    return _hat(image, d1_px, dark=False)


def bottom_hat_by_reconstruction(image: np.ndarray, d1_px: float) -> np.ndarray:
    """``R*_B(f dilated by D1 | f) - f`` (dual of :func:`top_hat_by_reconstruction`)."""
    return _hat(image, d1_px, dark=True)


def binary_opening_by_reconstruction(binary: np.ndarray, d2_px: float) -> np.ndarray:
    """Binary opening by reconstruction with scikit-image: components of ``binary`` that
    contain a disk of diameter ``d2_px``, whole (8-connectivity); bool (H, W)."""
    g = np.asarray(binary, dtype=bool)
    if not g.any():
        return g.copy()
    seed = erosion(g.view(np.uint8), disk(disk_radius_px(d2_px)), mode="max")
    return reconstruction(seed, g.view(np.uint8), method="dilation",
                          footprint=np.ones((3, 3), bool)).astype(bool)


def order_statistics(values: np.ndarray, ranks) -> np.ndarray:
    """:func:`clearfast_gis.detection._kernels.order_statistics` with ``np.partition``."""
    v = np.asarray(values).ravel()
    r = np.asarray(ranks, dtype=np.int64).ravel()
    return np.partition(v, r)[r]


def box_mean(image: np.ndarray, size: int) -> np.ndarray:
    """:func:`clearfast_gis.detection._kernels.box_mean` with scipy's ``uniform_filter``."""
    from scipy import ndimage

    return ndimage.uniform_filter(np.asarray(image, dtype=np.float64), size=int(size),
                                  mode="nearest")
