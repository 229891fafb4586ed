"""Finite-volume heat conduction in an axisymmetric soil block, implicit in time.

The unknowns are cell temperatures on an (r, z) grid (one radial cell gives the 1-D soil
column). Faces between cells conduct with the harmonic mean of the two half-cell
resistances; the bottom face is held at a given temperature; the side and the axis are
adiabatic. The surface energy balance is eliminated into the top cells as a Robin
condition: with the net surface flux written ``q = Q - h_ref T_s`` (``h_ref`` constant,
``Q`` evaluated from the lagged, extrapolated surface temperature) the system matrix is
constant, so one sparse LU factorisation serves a whole run. Time stepping is BDF2
(second order, L-stable), started as if the state before the first step equalled the
initial state.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from clearfast_gis.units import STEFAN_BOLTZMANN


@dataclass(frozen=True)
class CellProps:
    """Thermal properties per cell, arrays of shape (Nz, Nr).

    ``k_r_wmk`` conducts across radial faces, ``k_z_wmk`` across horizontal faces (they differ
    in cells that the object's top or bottom cuts: parallel and series mixing).
    """

    k_r_wmk: np.ndarray
    k_z_wmk: np.ndarray
    rho_c_jm3k: np.ndarray


@dataclass(frozen=True)
class SurfaceDrive:
    """Per-step boundary data, arrays of shape (N + 1,) indexed by step (index 0 unused).

    Attributes
    ----------
    flux_wm2 : ndarray
        ``(1 - albedo) E_sun + eps E_sky + h_c T_air``, W m-2 (the part of the surface
        flux that does not depend on the surface temperature).
    hc_wm2k : ndarray
        Convective coefficient, W m-2 K-1.
    bottom_k : ndarray
        Temperature of the bottom face, K.
    emissivity : float
        Surface emissivity (0 makes the surface condition linear: ``q = flux - h_c T_s``).
    h_ref_wm2k : float
        Constant linearisation coefficient in the matrix, W m-2 K-1.
    """

    flux_wm2: np.ndarray
    hc_wm2k: np.ndarray
    bottom_k: np.ndarray
    emissivity: float
    h_ref_wm2k: float


@dataclass(frozen=True)
class SolverResult:
    """Output of :func:`run`.

    ``surface_k`` (N + 1, Nr): surface temperature of every column at every step;
    ``states`` maps a requested step index to the cell temperatures (Nz, Nr) at that step;
    ``profiles`` (N + 1, Nz, Nr) when all states were kept, else None.
    """

    surface_k: np.ndarray
    states: dict[int, np.ndarray]
    profiles: np.ndarray | None


def _assemble(z_faces: np.ndarray, r_faces: np.ndarray, props: CellProps):
    nz, nr = z_faces.size - 1, r_faces.size - 1
    dz = np.diff(z_faces)
    ring = 0.5 * (r_faces[1:] ** 2 - r_faces[:-1] ** 2)  # horizontal face area per radian
    rc = 0.5 * (r_faces[1:] + r_faces[:-1])
    cap = (props.rho_c_jm3k * dz[:, None] * ring[None, :]).ravel()
    idx = np.arange(nz * nr).reshape(nz, nr)
    rows, cols, vals = [], [], []
    diag = np.zeros(nz * nr)
    # vertical faces between rows iz and iz + 1
    kz = props.k_z_wmk
    res = (0.5 * dz[:-1, None] / kz[:-1]) + (0.5 * dz[1:, None] / kz[1:])
    g = ring[None, :] / res
    a, b = idx[:-1].ravel(), idx[1:].ravel()
    rows += [a, b]
    cols += [b, a]
    vals += [-g.ravel(), -g.ravel()]
    np.add.at(diag, a, g.ravel())
    np.add.at(diag, b, g.ravel())
    # radial faces between columns ir and ir + 1
    if nr > 1:
        kr = props.k_r_wmk
        rf = r_faces[1:-1]
        res = (rf - rc[:-1])[None, :] / kr[:, :-1] + (rc[1:] - rf)[None, :] / kr[:, 1:]
        g = (rf[None, :] * dz[:, None]) / res
        a, b = idx[:, :-1].ravel(), idx[:, 1:].ravel()
        rows += [a, b]
        cols += [b, a]
        vals += [-g.ravel(), -g.ravel()]
        np.add.at(diag, a, g.ravel())
        np.add.at(diag, b, g.ravel())
    g_bottom = ring / (0.5 * dz[-1] / kz[-1])
    diag[idx[-1]] += g_bottom
    k0 = kz[0] / (0.5 * dz[0])  # surface-to-top-centre conductance per area, W m-2 K-1
    rows.append(np.arange(nz * nr))
    cols.append(np.arange(nz * nr))
    vals.append(diag)
    mat = sp.csr_matrix(
        (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
        shape=(nz * nr, nz * nr),
    )
    return mat, cap, ring, k0, g_bottom, idx


def run(
    z_faces: np.ndarray,
    r_faces: np.ndarray,
    props: CellProps,
    drive: SurfaceDrive,
    dt_s: float,
    init_k: np.ndarray,
    init_prev_k: np.ndarray | None = None,
    surface_init_k: tuple[np.ndarray, np.ndarray] | None = None,
    keep_states: tuple[int, ...] = (),
    keep_profiles: bool = False,
) -> SolverResult:
    """Integrate the heat equation over ``N = len(drive.flux_wm2) - 1`` steps of ``dt_s``.

    Parameters
    ----------
    z_faces : ndarray, shape (Nz + 1,)
        Depth faces, m (0 = surface).
    r_faces : ndarray, shape (Nr + 1,)
        Radial faces, m (0 = axis).
    props : CellProps
        Cell properties, (Nz, Nr).
    drive : SurfaceDrive
        Boundary data per step.
    dt_s : float
        Time step, s.
    init_k, init_prev_k : ndarray, shape (Nz, Nr)
        Temperatures at step 0 and one step before (BDF2 history; default: equal), K.
    surface_init_k : (ndarray, ndarray), shapes (Nr,), optional
        Surface temperatures at step 0 and one step before (for the lagged flux); default:
        the top cells' temperatures.
    keep_states : tuple of int
        Steps whose full state to return.
    keep_profiles : bool
        Keep every step's full state (memory N x Nz x Nr).

    Returns
    -------
    SolverResult
    """
    nz, nr = z_faces.size - 1, r_faces.size - 1
    mat, cap, ring, k0, g_bottom, idx = _assemble(z_faces, r_faces, props)
    h = drive.h_ref_wm2k
    top = idx[0]
    bottom = idx[-1]
    top_gain = ring * k0 * h / (k0 + h)
    diag_add = np.zeros(nz * nr)
    diag_add[top] = top_gain
    c_dt = cap / dt_s
    system = mat + sp.diags(1.5 * c_dt + diag_add)
    lu = splu(system.tocsc())
    q_gain = ring * k0 / (k0 + h)
    ts_gain = 1.0 / (k0 + h)
    n_steps = drive.flux_wm2.size - 1
    eps_sigma = drive.emissivity * STEFAN_BOLTZMANN

    t_now = np.asarray(init_k, dtype=float).ravel().copy()
    t_prev = t_now.copy() if init_prev_k is None else np.asarray(init_prev_k, float).ravel()
    if surface_init_k is None:
        ts_now = t_now[top].copy()
        ts_prev = ts_now.copy()
    else:
        ts_now = np.asarray(surface_init_k[0], dtype=float).copy()
        ts_prev = np.asarray(surface_init_k[1], dtype=float).copy()
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
    for n in range(1, n_steps + 1):
        tp = 2.0 * ts_now - ts_prev
        tp3 = tp * tp * tp
        hp = 4.0 * eps_sigma * tp3 + hc[n]
        q = flux[n] + 3.0 * eps_sigma * tp3 * tp - (hp - h) * tp
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
    return SolverResult(surface, states, profiles)
