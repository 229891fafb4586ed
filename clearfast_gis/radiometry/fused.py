"""Counts to apparent temperature in one pass over a frame (the fast kernel of the stage).

:func:`clearfast_gis.radiometry.stage.apparent_temperature_frames` chains, per frame, the
blend of two calibrations in time, Eq. 1 (counts to radiance), Eq. 4 (atmosphere) and Eq. 5
(the inverse Planck table), each a whole-array numpy operation with its temporaries. The kernel
here does the same arithmetic pixel by pixel in one loop (numba, no temporaries, GIL released);
it agrees with the array chain to 1 mK (tested).
"""

from __future__ import annotations

import numba
import numpy as np


@numba.njit(cache=True, nogil=True)
def _fused(raw, gain0, offset0, gain1, offset1, w1, tau, b_air, r0, inv_dr, t_nodes,
           out):  # pragma: no cover - compiled
    h, w = raw.shape
    n = t_nodes.size - 1
    w0 = 1.0 - w1
    for i in range(h):
        for j in range(w):
            g = w0 * gain0[i, j] + w1 * gain1[i, j]
            o = w0 * offset0[i, j] + w1 * offset1[i, j]
            t = tau[i, j]
            surf = (raw[i, j] * g + o - (1.0 - t) * b_air) / t
            s = (surf - r0) * inv_dr
            if s >= 0.0 and s <= n:  # False for NaN
                k = min(int(s), n - 1)
                f = s - k
                out[i, j] = t_nodes[k] + f * (t_nodes[k + 1] - t_nodes[k])
            else:
                out[i, j] = np.nan


def apparent_frame(raw: np.ndarray, parts: list, tau: np.ndarray, b_air: float, table,
                   out: np.ndarray) -> np.ndarray:
    """Apparent temperature of one frame, in one pass.

    Parameters
    ----------
    raw : (H, W) integer or float
        Raw counts.
    parts : list of (GainOffset, weight)
        One calibration (weight 1) or two blended linearly in time (weights summing to 1).
    tau : float (H, W)
        Band transmittance of each pixel's path (1 without the atmospheric correction).
    b_air : float
        Band radiance of a blackbody at the air temperature, W m-2 sr-1 (path radiance is
        ``(1 - tau) b_air``).
    table : BandTable
        The band's inverse table (:attr:`inverse_t_k` on a uniform radiance grid).
    out : float32 (H, W)
        Written with the apparent temperature, kelvin; NaN at uncalibrated pixels and outside
        the table.

    Returns
    -------
    ``out``
    """
    c0 = parts[0][0]
    c1, w1 = parts[1] if len(parts) > 1 else (c0, 0.0)
    _fused(raw, c0.gain, c0.offset, c1.gain, c1.offset, float(w1),
           np.ascontiguousarray(tau, dtype=np.float32), float(b_air),
           table.inverse_radiance0, 1.0 / table.inverse_step, table.inverse_t_k, out)
    return out
