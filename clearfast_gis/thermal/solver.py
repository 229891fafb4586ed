"""Finite-volume heat conduction in an axisymmetric soil block, implicit in time.

The unknowns are cell temperatures on an (r, z) grid (one radial cell gives the 1-D soil
column). Faces between cells conduct with the harmonic mean of the two half-cell
resistances; the bottom face is held at a given temperature; the side and the axis are
adiabatic. The surface energy balance is eliminated into the top cells as a Robin
condition: with the net surface flux written ``q = Q - h_ref T_s`` (``h_ref`` constant,
``Q`` evaluated from the lagged, extrapolated surface temperature) the system matrix is
constant, so one factorisation serves a whole run. Time stepping is BDF2 (second order,
L-stable), started as if the state before the first step equalled the initial state.

In the natural cell order (``iz * Nr + ir``) the matrix is a band of half-bandwidth ``Nr``.
The fast kernels factor it by band Cholesky and run the whole time loop compiled, with the
GIL released (:mod:`clearfast_gis.thermal._kernels`); ``--kernels reference`` factors it by
scipy's sparse LU and steps in Python (:mod:`clearfast_gis.thermal._reference`). Both build
the matrix from one conductance network (:func:`_network`) and agree to ~1e-11 K.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from clearfast_gis import kernels
from clearfast_gis.thermal.moisture import SurfaceWater


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
    latent : Latent or None
        Evaporation and dew at the surface (None: a dry surface, no latent heat).
    """

    flux_wm2: np.ndarray
    hc_wm2k: np.ndarray
    bottom_k: np.ndarray
    emissivity: float
    h_ref_wm2k: float
    latent: Latent | None = None

    def from_step(self, start: int) -> SurfaceDrive:
        """The same drive from step ``start`` on (index ``start`` becomes 0)."""
        lat = self.latent
        if lat is not None:
            lat = Latent(lat.coef_wm2hpa[start:], lat.e_air_hpa[start:], lat.rain_kgm2s[start:],
                         lat.water, lat.theta_start)
        return SurfaceDrive(self.flux_wm2[start:], self.hc_wm2k[start:], self.bottom_k[start:],
                            self.emissivity, self.h_ref_wm2k, lat)


@dataclass(frozen=True)
class Latent:
    """Latent heat at the surface per step, arrays of shape (N + 1,) (index 0 unused).

    Attributes
    ----------
    coef_wm2hpa : ndarray
        ``h_c / gamma``: the bulk transfer coefficient of vapour, W m-2 hPa-1.
    e_air_hpa : ndarray
        Vapour pressure of the air, hPa.
    rain_kgm2s : ndarray
        Rain rate, kg m-2 s-1.
    water : SurfaceWater
        The surface layer's water parameters (:mod:`clearfast_gis.thermal.moisture`).
    theta_start : float or ndarray, shape (Nr,)
        Surface water at step 0, m3 m-3.
    """

    coef_wm2hpa: np.ndarray
    e_air_hpa: np.ndarray
    rain_kgm2s: np.ndarray
    water: SurfaceWater
    theta_start: float | np.ndarray


@dataclass(frozen=True)
class SolverResult:
    """Output of :func:`run`.

    ``surface_k`` (N + 1, Nr): surface temperature of every column at every step;
    ``states`` maps a requested step index to the cell temperatures (Nz, Nr) at that step;
    ``profiles`` (N + 1, Nz, Nr) when all states were kept, else None; ``theta`` (N + 1, Nr)
    the surface layer's volumetric water at every step with latent heat, else None.
    """

    surface_k: np.ndarray
    states: dict[int, np.ndarray]
    profiles: np.ndarray | None
    theta: np.ndarray | None = None


