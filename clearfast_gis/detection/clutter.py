"""Background clutter of the mosaics: the scene noise a mine's contrast has to beat."""

from __future__ import annotations

import numpy as np
from scipy import ndimage

from clearfast_gis.parallel import thread_map

#: Scale of the local background a contrast is measured against, metres (an AP mine and its
#: ring).
CLUTTER_SCALE_M = 0.3


def background_clutter_k(stack: np.ndarray, labels: np.ndarray, pixel_size_m: float,
                         scale_m: float = CLUTTER_SCALE_M) -> float:
    """Robust 1-sigma of the local contrast of mine-free background cells, K.

    Each scan's image minus its median over a ``scale_m`` window, over the cells outside every
    anomaly; the spread is 1.4826 times the median absolute deviation; the median over scans.

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
    size = max(3, int(round(scale_m / pixel_size_m)) | 1)
    background = labels == 0

    def spread(band: np.ndarray) -> float | None:
        img = np.asarray(band, dtype=np.float64)  # one image at a time: no float64 stack
        ok = np.isfinite(img)
        if not ok.any():
            return None
        filled = np.where(ok, img, np.median(img[ok]))
        local = filled - ndimage.median_filter(filled, size=size)
        v = local[ok & background]
        return 1.4826 * np.median(np.abs(v - np.median(v))) if v.size else None

    # the median filter releases the GIL: the scans on threads, combined in scan order
    spreads = [v for v in thread_map(spread, stack) if v is not None]
    return float(np.median(spreads)) if spreads else float("nan")
