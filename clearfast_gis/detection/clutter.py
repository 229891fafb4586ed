"""Background clutter of the mosaics: the scene noise a mine's contrast has to beat."""

from __future__ import annotations

import warnings

import numpy as np

from clearfast_gis import kernels
from clearfast_gis.detection.selection import median
from clearfast_gis.detection.stack import as_scan_stack, map_scans

#: Scale of the local background a contrast is measured against, metres (an AP mine and its
#: ring).
CLUTTER_SCALE_M = 0.3

#: The detector's default cut in clutter sigmas (``ProcessOptions.threshold_snr``): the
#: stretch's cut of each filtered image is capped at this many times the image's clutter.
THRESHOLD_SNR = 4.0


def box_mean(image: np.ndarray, size: int) -> np.ndarray:
    """Mean over a ``size`` x ``size`` window centred on each cell, the image's edge values
    extended beyond it (scipy's ``uniform_filter`` with ``mode="nearest"``).

    Parameters
    ----------
    image : ndarray, shape (H, W)
        Finite values (any unit).
    size : int
        Window side, cells.

    Returns
    -------
    ndarray of float64, shape (H, W)
        In the unit of ``image``. The fast kernel (numba) gives scipy's values bit for bit.
    """
    return kernels.kernel("box_mean")(image, size)


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
    finite = np.isfinite(image)
    ok = finite if keep is None else finite & keep
    if not ok.any():
        return float("nan")
    size = max(3, int(round(scale_m / pixel_size_m)) | 1)
    img = np.asarray(image, dtype=np.float64)
    # exact medians by selection (np.median's values, without its copies); a float32 image's
    # first one selected among its float32 values
    values = image if np.asarray(image).dtype == np.float32 else img
    filled = np.where(finite, img, median(values[finite], np.float64))
    local = box_mean(filled, size)
    v = np.subtract(filled, local, out=local)[ok]
    np.abs(np.subtract(v, median(v), out=v), out=v)
    return float(1.4826 * median(v))


def background_levels(stack, labels: np.ndarray, pixel_size_m: float,
                      scale_m: float = CLUTTER_SCALE_M, clutter: bool = True
                      ) -> tuple[np.ndarray, float]:
    """The mine-free background of every scan, in one pass over the stack (band 0 of each
    scan, read scan by scan: :mod:`clearfast_gis.detection.stack`).

    Parameters
    ----------
    stack : ScanStack, or ndarray (S, H, W) or (S, B, H, W)
        Apparent temperature per scan, K or degrees C; NaN outside the footprint.
    labels : ndarray of int, shape (H, W)
        Anomaly labels (0 = background).
    pixel_size_m : float
        Cell size, m.
    clutter : bool
        Also measure the clutter (30 ms a trial scan); without it the second value is NaN.

    Returns
    -------
    median : float32 (S,)
        Median over the background cells per scan (the stack's unit; NaN without any).
    clutter : float
        Robust 1-sigma of the local contrast of the background cells, K: the median over
        scans of :func:`image_clutter_k` over the cells outside every anomaly; NaN when no
        scan has background cells.
    """
    background = labels == 0

    def one_scan(_scan: int, bands: np.ndarray) -> tuple[float, float]:
        return (np.nanmedian(bands[0][background]),
                image_clutter_k(bands[0], pixel_size_m, background, scale_m) if clutter
                else float("nan"))

    # a scan without background cells: NaN (the process's filter, so on the threads too)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=RuntimeWarning)
        per_scan = list(map_scans(one_scan, as_scan_stack(stack)))
    spreads = [v for _, v in per_scan if np.isfinite(v)]
    return (np.array([m for m, _ in per_scan]),
            float(np.median(spreads)) if spreads else float("nan"))


def background_clutter_k(stack, labels: np.ndarray, pixel_size_m: float,
                         scale_m: float = CLUTTER_SCALE_M) -> float:
    """Robust 1-sigma of the local contrast of mine-free background cells, K (NaN when no
    scan has background cells): the clutter of :func:`background_levels`, same parameters."""
    return background_levels(stack, labels, pixel_size_m, scale_m)[1]
