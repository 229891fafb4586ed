"""Histogram stretching and thresholding of filtered images (paper §4.2)."""

from __future__ import annotations

import numpy as np

from clearfast_gis.detection.selection import order_statistics

__all__ = ["inverted_cdf_rank", "stretch_limits", "stretch", "stretch_threshold"]


def stretch_limits(image: np.ndarray, epsilon: float = 0.01) -> tuple[float, float]:
    """The stretch limits I1, I2: where the normalised cumulative histogram reaches
    ``epsilon`` and ``1 - epsilon``.

    Parameters
    ----------
    image : ndarray
        Any shape; NaN pixels are ignored.
    epsilon : float
        Fraction of the pixels clipped at each end, 0 <= epsilon < 0.5.

    Returns
    -------
    (I1, I2) : tuple of float
        The ``epsilon`` and ``1 - epsilon`` quantiles (lower empirical value, i.e. the smallest
        grey level whose cumulative frequency reaches the fraction). (nan, nan) if the image has
        no valid pixel.
    """
    if not 0.0 <= epsilon < 0.5:
        raise ValueError(f"epsilon must be in [0, 0.5), got {epsilon}")
    values = np.asarray(image)
    if values.dtype not in (np.float32, np.float64):
        values = values.astype(np.float64)
    values = values.ravel()
    values = values[np.isfinite(values)]
    if values.size == 0:
        return float("nan"), float("nan")
    # select the two ranks (no float64 copy, no full sort)
    lo, hi = order_statistics(values, [inverted_cdf_rank(values.size, epsilon),
                                       inverted_cdf_rank(values.size, 1.0 - epsilon)])
    return float(lo), float(hi)


def inverted_cdf_rank(n: int, q: float) -> int:
    """Rank (0-based, in sorted order) of the ``q`` quantile of ``n`` values by the inverted
    empirical CDF: the smallest value whose cumulative frequency reaches ``q``. The
    arithmetic of ``np.quantile(..., method="inverted_cdf")``, so the value is the same."""
    index = n * q - 1.0
    below = np.floor(index)
    rank = below + 1.0 if index - below > 0.0 else below
    return int(min(max(rank, 0.0), n - 1))


def stretch(image: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """The mapping F_m: 0 below ``lo``, 1 above ``hi``, linear between (float32, NaN kept).

    A degenerate range (``hi <= lo``) maps values above ``lo`` to 1 and the rest to 0.
    """
    f = np.asarray(image, dtype=np.float32)
    if not hi > lo:
        out = (f > lo).astype(np.float32)
        out[np.isnan(f)] = np.nan
        return out
    return np.clip((f - np.float32(lo)) / np.float32(hi - lo), 0.0, 1.0)


def stretch_threshold(image: np.ndarray, epsilon: float = 0.01,
                      threshold: float = 0.5, ceiling: float | None = None) -> np.ndarray:
    """G = T(F_m(t, I1, I2), threshold): stretch at the epsilon percentiles and threshold.

    The stretch puts the cut at ``I1 + threshold (I2 - I1)`` in the image's units. On a site
    whose brightest 1 % are objects far stronger than a buried mine (markers, vegetation,
    surface-laid mines) that cut can lie above a mine's contrast while the mine stands well
    above the noise; ``ceiling`` caps the cut (a pixel is then set above
    ``min(cut, ceiling)``).

    Parameters
    ----------
    image : ndarray (H, W)
        A top-hat or bottom-hat image (>= 0), NaN = no-data.
    epsilon : float
        Stretch fraction (paper's epsilon).
    threshold : float
        Threshold on the stretched image (the paper fixes 0.5), strict: a pixel is set when
        its stretched value is above the threshold.
    ceiling : float, optional
        Highest cut in the image's units (e.g. a multiple of the image's noise, K); None: the
        stretch alone (the paper).

    Returns
    -------
    ndarray of bool (H, W); False on no-data and everywhere when the image is constant.
    """
    lo, hi = stretch_limits(image, epsilon)
    f = np.asarray(image, dtype=np.float32)
    if not np.isfinite(lo):
        return np.zeros(f.shape, dtype=bool)
    with np.errstate(invalid="ignore"):
        if ceiling is not None and np.isfinite(ceiling) and ceiling < lo + threshold * (hi - lo):
            return f > np.float32(ceiling)
        return stretch(f, lo, hi) > threshold
