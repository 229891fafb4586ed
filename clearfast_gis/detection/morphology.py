"""Disk erosion/dilation and top-hat / bottom-hat by reconstruction (paper §4.1).

A disk of diameter D pixels is ``skimage.morphology.disk(r)`` with ``r = round((D - 1) / 2)``
(it spans ``2 r + 1`` pixels); that exact footprint is the OpenCV kernel, so
``cv2.erode`` gives the same values as ``skimage.morphology.erosion`` (pixels outside the image
are ignored by both). Float images with ``r >= CHORD_MIN_RADIUS_PX`` are eroded by the disk's
chords instead (:mod:`clearfast_gis.detection._chords`: the same values as ``cv2.erode``,
four to five times faster for the detector's D1 of 25 pixels). NaN (no-data) pixels are
ignored by the erosion/dilation (they are set to +inf / -inf first) and are walls for the
reconstruction; they are NaN in the results.
"""

from __future__ import annotations

import functools

import cv2
import numpy as np
from skimage.morphology import disk

from clearfast_gis import kernels
from clearfast_gis.detection._chords import chord_half_widths, erode_chords, segment_schedule

__all__ = ["binary_opening_by_reconstruction", "bottom_hat_by_reconstruction",
           "disk_footprint", "disk_radius_px", "erode_disk", "dilate_disk",
           "top_hat_by_reconstruction"]


def disk_radius_px(diameter_px: float) -> int:
    """Radius r (pixels) of the digital disk of diameter ``diameter_px``: ``round((D-1)/2)``."""
    if not np.isfinite(diameter_px) or diameter_px < 1:
        raise ValueError(f"disk diameter must be >= 1 pixel, got {diameter_px}")
    return int(np.floor((float(diameter_px) - 1.0) / 2.0 + 0.5))


def disk_footprint(diameter_px: float) -> np.ndarray:
    """The disk structuring element of diameter ``diameter_px`` as uint8 (2r+1, 2r+1)."""
    return disk(disk_radius_px(diameter_px)).astype(np.uint8)


CHORD_MIN_RADIUS_PX = 3
"""Float images are eroded by chords for disks of this radius and larger (OpenCV's loop over
the disk's cells is as fast below it)."""


@functools.lru_cache(maxsize=32)
def _chords(diameter_px: float) -> tuple[np.ndarray, np.ndarray] | None:
    """(half-widths, schedule) of the disk of ``diameter_px`` for :func:`erode_chords`, or
    None below :data:`CHORD_MIN_RADIUS_PX`."""
    if disk_radius_px(diameter_px) < CHORD_MIN_RADIUS_PX:
        return None
    half_widths = chord_half_widths(disk_footprint(diameter_px))
    return None if half_widths is None else (half_widths, segment_schedule(half_widths))


def _erode_float(src: np.ndarray, diameter_px: float, dilate: bool) -> np.ndarray:
    """Erosion (or dilation) of a float image without NaN by the disk, pixels outside the
    image ignored: by chords, or ``cv2.erode`` / ``cv2.dilate`` for small disks."""
    chords = _chords(float(diameter_px))
    if chords is None:
        op = cv2.dilate if dilate else cv2.erode
        return op(src, disk_footprint(diameter_px), borderType=cv2.BORDER_CONSTANT,
                  borderValue=_border_value(src.dtype, high=not dilate))
    # max(f) = -min(-f), exactly
    f = np.negative(src) if dilate else np.ascontiguousarray(src)
    out = np.empty(f.shape, dtype=f.dtype)
    erode_chords(f, *chords, out)
    return np.negative(out, out=out) if dilate else out


def _as_cv(image: np.ndarray) -> np.ndarray:
    image = np.asarray(image)
    if image.dtype == np.bool_:
        return image.view(np.uint8)
    if image.dtype in (np.uint8, np.uint16, np.int16, np.float32, np.float64):
        return image
    return image.astype(np.float64)


