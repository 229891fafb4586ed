"""The heat solver's fast kernels (``--kernels fast``, :mod:`clearfast_gis.kernels`).

:func:`heat_equation` is the registry's ``heat_equation``:
:func:`clearfast_gis.thermal.solver.run` on a band Cholesky factor with the whole time loop
compiled (:func:`march`, GIL released); its reference, scipy's sparse LU with the time loop in
Python, is :mod:`clearfast_gis.thermal._reference`.

Cholesky factorisation and solves of symmetric positive-definite band matrices (numba).

Storage is the lower band by columns: ``band[j, d] = A[j + d, j]`` for ``d = 0..p``, shape
(n, p + 1), ``p`` the half-bandwidth; entries past the end of the matrix (``j + d >= n``) are
ignored. It is the transpose of LAPACK's lower band layout (``scipy.linalg.cholesky_banded``
with ``lower=True`` takes ``band.T``).

:func:`cholesky` returns the factor ``L`` (``A = L L^T``) in the same storage. For repeated
solves, :func:`pack` rearranges it so that each substitution step reads one contiguous row
(the row of ``L`` left of the diagonal, scaled by ``1 / L[j, j]``, for the forward sweep; the
column below the diagonal, scaled alike, for the backward sweep), and :func:`solve_padded`
works on a zero-padded vector so that the inner loops have a fixed length and no bounds
cases. All kernels release the GIL.

:func:`march` is the heat solver's whole time loop on such a factor. It lives here, next to
:func:`solve_padded`, because numba's on-disk cache is invalidated per source file: a compiled
caller in another module would keep its copy of the solve after an edit here.
"""

from __future__ import annotations

import numba
import numpy as np

from clearfast_gis.thermal.moisture import (
    LATENT_HEAT_JKG,
    MAGNUS_A_HPA,
    MAGNUS_B,
    MAGNUS_C_C,
)
from clearfast_gis.thermal.solver import (
    SolverResult,
    _band,
    _initial,
    _latent_arrays,
    _network,
    _step_terms,
)
from clearfast_gis.units import STEFAN_BOLTZMANN, ZERO_CELSIUS_K


@numba.njit(cache=True, nogil=True)
def cholesky(band):  # pragma: no cover - compiled
    """Band Cholesky factor ``L`` of an SPD matrix, ``A = L L^T``.

    Parameters
    ----------
    band : ndarray, shape (n, p + 1)
        Lower band of ``A`` by columns, ``band[j, d] = A[j + d, j]``.

    Returns
    -------
    ndarray, shape (n, p + 1)
        ``L`` in the same storage (``L[j + d, j]``); entries past the matrix are zero.

    Raises
    ------
    ValueError
        A pivot is not positive (the matrix is not positive definite).
    """
    n, w = band.shape
    p = w - 1
    low = band.copy()
    for j in range(n):
        pivot = low[j, 0]
        if not pivot > 0.0:
            raise ValueError("band matrix is not positive definite")
        ljj = np.sqrt(pivot)
        low[j, 0] = ljj
        inv = 1.0 / ljj
        m = min(p, n - 1 - j)
        for d in range(1, m + 1):
            low[j, d] *= inv
        # right-looking update of the trailing block: A[j + d2, j + d1] -= L[j+d2, j] L[j+d1, j]
        for d1 in range(1, m + 1):
            a = low[j, d1]
            col = low[j + d1]
            for d2 in range(d1, m + 1):
                col[d2 - d1] -= low[j, d2] * a
    for j in range(max(n - p, 0), n):
        for d in range(n - j, p + 1):
            low[j, d] = 0.0
    return low


