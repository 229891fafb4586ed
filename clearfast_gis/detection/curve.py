"""Does a suspect's contrast curve follow a buried mine's diurnal curve on that day?

A mine, a worse conductor than the soil (TNT: thermal inertia ~720 J m-2 K-1 s-1/2), warms
faster than its surroundings by day and cools faster at night: its contrast peaks in the
late morning to the afternoon (later the deeper it lies) and is lowest at night. A stone
(granite ~2400) or metal conducts and stores heat: its contrast runs the other way, lowest
around midday and highest at night. Where the site soil stores more heat than sand (moist
clay, loam) a stone's grey-body emissivity adds a steady offset to its apparent
temperature, so it is warm at every scan; only the *shape* of its curve gives it away.

The reference is the survey's own thermal model (:func:`clearfast_gis.thermal.daycontrast.
day_contrast`: the logged weather, the soil fitted to the thermocouples) run for a 10.4 cm
TNT cylinder at 0-5 cm (:data:`MAX_MATCH_DEPTH_M`). The match is the Pearson correlation
of the measured curve with the modelled one, each less its mean (an emissivity offset does
not count), taken at the best-matching depth: about +1 for a mine, negative for a stone or
metal object (-0.7 to -0.8 for a surface stone in the model of a clear day in clay, loam or sand).
Deeper reference curves are left out: at 8-10 cm the mine's contrast is a few hundredths
of a kelvin and lags by hours, and a stone's curve correlates with some lagged curve.
"""

from __future__ import annotations

import math

import numpy as np

MIN_SCANS = 4
"""Fewest scans with a finite contrast for a match (below: NaN)."""

MAX_MATCH_DEPTH_M = 0.05
"""Deepest reference mine a curve is matched against, m (the depths the survey must find)."""


def match_curves(depths_m: np.ndarray, curves_k: np.ndarray) -> np.ndarray:
    """The reference curves (D, S) of depths at most :data:`MAX_MATCH_DEPTH_M`, K."""
    keep = np.asarray(depths_m, dtype=float) <= MAX_MATCH_DEPTH_M + 1e-9
    return np.asarray(curves_k, dtype=float)[keep]


def _correlations(contrast_k: np.ndarray, model_curves_k: np.ndarray
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Pearson correlation of the measured curve with each modelled curve.

    Returns ``(r, valid, ok)``: ``r`` (V,) over the ``valid`` (D,) curves that are not flat,
    ``ok`` (S,) the scans used; None with fewer than :data:`MIN_SCANS` finite scans or a
    flat curve.
    """
    c = np.asarray(contrast_k, dtype=float)
    m = np.atleast_2d(np.asarray(model_curves_k, dtype=float))
    if m.shape[-1] != c.size:
        raise ValueError(f"contrast has {c.size} scans, the model curves {m.shape[-1]}")
    ok = np.isfinite(c) & np.isfinite(m).all(axis=0)
    if ok.sum() < MIN_SCANS:
        return None
    x = c[ok] - c[ok].mean()
    y = m[:, ok] - m[:, ok].mean(axis=1, keepdims=True)
    norm = np.sqrt(np.sum(x * x) * np.sum(y * y, axis=1))
    valid = norm > 0
    if not valid.any():
        return None
    return (y[valid] @ x) / norm[valid], valid, ok


def mine_curve_match(contrast_k: np.ndarray, model_curves_k: np.ndarray) -> float:
    """Best correlation of a measured contrast curve with the modelled mine curves.

    Parameters
    ----------
    contrast_k : ndarray, shape (S,)
        Measured contrast (centre minus background ring) per scan, K; NaN = not seen.
    model_curves_k : ndarray, shape (D, S)
        Modelled contrast of the reference mine at D depths at the same scan times, K.

    Returns
    -------
    float
        The largest Pearson correlation over the D depths, in [-1, 1]; NaN with fewer than
        :data:`MIN_SCANS` finite scans or a flat curve.

    Examples
    --------
    >>> import numpy as np
    >>> mine = np.array([[-0.5, -0.3, 0.8, 0.4, -0.2, -0.4]])
    >>> round(mine_curve_match(0.5 * mine[0] + 0.01, mine), 3)
    1.0
    >>> stone = np.array([1.9, 1.5, -0.1, 0.8, 1.4, 1.7])
    >>> mine_curve_match(stone, mine) < -0.5
    True
    """
    corr = _correlations(contrast_k, model_curves_k)
    if corr is None:
        return math.nan
    return float(np.clip(corr[0].max(), -1.0, 1.0))


def mine_curve_level(contrast_k: np.ndarray, model_curves_k: np.ndarray) -> float:
    """Where a measured curve sits against the best-matching modelled mine curve.

    The measured curve is fitted as ``a m + b`` to the modelled mine curve ``m`` of the depth
    that :func:`mine_curve_match` picks (least squares over the scans seen); the level is the
    offset ``b`` in units of the fitted swing ``a (max m - min m)``. A mine's contrast is the
    model's, warm by day and cool at night: a level near 0 (a surface-laid mine's emissivity
    offset moves it by a few tenths). A bare-soil bay at the edge of a grass patch, warm
    against the cooler leaves around it at every scan and warmest in the afternoon, follows
    the shape of the mine's curve but sits about one swing above it: warm at night, when a
    mine is cool.

    Parameters
    ----------
    contrast_k : ndarray, shape (S,)
        Measured contrast per scan, K; NaN = not seen.
    model_curves_k : ndarray, shape (D, S)
        Modelled contrast of the reference mine at D depths at the same scan times, K.

    Returns
    -------
    float
        ``b / (a (max m - min m))``, dimensionless; NaN when the match is undefined or the
        curve does not follow the model (best correlation <= 0).

    Examples
    --------
    >>> import numpy as np
    >>> mine = np.array([[-0.5, -0.3, 0.8, 0.4, -0.2, -0.4]])
    >>> abs(mine_curve_level(0.5 * mine[0], mine)) < 1e-9
    True
    >>> round(mine_curve_level(0.5 * mine[0] + 0.65, mine), 3)
    1.0
    """
    corr = _correlations(contrast_k, model_curves_k)
    if corr is None or corr[0].max() <= 0:
        return math.nan
    r, valid, ok = corr
    m = np.atleast_2d(np.asarray(model_curves_k, dtype=float))[valid][int(np.argmax(r))][ok]
    c = np.asarray(contrast_k, dtype=float)[ok]
    dm = m - m.mean()
    a = float(dm @ (c - c.mean())) / float(dm @ dm)
    b = c.mean() - a * m.mean()
    swing = a * (m.max() - m.min())
    return float(b / swing) if swing > 0 else math.nan
