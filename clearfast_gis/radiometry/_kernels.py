"""The radiometry's fast kernels (``--kernels fast``, :mod:`clearfast_gis.kernels`).

- :func:`inverse_planck` (the registry's ``inverse_planck``): Eq. 5 on the radiance-uniform
  inverse table of :class:`~clearfast_gis.radiometry.table.BandTable`, by index arithmetic
  and linear interpolation (numba); :func:`_uniform_hermite` evaluates the forward table.
- :func:`apparent_frame` (``apparent_frame``): counts to apparent temperature in one pass over
  a frame. :func:`clearfast_gis.radiometry.stage.apparent_temperature_frames` chains, per
  frame, the blend of two calibrations in time, Eq. 1 (counts to radiance), Eq. 4
  (atmosphere) and Eq. 5 (the inverse Planck table); the kernel does the same arithmetic
  pixel by pixel in one loop (numba, no temporaries, GIL released); it agrees with the array
  chain to 1 mK (tested).

The references are in :mod:`clearfast_gis.radiometry._reference`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numba
import numpy as np

if TYPE_CHECKING:
    from clearfast_gis.radiometry.table import BandTable


@numba.njit(cache=True, nogil=True)
def _uniform_linear(x, x0, inv_dx, y, out):
    """out[i] = y interpolated linearly at x[i] on the uniform grid x0 + k / inv_dx; NaN
    outside the grid or for NaN input."""
    n = y.size - 1
    for i in range(x.size):
        s = (np.float64(x[i]) - x0) * inv_dx
        if s >= 0.0 and s <= n:
            j = min(int(s), n - 1)
            f = s - j
            out[i] = y[j] + f * (y[j + 1] - y[j])
        else:
            out[i] = np.nan


@numba.njit(cache=True, nogil=True)
def _uniform_hermite(x, x0, dx, y, dy, out):
    """Cubic Hermite interpolation of (y, dy/dx) on a uniform grid; NaN outside."""
    n = y.size - 1
    inv_dx = 1.0 / dx
    for i in range(x.size):
        s = (np.float64(x[i]) - x0) * inv_dx
        if s >= 0.0 and s <= n:
            j = min(int(s), n - 1)
            t = s - j
            t2 = t * t
            t3 = t2 * t
            h00 = 2.0 * t3 - 3.0 * t2 + 1.0
            h10 = t3 - 2.0 * t2 + t
            h01 = -2.0 * t3 + 3.0 * t2
            h11 = t3 - t2
            out[i] = h00 * y[j] + h10 * dx * dy[j] + h01 * y[j + 1] + h11 * dx * dy[j + 1]
        else:
            out[i] = np.nan


@numba.njit(cache=True, nogil=True)
def _fused(raw, gain0, offset0, gain1, offset1, w1, tau, b_air, r0, inv_dr, t_nodes,
           out):  # pragma: no cover - compiled
    h, w = raw.shape
    n = t_nodes.size - 1
    w0 = 1.0 - w1
    s_row = np.empty(w, dtype=np.float64)  # table coordinate of each pixel of a row
    for i in range(h):
        # the arithmetic of a row first (no branch, so the loop vectorises), then the table
        for j in range(w):
            g = w0 * gain0[i, j] + w1 * gain1[i, j]
            o = w0 * offset0[i, j] + w1 * offset1[i, j]
            t = tau[i, j]
            surf = (raw[i, j] * g + o - (1.0 - t) * b_air) / t
            s_row[j] = (surf - r0) * inv_dr
        for j in range(w):
            s = s_row[j]
            if s >= 0.0 and s <= n:  # False for NaN
                k = min(int(s), n - 1)
                f = s - k
                out[i, j] = t_nodes[k] + f * (t_nodes[k + 1] - t_nodes[k])
            else:
                out[i, j] = np.nan


def inverse_planck(table: BandTable, r: np.ndarray, dtype=np.float32) -> np.ndarray:
    """:meth:`~clearfast_gis.radiometry.table.BandTable.temperature` on the fast kernels
    (radiance-uniform table, numba)."""
    if r.dtype not in (np.float32, np.float64):
        r = r.astype(np.float64)
    flat = np.ascontiguousarray(r).ravel()
    out = np.empty(flat.shape, dtype=dtype)
    _uniform_linear(flat, table.inverse_radiance0, 1.0 / table.inverse_step,
                    table.inverse_t_k, out)
    return out.reshape(r.shape)


def apparent_frame(raw: np.ndarray, parts: list, tau, t_air_k: float, b_air: float, table,
                    out: np.ndarray) -> None:
    """One frame's apparent temperature (kelvin) into ``out`` on the fast kernels:
    calibration (``parts``: weighted gain/offset of the calibration events), atmosphere
    (transmittance ``tau``, scalar or (H, W); air radiance ``b_air``) and inverse Planck fused
    per pixel (the registry's ``apparent_frame``, called by
    :func:`clearfast_gis.radiometry.stage.apparent_temperature_frames`).

    ``raw`` (H, W) raw counts; ``parts`` one calibration (weight 1) or two blended linearly in
    time (weights summing to 1), as (GainOffset, weight); ``b_air`` band radiance of a
    blackbody at the air temperature, W m-2 sr-1 (path radiance ``(1 - tau) b_air``);
    ``table`` the band's :class:`~clearfast_gis.radiometry.table.BandTable`; ``out`` float32
    (H, W), written with the apparent temperature, kelvin (NaN at uncalibrated pixels and
    outside the table); ``t_air_k`` is used by the reference only.
    """
    tau_map = np.broadcast_to(np.asarray(tau, dtype=np.float32), raw.shape)
    c0 = parts[0][0]
    c1, w1 = parts[1] if len(parts) > 1 else (c0, 0.0)
    _fused(raw, c0.gain, c0.offset, c1.gain, c1.offset, float(w1),
           np.ascontiguousarray(tau_map, dtype=np.float32), float(b_air),
           table.inverse_radiance0, 1.0 / table.inverse_step, table.inverse_t_k, out)