def erode_disk(image: np.ndarray, diameter_px: float) -> np.ndarray:
    """Grey-scale (or binary) erosion by a disk; NaN pixels are ignored and stay NaN.

    Parameters
    ----------
    image : ndarray (H, W)
        bool, uint8, uint16, float32 or float64.
    diameter_px : float
        Disk diameter in pixels.
    """
    return _disk_filter(image, diameter_px, dilate=False)


def dilate_disk(image: np.ndarray, diameter_px: float) -> np.ndarray:
    """Grey-scale (or binary) dilation by a disk; NaN pixels are ignored and stay NaN."""
    return _disk_filter(image, diameter_px, dilate=True)


def _disk_filter(image: np.ndarray, diameter_px: float, dilate: bool) -> np.ndarray:
    """Erosion (``dilate`` False) or dilation by a disk: float images by the disk's chords,
    integer and binary ones by OpenCV; NaN pixels ignored (the neutral value in their place)
    and NaN again in the result."""
    src = _as_cv(image)
    nan = None
    if src.dtype.kind == "f":
        nan = np.isnan(src)
        if nan.any():
            src = np.where(nan, -np.inf if dilate else np.inf, src).astype(src.dtype)
        else:
            nan = None
    if src.dtype.kind == "f":
        out = _erode_float(src, diameter_px, dilate=dilate)
    else:
        op = cv2.dilate if dilate else cv2.erode
        out = op(src, disk_footprint(diameter_px), borderType=cv2.BORDER_CONSTANT,
                 borderValue=_border_value(src.dtype, high=not dilate))
    if nan is not None:
        out[nan] = np.nan
    return out.astype(bool) if np.asarray(image).dtype == np.bool_ else out


def _border_value(dtype: np.dtype, high: bool) -> float:
    if dtype.kind == "f":
        return float(np.inf if high else -np.inf)
    info = np.iinfo(dtype)
    return float(info.max if high else info.min)


def top_hat_by_reconstruction(image: np.ndarray, d1_px: float) -> np.ndarray:
    """White top-hat by reconstruction ``t = f - r_B(f o D1 | f)`` (paper §4.1).

    Bright structures that a disk of diameter ``d1_px`` does not fit into keep their contrast
    over their surroundings; larger bright regions and the background become 0.

    Parameters
    ----------
    image : ndarray (H, W) float32 or float64
        Apparent temperature (K or degrees C) or grey levels; NaN = no-data.
    d1_px : float
        Disk diameter D1 in pixels (larger than the largest expected object).

    Returns
    -------
    ndarray (H, W), same float dtype, >= 0, NaN on no-data.

    Notes
    -----
    The reconstruction of the eroded image equals the reconstruction of the opening (the
    erosion lies between the opening's erosion and the image), so the dilation of the opening
    is skipped.
    """
    f = np.asarray(image)
    if f.dtype.kind != "f":
        f = f.astype(np.float32)
    return kernels.kernel("top_hat_by_reconstruction")(f, d1_px)


def bottom_hat_by_reconstruction(image: np.ndarray, d1_px: float) -> np.ndarray:
    """Black top-hat by reconstruction ``b = r*_B(f . D1 | f) - f`` (dual of the top-hat).

    Dark (cold) structures smaller than the disk come out positive. Same parameters and
    conventions as :func:`top_hat_by_reconstruction`.
    """
    f = np.asarray(image)
    if f.dtype.kind != "f":
        f = f.astype(np.float32)
    return kernels.kernel("bottom_hat_by_reconstruction")(f, d1_px)


def binary_opening_by_reconstruction(binary: np.ndarray, d2_px: float) -> np.ndarray:
    """Binary opening by reconstruction ``O = R_B(G o D2 | G)`` (paper §4.3).

    Keeps the 8-connected components of ``binary`` that contain a disk of diameter ``d2_px``,
    whole.

    Parameters
    ----------
    binary : ndarray of bool (H, W)
    d2_px : float
        Disk diameter D2 in pixels (D2 < D1).
    """
    g = np.asarray(binary, dtype=bool)
    if not g.any():
        return g.copy()
    return kernels.kernel("binary_opening_by_reconstruction")(g, d2_px)