@numba.njit(cache=True, nogil=True)
def pack(low):  # pragma: no cover - compiled
    """Rearrange a band Cholesky factor for :func:`solve_padded`.

    Parameters
    ----------
    low : ndarray, shape (n, p + 1)
        Factor from :func:`cholesky`.

    Returns
    -------
    ndarray, shape (n, 2 p + 1)
        Row ``j``: ``L[j, j - p + e] / L[j, j]`` for ``e = 0..p-1`` (zero before the first
        column), ``1 / L[j, j]``, then ``L[j + d, j] / L[j, j]`` for ``d = 1..p`` (zero past
        the last row).
    """
    n, w = low.shape
    p = w - 1
    packed = np.zeros((n, 2 * p + 1))
    for j in range(n):
        inv = 1.0 / low[j, 0]
        packed[j, p] = inv
        for d in range(1, p + 1):
            if j + d < n:
                packed[j, p + d] = low[j, d] * inv
            if j >= d:
                packed[j, p - d] = low[j - d, d] * inv
    return packed


@numba.njit(cache=True, nogil=True)
def solve_padded(packed, b, xp):  # pragma: no cover - compiled
    """Solve ``L L^T x = b`` into a zero-padded vector.

    Parameters
    ----------
    packed : ndarray, shape (n, 2 p + 1)
        Factor from :func:`pack`.
    b : ndarray, shape (n,)
        Right-hand side (not modified).
    xp : ndarray, shape (n + 2 p,)
        Receives ``x`` in ``xp[p:p + n]``; ``xp[:p]`` and ``xp[p + n:]`` must be zero (they
        are read, never written).
    """
    n, w = packed.shape
    p = (w - 1) // 2
    if p == 0:  # diagonal matrix
        for j in range(n):
            xp[j] = b[j] * packed[j, 0] * packed[j, 0]
        return
    # forward: y[j] = b[j] / L[j, j] - sum_k L[j, k] / L[j, j] y[k], the neighbour k = j - 1
    # last (it is the value just computed, kept in a register)
    prev = 0.0
    for j in range(n):
        row = packed[j, : p - 1]
        win = xp[j: j + p - 1]
        s = 0.0
        for e in range(p - 1):
            s += row[e] * win[e]
        prev = (b[j] * packed[j, p] - s) - packed[j, p - 1] * prev
        xp[j + p] = prev
    # backward: x[j] = y[j] / L[j, j] - sum_i L[i, j] / L[j, j] x[i], i = j + 1 last
    prev = 0.0
    for i in range(n):
        j = n - 1 - i
        row = packed[j, p + 2:]
        win = xp[j + p + 2: j + 2 * p + 1]
        s = 0.0
        for d in range(p - 1):
            s += row[d] * win[d]
        prev = (xp[j + p] * packed[j, p] - s) - packed[j, p + 1] * prev
        xp[j + p] = prev


