"""The matched filter's running sums over the scans (numba), behind
:func:`clearfast_gis.detection.deep.stack_match`.

One pass over a scan's normalised contrast adds its terms to every template's sums, where
the numpy form made five full-grid float64 temporaries per template and scan. The same
operations in the same order at every cell: a cell without data adds nothing (numpy added
``+-0.0`` there, which leaves a sum that starts at ``+0.0`` unchanged), so the sums are the same
to the last bit (``tests/detection/test_deep.py``).
"""

from __future__ import annotations

import numba
import numpy as np


@numba.njit(cache=True, nogil=True)
def add_scan(z, u, num, den, energy, scans):  # pragma: no cover - compiled
    """Add one scan to the matched filter's sums, in place.

    Parameters
    ----------
    z : float32 (H, W)
        The scan's contrast over its spread, noise sigmas; NaN or inf = no data.
    u : float64 (T,)
        Each template's value at the scan over the scan's spread.
    num, den : float64 (T, H, W)
        ``sum u z`` and ``sum u**2`` over the scans with data at each cell.
    energy : float64 (H, W)
        ``sum z**2``.
    scans : int32 (H, W)
        Scans with data.
    """
    h, w = z.shape
    for i in range(h):
        for j in range(w):
            v = z[i, j]
            if np.isfinite(v):
                zz = np.float64(v)
                energy[i, j] += zz * zz
                scans[i, j] += 1
    for t in range(u.size):
        ut = u[t]
        uu = ut * ut
        nt, dt = num[t], den[t]
        for i in range(h):
            for j in range(w):
                v = z[i, j]
                if np.isfinite(v):
                    nt[i, j] += ut * np.float64(v)
                    dt[i, j] += uu
