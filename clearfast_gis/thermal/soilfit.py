"""Soil diffusivity from a thermocouple log.

The column between the shallowest and the deepest sensor is a 1-D conduction problem with
both ends known (the two sensors' readings); the diffusivity that best predicts the
sensors in between is the soil's. Only the diffusivity matters here (no surface balance).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import scipy.sparse as sp
from scipy.interpolate import PchipInterpolator
from scipy.optimize import least_squares
from scipy.sparse.linalg import splu

from clearfast_gis.errors import InvalidInput


def soil_log_field(log: Any, name: str) -> np.ndarray:
    """Field ``name`` of a soil log (object or mapping) as a float array."""
    value = log.get(name) if isinstance(log, Mapping) else getattr(log, name, None)
    if value is None:
        raise InvalidInput("missing from the soil log", field=name)
    return np.asarray(value, dtype=float)


def conduction_between(
    alpha_m2s: float,
    time_s: np.ndarray,
    depth_m: np.ndarray,
    temp_k: np.ndarray,
    dz_m: float = 0.005,
    dt_s: float | None = None,
) -> np.ndarray:
    """Temperatures at the interior sensors predicted from the two outermost ones.

    Finite differences on a uniform grid between the first and last depth, BDF2 in time,
    initial profile a monotone cubic (PCHIP) through the first record.

    Parameters
    ----------
    alpha_m2s : float
        Soil diffusivity, m2 s-1.
    time_s : ndarray, shape (T,)
        Record times, s (increasing).
    depth_m : ndarray, shape (D,)
        Sensor depths, m (increasing, D >= 3).
    temp_k : ndarray, shape (T, D)
        Readings (any consistent unit).
    dz_m : float
        Grid spacing, m.
    dt_s : float, optional
        Step; default half the median record interval.

    Returns
    -------
    ndarray, shape (T, D - 2)
        Predicted readings of the interior sensors.
    """
    z0, z1 = depth_m[0], depth_m[-1]
    n = max(int(np.ceil((z1 - z0) / dz_m)), 4)
    z = np.linspace(z0, z1, n + 1)
    h = z[1] - z[0]
    if dt_s is None:
        dt_s = 0.5 * float(np.median(np.diff(time_s)))
    n_steps = int(np.ceil((time_s[-1] - time_s[0]) / dt_s))
    t = time_s[0] + dt_s * np.arange(n_steps + 1)
    top = np.interp(t, time_s, temp_k[:, 0])
    bot = np.interp(t, time_s, temp_k[:, -1])
    m = n - 1  # interior nodes
    lam = alpha_m2s / h**2
    lap = sp.diags([np.full(m - 1, lam), np.full(m, -2 * lam), np.full(m - 1, lam)],
                   [-1, 0, 1])
    lu = splu((sp.identity(m) * (1.5 / dt_s) - lap).tocsc())
    u = PchipInterpolator(depth_m, temp_k[0])(z[1:-1])
    u_prev = u.copy()
    states = np.empty((n_steps + 1, n + 1))
    states[0, 1:-1] = u
    rhs = np.empty(m)
    for k in range(1, n_steps + 1):
        np.multiply(2.0 * u - 0.5 * u_prev, 1.0 / dt_s, out=rhs)
        rhs[0] += lam * top[k]
        rhs[-1] += lam * bot[k]
        u_prev, u = u, lu.solve(rhs)
        states[k, 1:-1] = u
    states[:, 0] = top
    states[:, -1] = bot
    idx = np.clip(np.searchsorted(z, depth_m[1:-1]) - 1, 0, n - 1)
    w = (depth_m[1:-1] - z[idx]) / h
    at_sensors = states[:, idx] * (1 - w) + states[:, idx + 1] * w
    out = np.empty((time_s.size, depth_m.size - 2))
    for j in range(out.shape[1]):
        out[:, j] = np.interp(time_s, t, at_sensors[:, j])
    return out


def ar1_inflation(resid: np.ndarray) -> float:
    """Variance inflation ``(1 + rho) / (1 - rho)`` for lag-1 correlated residuals (T, D)."""
    r = resid - resid.mean(axis=0)
    num = float(np.sum(r[1:] * r[:-1]))
    den = float(np.sum(r * r))
    rho = np.clip(num / den, 0.0, 0.95) if den > 0 else 0.0
    return (1 + rho) / (1 - rho)


def fit_soil_diffusivity(
    soil_log: Any,
    alpha_bounds_m2s: tuple[float, float] = (1e-8, 1e-5),
) -> tuple[float, float]:
    """Soil thermal diffusivity from thermocouples at three or more depths.

    Parameters
    ----------
    soil_log : object or mapping
        ``time_s`` (T,), ``depth_m`` (D,), ``temp_c`` (T, D) (e.g. ``read_soil_log``'s
        ``SoilLog``). Records with a missing (NaN) reading are dropped.
    alpha_bounds_m2s : (float, float)
        Search range, m2 s-1.

    Returns
    -------
    alpha_m2s : float
        Best-fitting diffusivity, m2 s-1.
    sigma_m2s : float
        1-sigma uncertainty from the Jacobian, the residual variance and a lag-1
        autocorrelation correction (the residuals of a smooth log are far from independent).

    Raises
    ------
    InvalidInput
        Fewer than 3 depths, fewer than 12 complete records or a degenerate log.
    """
    t = soil_log_field(soil_log, "time_s")
    z = soil_log_field(soil_log, "depth_m")
    temp = soil_log_field(soil_log, "temp_c")
    if z.ndim != 1 or z.size < 3:
        raise InvalidInput("at least 3 sensor depths needed", field="depth_m")
    if temp.shape != (t.size, z.size):
        raise InvalidInput(f"expected shape ({t.size}, {z.size})", field="temp_c")
    order = np.argsort(z)
    z, temp = z[order], temp[:, order]
    if np.any(np.diff(z) <= 0):
        raise InvalidInput("depths must be distinct", field="depth_m")
    good = np.all(np.isfinite(temp), axis=1) & np.isfinite(t)
    t, temp = t[good], temp[good]
    keep = np.concatenate([[True], np.diff(t) > 0]) if t.size else np.zeros(0, bool)
    t, temp = t[keep], temp[keep]
    if t.size < 12:
        raise InvalidInput("fewer than 12 complete records", field="temp_c")
    observed = temp[:, 1:-1]

    def resid(p: np.ndarray) -> np.ndarray:
        return (conduction_between(10.0 ** p[0], t, z, temp) - observed).ravel()

    lo, hi = np.log10(alpha_bounds_m2s)
    grid = np.linspace(lo, hi, 7)
    costs = [np.sum(resid(np.array([g])) ** 2) for g in grid]
    start = float(np.clip(grid[int(np.argmin(costs))], lo + 1e-3, hi - 1e-3))
    sol = least_squares(resid, [start], bounds=([lo], [hi]), diff_step=1e-3, x_scale=[0.1])
    r = sol.fun.reshape(observed.shape)
    dof = max(r.size - 1, 1)
    s2 = float(np.sum(r**2)) / dof * ar1_inflation(r)
    jtj = float(sol.jac[:, 0] @ sol.jac[:, 0])
    sigma_log = np.sqrt(s2 / jtj) if jtj > 0 else np.inf
    alpha = 10.0 ** sol.x[0]
    return float(alpha), float(alpha * np.log(10.0) * sigma_log)
