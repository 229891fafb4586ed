"""Radiometric seam balancing (paper §5.3): a linear map fitted on cumulative histograms.

The paper finds ``a, b`` minimising ``sum_g [C_m(g) - C_i(a g + b)]^2`` over the overlap of the
mosaic (``C_m``) and the new frame (``C_i``). For monotone cumulative histograms this is the
least-squares line through matching quantiles, which is what is computed here: the quantiles
of the frame's overlap are regressed onto the same quantiles of the mosaic's overlap. The
result is applied to the frame before insertion. It changes temperatures, so it is an option
(off by default) whose use is recorded in the products.
"""

from __future__ import annotations

import numpy as np


def fit_linear_histogram_mapping(mosaic_overlap: np.ndarray, frame_overlap: np.ndarray,
                                 n_quantiles: int = 64, min_samples: int = 50
                                 ) -> tuple[float, float]:
    """Gain and offset ``(a, b)`` so that ``a * frame + b`` matches the mosaic's histogram.

    Parameters
    ----------
    mosaic_overlap, frame_overlap : ndarray
        Values of the mosaic and of the new frame over their common cells (any shape, same
        units, NaN ignored).
    n_quantiles : int
        Number of matched quantiles (between 2 % and 98 %).
    min_samples : int
        Below this many common finite samples the identity ``(1, 0)`` is returned.

    Returns
    -------
    a, b : float
    """
    m = np.asarray(mosaic_overlap, dtype=np.float64).ravel()
    f = np.asarray(frame_overlap, dtype=np.float64).ravel()
    ok = np.isfinite(m) & np.isfinite(f)
    if ok.sum() < min_samples:
        return 1.0, 0.0
    q = np.linspace(0.02, 0.98, n_quantiles)
    qm = np.quantile(m[ok], q)
    qf = np.quantile(f[ok], q)
    if np.ptp(qf) <= 1e-9:
        return 1.0, float(np.median(m[ok]) - np.median(f[ok]))
    a, b = np.polyfit(qf, qm, 1)
    return float(a), float(b)
