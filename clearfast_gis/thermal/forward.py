"""Forward thermal model: the undisturbed soil column and a soil with a buried cylinder.

Physics (design guide section 7): ``rho c dT/dt = (1/r) d/dr(r k dT/dr) + d/dz(k dT/dz)``;
surface energy balance ``-k dT/dz = (1 - A) E_sun + eps E_sky - eps sigma T^4 +
h_c (T_air - T) - LE`` with ``h_c = (5.7 + 3.8 v) * hc_scale``; the latent heat flux ``LE``
(evaporation, dew, rain; :mod:`clearfast_gis.thermal.moisture`) only for a soil with surface
water (``Soil.water``), else none; bottom
(0.5 m) held at the deepest thermocouple or the daily mean air temperature; adiabatic
side; spin-up with the first day's forcing repeated. Numerics in
:mod:`clearfast_gis.thermal.solver`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike
from scipy.interpolate import CubicSpline

from clearfast_gis.errors import InvalidInput
from clearfast_gis.thermal import grid as grids
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.thermal.materials import Material, Soil
from clearfast_gis.thermal.moisture import (
    WATER_HEAT_JKGK,
    SurfaceWater,
    psychrometric_hpa_k,
    saturation_slope_hpa_k,
    vapour_pressure_hpa,
)
from clearfast_gis.thermal.solar import DAY_S
from clearfast_gis.thermal.solver import CellProps, Latent, SurfaceDrive, run
from clearfast_gis.units import STEFAN_BOLTZMANN

Bottom = float | tuple[np.ndarray, np.ndarray] | None
"""Bottom boundary: a temperature in K, a series ``(time_s, temp_k)`` (e.g. the deepest
thermocouple), or None for the daily mean air temperature."""


@dataclass(frozen=True)
class BuriedObject:
    """A vertical cylinder in the soil.

    Attributes
    ----------
    radius_m, height_m : float
        Cylinder radius and height, m.
    depth_m : float
        Depth of the top face below the surface, m (0 = surface-laid).
    material : Material
        Homogeneous fill.
    """

    radius_m: float
    height_m: float
    depth_m: float
    material: Material

    def __post_init__(self) -> None:
        if not (self.radius_m > 0 and self.height_m > 0 and self.depth_m >= 0):
            raise InvalidInput("radius and height must be > 0, depth >= 0", field="object")


@dataclass(frozen=True)
class BackgroundRun:
    """The undisturbed soil column.

    ``time_s`` (T,); ``surface_k`` (T,) surface temperature, K; ``profile_k`` (T, D)
    temperature at the requested depths, K.
    """

    time_s: np.ndarray
    surface_k: np.ndarray
    profile_k: np.ndarray


@dataclass(frozen=True)
class ObjectRun:
    """Surface temperature above and around a buried object.

    ``time_s`` (T,); ``surface_k`` (T, R) at ``radii_m`` (R,) from the object's axis, K;
    ``background_k`` (T,) the undisturbed surface (same grid and time step), K.
    """

    time_s: np.ndarray
    surface_k: np.ndarray
    background_k: np.ndarray
    radii_m: np.ndarray


def convective_coefficient(wind_ms: ArrayLike, hc_scale: float = 1.0) -> np.ndarray:
    """Convective heat-transfer coefficient ``(5.7 + 3.8 v) * hc_scale``, W m-2 K-1."""
    return hc_scale * (5.7 + 3.8 * np.asarray(wind_ms, dtype=float))


def latent_drive(water: SurfaceWater, f: dict[str, np.ndarray], hc_wm2k: np.ndarray
                 ) -> tuple[Latent, np.ndarray, float]:
    """Evaporation, dew and rain at the surface per step.

    Parameters
    ----------
    water : SurfaceWater
    f : dict of ndarray, shape (N + 1,)
        Forcing channels per step (:meth:`Forcing.at`).
    hc_wm2k : ndarray, shape (N + 1,)
        Convective coefficient, W m-2 K-1.

    Returns
    -------
    latent : Latent
        Vapour transfer coefficient ``h_c / gamma``, air vapour pressure, rain (kg m-2 s-1).
    h_rain_wm2k : ndarray, shape (N + 1,)
        Rain's sensible heat ``P c_w`` (rain at air temperature), W m-2 K-1, to add to
        ``h_c`` (the flux then carries ``h_rain T_air``).
    h_latent_wm2k : float
        Mean slope of the potential latent flux at the air temperature, W m-2 K-1 (added to
        the solver's constant linearisation coefficient, for stability).
    """
    coef = hc_wm2k / psychrometric_hpa_k()
    e_air = vapour_pressure_hpa(f["air_temp_k"], f["rh_pct"])
    rain = f["rain_mm_h"] / 3600.0
    h_lat = float(np.mean(coef * saturation_slope_hpa_k(f["air_temp_k"])))
    latent = Latent(coef, e_air, rain, water,
                    water.theta_deep if water.theta_start is None else water.theta_start)
    return latent, rain * WATER_HEAT_JKGK, h_lat


def _fold_into_forcing(t: np.ndarray, forcing: Forcing) -> np.ndarray:
    """Map spin-up times before the record onto the record's first day."""
    t0 = forcing.time_s[0]
    early = t < t0
    shift = np.ceil((t0 - t[early]) / DAY_S) * DAY_S
    out = t.copy()
    out[early] = t[early] + shift
    return out


def _bottom_series(bottom: Bottom, forcing: Forcing, t: np.ndarray) -> np.ndarray:
    if bottom is None:
        return np.full(t.size, forcing.daily_mean_air_k())
    if np.isscalar(bottom):
        return np.full(t.size, float(bottom))
    bt, bk = (np.asarray(a, dtype=float) for a in bottom)
    if bt.ndim != 1 or bt.shape != bk.shape or bt.size < 1:
        raise InvalidInput("expected (time_s, temp_k) arrays of one length", field="bottom")
    return np.interp(_fold_into_forcing(t, Forcing(bt, bk, bk, bk, bk, bk)), bt, bk)


class _Setup:
    """Time grid, forcing per step and the spun-up background column for one run set."""

    def __init__(
        self,
        soil: Soil,
        forcing: Forcing,
        out_time_s: ArrayLike,
        spinup_days: float,
        dt_s: float,
        bottom: Bottom,
        bottom_m: float,
        refine: int,
    ) -> None:
        out = np.asarray(out_time_s, dtype=float)
        if out.ndim != 1 or out.size == 0 or not np.all(np.isfinite(out)):
            raise InvalidInput("expected a non-empty 1-D array of times", field="out_time_s")
        tol = 3600.0
        if out.min() < forcing.time_s[0] - tol or out.max() > forcing.time_s[-1] + tol:
            raise InvalidInput("output times outside the forcing record", field="out_time_s")
        if not isinstance(soil, Soil):
            raise InvalidInput("expected a Soil", field="soil")
        self.soil, self.out, self.dt = soil, out, dt_s / 2**refine
        self.z_faces = grids.depth_faces(bottom_m)
        for _ in range(refine):
            self.z_faces = grids.bisect(self.z_faces)
        self.refine = refine
        self.spin_steps = int(np.ceil(spinup_days * DAY_S / self.dt))
        span = out.max() - out.min()
        self.n_steps = self.spin_steps + int(np.ceil(span / self.dt)) + 2
        self.t0 = out.min() - self.spin_steps * self.dt
        self.t = self.t0 + self.dt * np.arange(self.n_steps + 1)
        f = forcing.at(np.clip(_fold_into_forcing(self.t, forcing), None, forcing.time_s[-1]))
        hc = convective_coefficient(f["wind_ms"], soil.hc_scale)
        eps = soil.emissivity
        t_mean = float(np.mean(f["air_temp_k"]))
        h_ref = 4 * eps * STEFAN_BOLTZMANN * t_mean**3 + float(np.mean(hc))
        latent = None
        if soil.water is not None:
            latent, h_rain, h_lat = latent_drive(soil.water, f, hc)
            hc = hc + h_rain
            h_ref += h_lat
        flux = (1 - soil.albedo) * f["solar_wm2"] + eps * f["sky_lw_wm2"] + hc * f["air_temp_k"]
        self.bottom_k = _bottom_series(bottom, forcing, self.t)
        self.drive = SurfaceDrive(flux, hc, self.bottom_k, eps, h_ref, latent)
        self.first_out = self.spin_steps - 2

    def column(self, keep_states=(), keep_profiles=False):
        nz = self.z_faces.size - 1
        ones = np.ones((nz, 1))
        props = CellProps(self.soil.k_wmk * ones, self.soil.k_wmk * ones,
                          self.soil.rho_c_jm3k * ones)
        init = np.full((nz, 1), self.bottom_k[0])
        return run(self.z_faces, np.array([0.0, 1.0]), props, self.drive, self.dt, init,
                   keep_states=keep_states, keep_profiles=keep_profiles)

    def to_out(self, series: np.ndarray, first: int) -> np.ndarray:
        """Cubic interpolation of a per-step series (steps from ``first``) to output times."""
        spline = CubicSpline(self.t[first:], series[first:], axis=0)
        return spline(self.out)


def simulate_background(
    soil: Soil,
    forcing: Forcing,
    out_time_s: ArrayLike,
    depths_m: ArrayLike = (),
    spinup_days: float = 2.0,
    dt_s: float = 300.0,
    bottom: Bottom = None,
    bottom_m: float = 0.5,
    refine: int = 0,
) -> BackgroundRun:
    """Temperature of the undisturbed soil column (1-D).

    Parameters
    ----------
    soil : Soil
        Soil properties (conductivity, heat capacity, emissivity, albedo, ``hc_scale``).
    forcing : Forcing
        Weather over (at least) the output period; before it, the first day is repeated.
    out_time_s : array_like, shape (T,)
        Output times, UTC epoch seconds.
    depths_m : array_like, shape (D,)
        Depths for ``profile_k``, m (0..bottom_m).
    spinup_days : float
        Spin-up before the first output, days.
    dt_s : float
        Time step, s.
    bottom : float or (time_s, temp_k) or None
        Bottom boundary (see :data:`Bottom`).
    bottom_m : float
        Depth of the bottom boundary, m.
    refine : int
        Number of grid and step halvings (for convergence checks).

    Returns
    -------
    BackgroundRun
    """
    setup = _Setup(soil, forcing, out_time_s, spinup_days, dt_s, bottom, bottom_m, refine)
    depths = np.asarray(depths_m, dtype=float).ravel()
    if np.any((depths < 0) | (depths > bottom_m)):
        raise InvalidInput(f"depths must lie in [0, {bottom_m}] m", field="depths_m")
    res = setup.column(keep_profiles=depths.size > 0)
    surface = setup.to_out(res.surface_k[:, 0], setup.first_out)
    if depths.size == 0:
        return BackgroundRun(setup.out, surface, np.empty((setup.out.size, 0)))
    zc = np.concatenate([[0.0], grids.centres(setup.z_faces), [bottom_m]])
    prof = np.concatenate(
        [res.surface_k[:, None, 0], res.profiles[:, :, 0], setup.bottom_k[:, None]], axis=1
    )
    j = np.clip(np.searchsorted(zc, depths) - 1, 0, zc.size - 2)
    w = (depths - zc[j]) / (zc[j + 1] - zc[j])
    at_depths = prof[:, j] * (1 - w) + prof[:, j + 1] * w
    return BackgroundRun(setup.out, surface, setup.to_out(at_depths, setup.first_out))


def object_props(
    z_faces: np.ndarray, r_faces: np.ndarray, soil: Material, obj: BuriedObject
) -> CellProps:
    """Cell properties of soil with a cylinder, shapes (Nz, Nr).

    The radial grid must have a face on the object's rim (:func:`grid.radial_faces`), so
    only the object's top and bottom cut cells. In a cut cell with object volume fraction f,
    horizontal faces see the series mix ``1 / (f / k_o + (1 - f) / k_s)``, radial faces the
    parallel mix ``f k_o + (1 - f) k_s``, and rho c the volume average: the properties, and
    so the results, vary smoothly with the depth.
    """
    top, bot = obj.depth_m, obj.depth_m + obj.height_m
    overlap = np.clip(np.minimum(z_faces[1:], bot) - np.maximum(z_faces[:-1], top), 0, None)
    fz = overlap / np.diff(z_faces)
    inside = r_faces[1:] <= obj.radius_m * (1 + 1e-9)
    f = fz[:, None] * inside[None, :]
    ks, ko = soil.k_wmk, obj.material.k_wmk
    k_series = 1.0 / (f / ko + (1 - f) / ks)
    k_parallel = f * ko + (1 - f) * ks
    rho_c = f * obj.material.rho_c_jm3k + (1 - f) * soil.rho_c_jm3k
    return CellProps(k_parallel, k_series, rho_c)


class ObjectModel:
    """Repeated forward runs for objects of one radius at one site (shares the spin-up).

    Parameters are those of :func:`simulate_object`; ``object_spinup_days`` is the 2-D
    spin-up, started from the spun-up 1-D column.
    """

    def __init__(
        self,
        soil: Soil,
        forcing: Forcing,
        out_time_s: ArrayLike,
        radius_m: float,
        spinup_days: float = 2.0,
        object_spinup_days: float = 1.0,
        dt_s: float = 600.0,
        bottom: Bottom = None,
        bottom_m: float = 0.5,
        refine: int = 0,
        n_inside: int = 6,
        outer_m: float = 0.4,
    ) -> None:
        self.setup = _Setup(soil, forcing, out_time_s, spinup_days, dt_s, bottom, bottom_m,
                            refine)
        s = self.setup
        self.start = max(s.spin_steps - int(np.ceil(object_spinup_days * DAY_S / s.dt)), 1)
        self.column = s.column(keep_states=(self.start - 1, self.start))
        self.radius_m = radius_m
        self.r_faces = grids.radial_faces(radius_m, outer_m, n_inside)
        for _ in range(refine):
            self.r_faces = grids.bisect(self.r_faces)
        self.r_centres = grids.centres(self.r_faces)
        self.background_k = s.to_out(self.column.surface_k[:, 0], s.first_out)

    def surface_steps(self, obj: BuriedObject) -> np.ndarray:
        """Surface temperature per step and column, shape (N + 1 - start, Nr), K."""
        s = self.setup
        if abs(obj.radius_m - self.radius_m) > 1e-9:
            raise InvalidInput("object radius differs from the model's", field="radius_m")
        props = object_props(s.z_faces, self.r_faces, s.soil, obj)
        nr = self.r_faces.size - 1
        col = self.column
        tile = np.ones((1, nr))
        ts = col.surface_k[self.start, 0] * np.ones(nr)
        ts_prev = col.surface_k[self.start - 1, 0] * np.ones(nr)
        drive = s.drive.from_step(self.start)
        if drive.latent is not None:
            drive = replace(drive, latent=replace(drive.latent,
                                                  theta_start=col.theta[self.start, 0]))
        res = run(s.z_faces, self.r_faces, props, drive, s.dt,
                  col.states[self.start] * tile, col.states[self.start - 1] * tile,
                  surface_init_k=(ts, ts_prev))
        return res.surface_k

    def surface_at(self, obj: BuriedObject, radii_m: ArrayLike) -> np.ndarray:
        """Surface temperature at the output times and ``radii_m``, shape (T, R), K."""
        steps = self.surface_steps(obj)
        radii = np.atleast_1d(np.asarray(radii_m, dtype=float))
        rc = self.r_centres
        j = np.clip(np.searchsorted(rc, radii) - 1, 0, rc.size - 2)
        w = np.clip((radii - rc[j]) / (rc[j + 1] - rc[j]), 0.0, 1.0)
        sampled = steps[:, j] * (1 - w) + steps[:, j + 1] * w
        full = np.empty((self.setup.t.size, radii.size))
        full[self.start:] = sampled
        return self.setup.to_out(full, self.setup.first_out)


def simulate_object(
    soil: Soil,
    obj: BuriedObject,
    forcing: Forcing,
    out_time_s: ArrayLike,
    radii_m: ArrayLike = (0.0,),
    spinup_days: float = 2.0,
    object_spinup_days: float = 1.0,
    dt_s: float = 600.0,
    bottom: Bottom = None,
    bottom_m: float = 0.5,
    refine: int = 0,
) -> ObjectRun:
    """Surface temperature over and around a buried cylinder (2-D axisymmetric).

    The soil column is spun up in 1-D for ``spinup_days``, then the axisymmetric block with
    the object (out to 0.4 m beyond its rim) runs from ``object_spinup_days`` before the
    first output. About 7 ms per call on one core with the fast kernels, 33 ms with the
    reference ones (24 h of 48 scans, the 1-D spin-up included).

    Parameters
    ----------
    soil : Soil
        Host soil.
    obj : BuriedObject
        The object (depth 0 = surface-laid; the surface keeps the soil's albedo and
        emissivity over it).
    forcing : Forcing
        Weather.
    out_time_s : array_like, shape (T,)
        Output times, UTC epoch seconds.
    radii_m : array_like, shape (R,)
        Distances from the object's axis for ``surface_k``, m; beyond the block's edge the
        value is that of the outermost column.
    spinup_days, object_spinup_days, dt_s, bottom, bottom_m, refine
        As in :func:`simulate_background`; ``refine`` halves grid and step.

    Returns
    -------
    ObjectRun
    """
    model = ObjectModel(soil, forcing, out_time_s, obj.radius_m, spinup_days,
                        object_spinup_days, dt_s, bottom, bottom_m, refine)
    radii = np.atleast_1d(np.asarray(radii_m, dtype=float))
    return ObjectRun(model.setup.out, model.surface_at(obj, radii), model.background_k, radii)
