"""The heat solver's reference kernel (``--kernels reference``, :mod:`clearfast_gis.kernels`):
the registry's ``heat_equation`` by scipy's sparse LU and a Python time loop, which the band
kernels of :mod:`clearfast_gis.thermal._kernels` are checked against (~1e-11 K)."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from clearfast_gis.thermal._kernels import _latent_step
from clearfast_gis.thermal.solver import (
    SolverResult,
    _assemble,
    _initial,
    _latent_arrays,
    _step_terms,
)
from clearfast_gis.units import STEFAN_BOLTZMANN


def heat_equation(z_faces, r_faces, props, drive, dt_s, init_k, init_prev_k, surface_init_k,
                  keep_states, keep_profiles) -> SolverResult:
    """:func:`clearfast_gis.thermal.solver.run` by a sparse LU factorisation and a Python time
    loop (the reference of ``--kernels reference``, which the band path is checked against)."""
    nz, nr = z_faces.size - 1, r_faces.size - 1
    mat, cap, ring, k0, g_bottom, idx = _assemble(z_faces, r_faces, props)
    h = drive.h_ref_wm2k
    top = idx[0]
    bottom = idx[-1]
    c_dt, diag_add, q_gain, ts_gain = _step_terms(cap, ring, k0, top, h, dt_s)
    system = mat + sp.diags(diag_add)
    lu = splu(system.tocsc())
    n_steps = drive.flux_wm2.size - 1
    eps_sigma = drive.emissivity * STEFAN_BOLTZMANN

    t_now, t_prev, ts_now, ts_prev = _initial(init_k, init_prev_k, surface_init_k, top)
    surface = np.empty((n_steps + 1, nr))
    surface[0] = ts_now
    keep = set(keep_states)
    states: dict[int, np.ndarray] = {}
    if 0 in keep:
        states[0] = t_now.reshape(nz, nr).copy()
    profiles = np.empty((n_steps + 1, nz, nr)) if keep_profiles else None
    if profiles is not None:
        profiles[0] = t_now.reshape(nz, nr)
    rhs_base = np.empty(nz * nr)
    flux, hc, tb = drive.flux_wm2, drive.hc_wm2k, drive.bottom_k
    lat, water, theta, theta_out = _latent_arrays(drive, dt_s, nr)
    if drive.latent is not None:
        theta_out[0] = theta
    for n in range(1, n_steps + 1):
        tp = 2.0 * ts_now - ts_prev
        tp3 = tp * tp * tp
        hp = 4.0 * eps_sigma * tp3 + hc[n]
        q = flux[n] + 3.0 * eps_sigma * tp3 * tp - (hp - h) * tp
        if drive.latent is not None:
            q = q - np.array([_latent_step(tp[i], i, n, *lat, water, theta)
                              for i in range(nr)])
            theta_out[n] = theta
        np.multiply(c_dt, 2.0 * t_now - 0.5 * t_prev, out=rhs_base)
        rhs_base[top] += q_gain * q
        rhs_base[bottom] += g_bottom * tb[n]
        t_new = lu.solve(rhs_base)
        ts_prev = ts_now
        ts_now = (q + k0 * t_new[top]) * ts_gain
        t_prev, t_now = t_now, t_new
        surface[n] = ts_now
        if n in keep:
            states[n] = t_now.reshape(nz, nr).copy()
        if profiles is not None:
            profiles[n] = t_now.reshape(nz, nr)
    return SolverResult(surface, states, profiles,
                        theta_out if drive.latent is not None else None)