def solve(packed: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Solve ``A x = b`` given the packed band Cholesky factor of ``A``.

    Parameters
    ----------
    packed : ndarray, shape (n, 2 p + 1)
        Factor from :func:`pack` (of :func:`cholesky`).
    b : ndarray, shape (n,)
        Right-hand side.

    Returns
    -------
    ndarray, shape (n,)
    """
    n, w = packed.shape
    p = (w - 1) // 2
    xp = np.zeros(n + 2 * p)
    solve_padded(packed, np.ascontiguousarray(b, dtype=np.float64), xp)
    return xp[p:p + n].copy()


@numba.njit(cache=True, nogil=True)
def _latent_step(tp, i, step, lat_coef, e_air, rain, water, theta):  # pragma: no cover
    """Latent heat flux (W m-2) of column ``i`` at surface temperature ``tp`` (K), and the
    force-restore update of its surface water ``theta[i]`` over the step (in place).

    The arithmetic of :mod:`clearfast_gis.thermal.moisture` (Magnus, Lee & Pielke wetness,
    bulk transfer with the Lewis analogy, Deardorff force-restore); dew (the surface below
    the dew point) condenses at the full rate.
    """
    tc = tp - ZERO_CELSIUS_K
    deficit = MAGNUS_A_HPA * np.exp(MAGNUS_B * tc / (tc + MAGNUS_C_C)) - e_air[step]
    beta = 1.0
    if deficit > 0.0:
        x = min(max(theta[i] / water[0], 0.0), 1.0)
        beta = 0.25 * (1.0 - np.cos(np.pi * x)) ** 2
    le = beta * lat_coef[step] * deficit
    dtheta = -water[3] * (le / LATENT_HEAT_JKG - rain[step]) - water[4] * (theta[i] - water[2])
    theta[i] = min(max(theta[i] + water[5] * dtheta, 0.0), water[1])
    return le


@numba.njit(cache=True, nogil=True)
def march(packed, c_dt, q_gain, k0, ts_gain, g_bottom, h, eps_sigma, flux, hc, tb, t_now,
           t_prev, ts_now, ts_prev, keep, surface, kept, profiles, lat_coef, e_air, rain,
           water, theta, theta_out):  # pragma: no cover
    """BDF2 time loop of :func:`clearfast_gis.thermal.solver.run` on a band factor.

    The same arithmetic, step by step, as the reference loop (sparse LU): extrapolated
    surface temperature, linearised surface flux ``q`` eliminated into the top cells,
    ``rhs = c_dt (2 T_n - T_(n-1) / 2)`` plus the surface and bottom terms, one solve, then
    the surface temperature from the new top cells. Cells are numbered ``iz * Nr + ir``: the
    top cells are the first ``Nr`` unknowns, the bottom cells the last ``Nr``.

    Parameters
    ----------
    packed : ndarray, shape (n, 2 Nr + 1)
        Packed factor of the system matrix (:func:`pack`).
    c_dt : ndarray, shape (n,)
        Cell capacity over the step, W K-1.
    q_gain, k0, ts_gain, g_bottom : ndarray, shape (Nr,)
        Surface-flux share of the top cells (m2), surface-to-top-centre conductance
        (W m-2 K-1), ``1 / (k0 + h)`` (m2 K W-1), bottom conductance (W K-1).
    h, eps_sigma : float
        Linearisation coefficient (W m-2 K-1) and emissivity x sigma (W m-2 K-4).
    flux, hc, tb : ndarray, shape (N + 1,)
        Temperature-independent surface flux (W m-2), convective coefficient
        (W m-2 K-1) and bottom temperature (K) per step (index 0 unused).
    t_now, t_prev : ndarray, shape (n,)
        Cell temperatures at step 0 and one step before, K.
    ts_now, ts_prev : ndarray, shape (Nr,)
        Surface temperatures at step 0 and one step before, K.
    keep : ndarray of bool, shape (N + 1,)
        Steps whose state to write to ``kept``.
    surface : ndarray, shape (N + 1, Nr)
        Receives the surface temperature at every step, K.
    kept : ndarray, shape (K, n)
        Receives the states of the kept steps in step order, K.
    profiles : ndarray, shape (N + 1, n) or (0, n)
        Receives every step's state, K (when it has N + 1 rows).
    lat_coef, e_air, rain : ndarray, shape (N + 1,) or (0,)
        Latent heat: ``h_c / gamma`` (W m-2 hPa-1), the air's vapour pressure (hPa) and the
        rain rate (kg m-2 s-1) per step; empty arrays switch evaporation off.
    water : ndarray, shape (6,) or (0,)
        ``[theta_fc, theta_sat, theta_deep, C1 / (rho_w d1), C2 / tau, dt_s]``
        (:meth:`clearfast_gis.thermal.moisture.SurfaceWater.kernel_parameters` and the step).
    theta : ndarray, shape (Nr,)
        Surface volumetric water at step 0, updated in place, m3 m-3.
    theta_out : ndarray, shape (N + 1, Nr) or (0, Nr)
        Receives the surface water at every step (when evaporation is on).
    """
    n = c_dt.size
    nr = q_gain.size
    p = (packed.shape[1] - 1) // 2
    bottom = n - nr
    # three zero-padded state buffers, rotated: the solve writes x into buf[p:p + n]
    cur = np.zeros(n + 2 * p)
    old = np.zeros(n + 2 * p)
    new = np.zeros(n + 2 * p)
    cur[p:p + n] = t_now
    old[p:p + n] = t_prev
    ts_c = ts_now.copy()
    ts_o = ts_prev.copy()
    q = np.empty(nr)
    rhs = np.empty(n)
    surface[0] = ts_c
    wet = lat_coef.size > 0
    if wet:
        theta_out[0] = theta
    n_kept = 0
    if keep[0]:
        kept[0] = t_now
        n_kept = 1
    if profiles.shape[0] > 0:
        profiles[0] = t_now
    for step in range(1, flux.size):
        for i in range(nr):
            tp = 2.0 * ts_c[i] - ts_o[i]
            tp3 = tp * tp * tp
            hp = 4.0 * eps_sigma * tp3 + hc[step]
            q[i] = flux[step] + 3.0 * eps_sigma * tp3 * tp - (hp - h) * tp
            if wet:
                q[i] -= _latent_step(tp, i, step, lat_coef, e_air, rain, water, theta)
                theta_out[step, i] = theta[i]
        for j in range(n):
            rhs[j] = c_dt[j] * (2.0 * cur[p + j] - 0.5 * old[p + j])
        for i in range(nr):
            rhs[i] += q_gain[i] * q[i]
        for i in range(nr):
            rhs[bottom + i] += g_bottom[i] * tb[step]
        solve_padded(packed, rhs, new)
        for i in range(nr):
            ts_o[i] = ts_c[i]
            ts_c[i] = (q[i] + k0[i] * new[p + i]) * ts_gain[i]
            surface[step, i] = ts_c[i]
        old, cur, new = cur, new, old
        if keep[step]:
            kept[n_kept] = cur[p:p + n]
            n_kept += 1
        if profiles.shape[0] > 0:
            profiles[step] = cur[p:p + n]


def heat_equation(z_faces, r_faces, props, drive, dt_s, init_k, init_prev_k, surface_init_k,
                  keep_states, keep_profiles) -> SolverResult:
    """:func:`clearfast_gis.thermal.solver.run` on a band Cholesky factor with the time loop
    compiled (GIL released)."""
    nz, nr = z_faces.size - 1, r_faces.size - 1
    net = _network(z_faces, r_faces, props)
    h = float(drive.h_ref_wm2k)
    c_dt, diag_add, q_gain, ts_gain = _step_terms(net.cap, net.ring, net.k0, net.idx[0], h,
                                                  dt_s)
    packed = pack(cholesky(_band(net, diag_add)))
    n_steps = drive.flux_wm2.size - 1
    t_now, t_prev, ts_now, ts_prev = _initial(init_k, init_prev_k, surface_init_k, net.idx[0])
    keep = set(keep_states)
    steps = [n for n in range(n_steps + 1) if n in keep]
    mask = np.zeros(n_steps + 1, dtype=np.bool_)
    mask[steps] = True
    kept = np.empty((len(steps), nz * nr))
    surface = np.empty((n_steps + 1, nr))
    profiles = np.empty((n_steps + 1 if keep_profiles else 0, nz * nr))

    def f64(a):
        return np.ascontiguousarray(a, dtype=np.float64)

    lat, water, theta, theta_out = _latent_arrays(drive, dt_s, nr)
    march(packed, c_dt, f64(q_gain), f64(net.k0), f64(ts_gain), f64(net.g_bottom), h,
                 float(drive.emissivity * STEFAN_BOLTZMANN), f64(drive.flux_wm2),
                 f64(drive.hc_wm2k), f64(drive.bottom_k), t_now, f64(t_prev), f64(ts_now),
                 f64(ts_prev), mask, surface, kept, profiles, *lat, water, theta, theta_out)
    states = {n: kept[i].reshape(nz, nr) for i, n in enumerate(steps)}
    return SolverResult(surface, states,
                        profiles.reshape(n_steps + 1, nz, nr) if keep_profiles else None,
                        theta_out if drive.latent is not None else None)