@dataclass(frozen=True)
class _Network:
    """Conductance network of a grid, per radian of azimuth (one cell per unknown).

    Cells are numbered ``idx[iz, ir] = iz * Nr + ir``; with ``n = Nz * Nr``:

    Attributes
    ----------
    g_z : ndarray, shape (Nz - 1, Nr)
        Conductance of the horizontal face between cells (iz, ir) and (iz + 1, ir), W K-1.
    g_r : ndarray, shape (Nz, Nr - 1)
        Conductance of the radial face between cells (iz, ir) and (iz, ir + 1), W K-1.
    diag : ndarray, shape (n,)
        Sum of the conductances of each cell's faces, the bottom face included, W K-1.
    cap : ndarray, shape (n,)
        Heat capacity of each cell, J K-1.
    ring : ndarray, shape (Nr,)
        Horizontal face area of each column, m2.
    k0 : ndarray, shape (Nr,)
        Surface-to-top-centre conductance per area, W m-2 K-1.
    g_bottom : ndarray, shape (Nr,)
        Conductance from the bottom cells to the bottom face, W K-1.
    idx : ndarray of int, shape (Nz, Nr)
        Cell numbers.
    """

    g_z: np.ndarray
    g_r: np.ndarray
    diag: np.ndarray
    cap: np.ndarray
    ring: np.ndarray
    k0: np.ndarray
    g_bottom: np.ndarray
    idx: np.ndarray


def _network(z_faces: np.ndarray, r_faces: np.ndarray, props: CellProps) -> _Network:
    """Face conductances and cell capacities of the grid (see :class:`_Network`)."""
    nz, nr = z_faces.size - 1, r_faces.size - 1
    dz = np.diff(z_faces)
    ring = 0.5 * (r_faces[1:] ** 2 - r_faces[:-1] ** 2)  # horizontal face area per radian
    rc = 0.5 * (r_faces[1:] + r_faces[:-1])
    cap = (props.rho_c_jm3k * dz[:, None] * ring[None, :]).ravel()
    idx = np.arange(nz * nr).reshape(nz, nr)
    diag = np.zeros(nz * nr)
    # vertical faces between rows iz and iz + 1
    kz = props.k_z_wmk
    res = (0.5 * dz[:-1, None] / kz[:-1]) + (0.5 * dz[1:, None] / kz[1:])
    g_z = ring[None, :] / res
    np.add.at(diag, idx[:-1].ravel(), g_z.ravel())
    np.add.at(diag, idx[1:].ravel(), g_z.ravel())
    # radial faces between columns ir and ir + 1
    g_r = np.zeros((nz, 0))
    if nr > 1:
        kr = props.k_r_wmk
        rf = r_faces[1:-1]
        res = (rf - rc[:-1])[None, :] / kr[:, :-1] + (rc[1:] - rf)[None, :] / kr[:, 1:]
        g_r = (rf[None, :] * dz[:, None]) / res
        np.add.at(diag, idx[:, :-1].ravel(), g_r.ravel())
        np.add.at(diag, idx[:, 1:].ravel(), g_r.ravel())
    g_bottom = ring / (0.5 * dz[-1] / kz[-1])
    diag[idx[-1]] += g_bottom
    k0 = kz[0] / (0.5 * dz[0])  # surface-to-top-centre conductance per area, W m-2 K-1
    return _Network(g_z, g_r, diag, cap, ring, k0, g_bottom, idx)


def _assemble(z_faces: np.ndarray, r_faces: np.ndarray, props: CellProps):
    """Conduction matrix (CSR, n x n, W K-1) and the network's cap, ring, k0, g_bottom, idx."""
    net = _network(z_faces, r_faces, props)
    n, idx = net.diag.size, net.idx
    rows, cols, vals = [], [], []
    faces = [(net.g_z, idx[:-1], idx[1:])]
    if net.g_r.size:
        faces.append((net.g_r, idx[:, :-1], idx[:, 1:]))
    for g, a, b in faces:
        a, b = a.ravel(), b.ravel()
        rows += [a, b]
        cols += [b, a]
        vals += [-g.ravel(), -g.ravel()]
    rows.append(np.arange(n))
    cols.append(np.arange(n))
    vals.append(net.diag)
    mat = sp.csr_matrix(
        (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n, n)
    )
    return mat, net.cap, net.ring, net.k0, net.g_bottom, net.idx


