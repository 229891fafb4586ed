"""Background clutter of the mosaics: the scene noise a mine's contrast has to beat."""

from __future__ import annotations

import numpy as np
from scipy import ndimage

from clearfast_gis.parallel import thread_map

#: Scale of the local background a contrast is measured against, metres (an AP mine and its
#: ring).
CLUTTER_SCALE_M = 0.3

#: The detector's default cut in clutter sigmas (``ProcessOptions.threshold_snr``): the
#: stretch's cut of each filtered image is capped at this many times the image's clutter.
THRESHOLD_SNR = 4.0


def image_clutter_k(image: np.ndarray, pixel_size_m: float, keep: np.ndarray | None = None,
                    scale_m: float = CLUTTER_SCALE_M) -> float:
    """Robust 1-sigma of the local contrast of one image, K.

    The image minus its mean over a ``scale_m`` square window (no-data filled with the
    image's median); the spread is 1.4826 times the median absolute deviation over the cells
    with data (and ``keep``): objects, a few per cent of the cells, do not move it.

    Parameters
    ----------
    image : ndarray, shape (H, W)
        Apparent temperature, K or degrees C; NaN = no data.
    pixel_size_m : float
        Cell size, m.
    keep : ndarray of bool, shape (H, W), optional
        Cells to measure (default: all with data).

    Returns
    -------
    float
        NaN when no cell is measured.
    """
    img = np.asarray(image, dtype=np.float64)
    ok = np.isfinite(img) if keep is None else np.isfinite(img) & keep
    if not ok.any():
        return float("nan")
    size = max(3, int(round(scale_m / pixel_size_m)) | 1)
    filled = np.where(np.isfinite(img), img, np.median(img[np.isfinite(img)]))
    v = (filled - ndimage.uniform_filter(filled, size=size, mode="nearest"))[ok]
    return float(1.4826 * np.median(np.abs(v - np.median(v))))


def background_clutter_k(stack: np.ndarray, labels: np.ndarray, pixel_size_m: float,
                         scale_m: float = CLUTTER_SCALE_M) -> float:
    """Robust 1-sigma of the local contrast of mine-free background cells, K: the median
    over scans of :func:`image_clutter_k` over the cells outside every anomaly.

    Parameters
    ----------
    stack : ndarray, shape (S, H, W)
        Apparent temperature per scan (one band), K or degrees C; NaN outside the footprint.
    labels : ndarray of int, shape (H, W)
        Anomaly labels (0 = background).
    pixel_size_m : float
        Cell size, m.

    Returns
    -------
    float
        NaN when no scan has background cells.
    """
    background = labels == 0
    # the box filter releases the GIL: the scans on threads, combined in scan order
    spreads = [v for v in thread_map(
        lambda band: image_clutter_k(band, pixel_size_m, background, scale_m), stack)
        if np.isfinite(v)]
    return float(np.median(spreads)) if spreads else float("nan")