def _band(net: _Network, diag_add: np.ndarray) -> np.ndarray:
    """Lower band of the conduction matrix plus ``diag(diag_add)``, W K-1.

    In the natural cell order the radial neighbour is one off the diagonal and the vertical
    one ``Nr`` off, so the half-bandwidth is ``Nr``.

    Returns
    -------
    ndarray, shape (Nz * Nr, Nr + 1)
        ``band[j, d] = A[j + d, j]`` (:mod:`clearfast_gis.thermal._kernels` storage).
    """
    nr = net.idx.shape[1]
    band = np.zeros((net.diag.size, nr + 1))
    band[:, 0] = net.diag + diag_add
    band[net.idx[:-1].ravel(), nr] = -net.g_z.ravel()
    if net.g_r.size:
        band[net.idx[:, :-1].ravel(), 1] = -net.g_r.ravel()
    return band


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

    Notes
    -----
    Runs on the band Cholesky kernels, or on the sparse LU reference under
    ``kernels.use("reference")`` (:mod:`clearfast_gis.kernels`).
    """
    args = (z_faces, r_faces, props, drive, dt_s, init_k, init_prev_k, surface_init_k,
            keep_states, keep_profiles)
    return kernels.kernel("heat_equation")(*args)


def _step_terms(cap: np.ndarray, ring: np.ndarray, k0: np.ndarray, top: np.ndarray,
                h: float, dt_s: float):
    """What a BDF2 step adds to the conduction matrix, and the surface elimination.

    Returns ``c_dt`` (n,), capacity over the step (W K-1); ``diag_add`` (n,), added to the
    matrix's diagonal: ``1.5 c_dt`` plus, in the top cells, the surface node eliminated
    (``ring k0 h / (k0 + h)``); ``q_gain`` (Nr,), m2, the share of the flux ``q`` that
    enters the top cell; ``ts_gain`` (Nr,), m2 K W-1, in ``T_s = (q + k0 T_top) ts_gain``.
    """
    c_dt = cap / dt_s
    diag_add = 1.5 * c_dt
    diag_add[top] += ring * k0 * h / (k0 + h)
    q_gain = ring * k0 / (k0 + h)
    ts_gain = 1.0 / (k0 + h)
    return c_dt, diag_add, q_gain, ts_gain


def _initial(init_k, init_prev_k, surface_init_k, top):
    """Cell temperatures (n,) and surface temperatures (Nr,) at step 0 and one step before."""
    t_now = np.asarray(init_k, dtype=float).ravel().copy()
    t_prev = t_now.copy() if init_prev_k is None else np.asarray(init_prev_k, float).ravel()
    if surface_init_k is None:
        ts_now = t_now[top].copy()
        ts_prev = ts_now.copy()
    else:
        ts_now = np.asarray(surface_init_k[0], dtype=float).copy()
        ts_prev = np.asarray(surface_init_k[1], dtype=float).copy()
    return t_now, t_prev, ts_now, ts_prev


def _latent_arrays(drive: SurfaceDrive, dt_s: float, nr: int):
    """The kernel's latent-heat arguments: (coef, e_air, rain), water parameters, the surface
    water at step 0 (Nr,) and the (N + 1, Nr) output; empty arrays without latent heat."""
    lat = drive.latent
    n = drive.flux_wm2.size
    if lat is None:
        empty = np.zeros(0)
        return (empty, empty, empty), empty, np.zeros(nr), np.zeros((0, nr))
    arrays = tuple(np.ascontiguousarray(a, dtype=np.float64)
                   for a in (lat.coef_wm2hpa, lat.e_air_hpa, lat.rain_kgm2s))
    water = np.append(lat.water.kernel_parameters(), float(dt_s))
    theta = np.ascontiguousarray(np.broadcast_to(np.asarray(lat.theta_start, float), (nr,)))
    return arrays, water, theta.copy(), np.empty((n, nr))


