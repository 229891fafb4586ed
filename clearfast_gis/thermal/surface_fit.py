"""Surface-flux parameters from mine-free background pixels or a shallow thermocouple.

Two fits of the 1-D model (:func:`clearfast_gis.thermal.forward.simulate_background`) to a
measured temperature of undisturbed soil:

- :func:`fit_surface_parameters`: albedo and convective scale (a dry surface), for the
  mosaics' background when no thermocouple is logged;
- :func:`fit_surface_balance`: albedo, convective scale, the surface's wetness (its latent
  heat) and the soil's volumetric heat capacity at the thermocouples' diffusivity, for a
  shallow thermocouple. A dry model fitted to a soil that evaporates moves the latent heat
  into the albedo (clay, demo seed 10: albedo 0.48 against 0.17, residual 0.56 K against
  0.06 K) and puts buried mines 1-2 cm too shallow; the heat capacity matters because the
  object's contrast follows the conductivity ratio, and the thermocouples give only the
  diffusivity (docs/thermal.md, "Inverse chain").
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np
from numpy.typing import ArrayLike
from scipy.optimize import least_squares

from clearfast_gis.errors import InvalidInput
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.thermal.forward import Bottom, simulate_background
from clearfast_gis.thermal.materials import Soil
from clearfast_gis.thermal.moisture import surface_water_of_wetness

ALBEDO_BOUNDS = (0.02, 0.7)
"""Fitted albedo range."""
HC_SCALE_BOUNDS = (0.2, 5.0)
"""Fitted convective scale range (multiplier on ``h_c``)."""
WETNESS_BOUNDS = (0.0, 1.5)
"""Fitted surface wetness range, theta / theta_fc (at 1 and above: the potential rate)."""
HEAT_CAPACITY_BOUNDS_JM3K = (0.9e6, 3.2e6)
"""Fitted soil heat capacity range, J m-3 K-1 (the soil types' dry 0.96 to saturated 3.05
MJ m-3 K-1, ``thermal/soils.py``)."""
WET_RMS_RATIO = 0.8
"""The surface is modelled wet (latent heat, dew, a fitted heat capacity) only when the wet
fit leaves at most this share of the dry fit's rms misfit. On the demo surveys of seeds 10 and
11 the evaporating soils (clay, loam, the tropics, both southern seasons, evaporating sand)
gave 0.06-0.13 (0.05-0.37 against a dry fit with its heat capacity free) and the twin's
water-free sand, with and without grass, 0.96-1.00; a wet model there adds dew the soil does
not have (it lowered the clear day's modelled contrast by 4 %)."""
WETNESS_STARTS = (0.05, 0.5, 1.0)
"""Starting wetnesses of the balance fit (the wetness factor is flat near 0 and above 1, so
one start can stall); the best of the fits is kept."""


def _checked(time_s: ArrayLike, temp_k: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Times and temperatures (valid samples only), at least 4."""
    t = np.asarray(time_s, dtype=float)
    obs = np.asarray(temp_k, dtype=float)
    if t.ndim != 1 or obs.shape != t.shape or t.size < 4:
        raise InvalidInput("need >= 4 scans with one temperature each", field="background_k")
    ok = np.isfinite(obs)
    if ok.sum() < 4:
        raise InvalidInput("fewer than 4 valid temperatures", field="background_k")
    return t[ok], obs[ok]


def _model_temperature(soil: Soil, forcing: Forcing, t: np.ndarray, depth_m: float,
                       bottom: Bottom, dt_s: float) -> np.ndarray:
    """The 1-D model's temperature (K) at ``depth_m`` (0: the surface) at ``t``."""
    if depth_m > 0:
        return simulate_background(soil, forcing, t, depths_m=(depth_m,), bottom=bottom,
                                   dt_s=dt_s).profile_k[:, 0]
    return simulate_background(soil, forcing, t, bottom=bottom, dt_s=dt_s).surface_k


def _albedo_hc_start(soil: Soil) -> list[float]:
    """Starting albedo and log ``hc_scale`` of a fit: the soil's, just inside the bounds."""
    return [float(np.clip(soil.albedo, ALBEDO_BOUNDS[0] + 0.01, ALBEDO_BOUNDS[1] - 0.01)),
            float(np.clip(np.log(soil.hc_scale), np.log(HC_SCALE_BOUNDS[0] + 0.01),
                          np.log(HC_SCALE_BOUNDS[1] - 0.1)))]


def _best_fit(model: Callable[[np.ndarray], Soil], starts: list[list[float]], bounds,
              forcing: Forcing, t: np.ndarray, obs: np.ndarray, depth_m: float,
              bottom: Bottom, dt_s: float) -> tuple[Soil, float]:
    """The least-squares fit of ``model``'s parameters to ``obs`` (K at ``depth_m``, times
    ``t``) from each start in turn; the least costly one, with its rms misfit (K)."""

    def resid(p: np.ndarray) -> np.ndarray:
        return _model_temperature(model(p), forcing, t, depth_m, bottom, dt_s) - obs

    best = None
    for start in starts:
        sol = least_squares(resid, start, bounds=bounds, diff_step=1e-3)
        if best is None or sol.cost < best.cost:
            best = sol
    return model(best.x), float(np.sqrt(np.mean(best.fun**2)))


def fit_surface_parameters(
    soil: Soil,
    forcing: Forcing,
    time_s: ArrayLike,
    background_k: ArrayLike,
    bottom: Bottom = None,
    dt_s: float = 600.0,
    depth_m: float = 0.0,
) -> tuple[Soil, float]:
    """Albedo and convective scale that make the 1-D model match the background surface
    (``depth_m = 0``) or a thermocouple at ``depth_m`` below it.

    Parameters
    ----------
    soil : Soil
        Soil with its (fitted) diffusivity; albedo and ``hc_scale`` are the starting point.
    forcing : Forcing
        Weather.
    time_s : array_like, shape (S,)
        Scan times, UTC epoch seconds.
    background_k : array_like, shape (S,)
        Measured temperature of undisturbed soil at ``depth_m``, K: the surface (e.g. the
        median of mine-free pixels, an apparent temperature) or a shallow thermocouple (a
        kinetic temperature, free of the surface's emissivity and reflected sky).
    bottom : Bottom
        Bottom boundary of the model.
    dt_s : float
        Model time step, s.
    depth_m : float
        Depth of the measured temperature, m (0 = surface).

    Returns
    -------
    soil : Soil
        ``soil`` with the fitted ``albedo`` (0.02-0.7) and ``hc_scale`` (0.2-5).
    rms_k : float
        Root-mean-square misfit left, K.
    """
    t, obs = _checked(time_s, background_k)

    def model(p: np.ndarray) -> Soil:
        return replace(soil, albedo=float(p[0]), hc_scale=float(np.exp(p[1])))

    bounds = ([ALBEDO_BOUNDS[0], np.log(HC_SCALE_BOUNDS[0])],
              [ALBEDO_BOUNDS[1], np.log(HC_SCALE_BOUNDS[1])])
    return _best_fit(model, [_albedo_hc_start(soil)], bounds, forcing, t, obs, depth_m,
                     bottom, dt_s)


def fit_surface_balance(
    soil: Soil,
    forcing: Forcing,
    time_s: ArrayLike,
    temp_k: ArrayLike,
    depth_m: float,
    bottom: Bottom = None,
    dt_s: float = 600.0,
) -> tuple[Soil, float]:
    """Albedo, convective scale, heat capacity and, when the soil evaporates, the surface
    wetness that make the 1-D model match a thermocouple at ``depth_m``, the diffusivity
    held.

    Two fits: a wet surface (albedo, convective scale, wetness, heat capacity) and a dry one
    (:func:`fit_surface_parameters`: albedo and convective scale, ``soil``'s heat capacity);
    the wet one is kept when it leaves at most :data:`WET_RMS_RATIO` of the dry one's rms
    misfit. The latent heat follows
    :mod:`clearfast_gis.thermal.moisture` with the logged humidity and rain; the surface
    layer is the generic one of
    :func:`~clearfast_gis.thermal.moisture.surface_water_of_wetness` (the texture is not
    known). The conductivity moves with the heat capacity (``k = alpha rho c``).

    Parameters
    ----------
    soil : Soil
        Soil with its fitted diffusivity (kept); its heat capacity and albedo are the start.
    forcing : Forcing
        Weather (air temperature, humidity, wind, sun, sky, rain from the weather log).
    time_s : array_like, shape (S,)
        Sample times, UTC epoch seconds.
    temp_k : array_like, shape (S,)
        Thermocouple temperature (kinetic), K.
    depth_m : float
        Thermocouple depth, m (> 0).
    bottom : Bottom
        Bottom boundary of the model.
    dt_s : float
        Model time step, s.

    Returns
    -------
    soil : Soil
        ``soil`` with the fitted ``albedo``, ``hc_scale`` and, for a wet surface, ``water``
        (wetness :data:`WETNESS_BOUNDS`) and ``rho_c_jm3k`` / ``k_wmk``
        (:data:`HEAT_CAPACITY_BOUNDS_JM3K`); a dry surface keeps ``soil``'s (no water).
    rms_k : float
        Root-mean-square misfit left, K.
    """
    if not depth_m > 0:
        raise InvalidInput("the balance fit needs a thermocouple below the surface",
                           field="depth_m")
    t, obs = _checked(time_s, temp_k)
    alpha = soil.alpha_m2s

    def model(p: np.ndarray) -> Soil:
        """p: albedo, log hc_scale, wetness, heat capacity (MJ m-3 K-1)."""
        rho_c = float(p[3]) * 1e6
        return replace(soil, albedo=float(p[0]), hc_scale=float(np.exp(p[1])),
                       water=surface_water_of_wetness(float(p[2])), rho_c_jm3k=rho_c,
                       k_wmk=alpha * rho_c)

    lo = [ALBEDO_BOUNDS[0], np.log(HC_SCALE_BOUNDS[0]), WETNESS_BOUNDS[0],
          HEAT_CAPACITY_BOUNDS_JM3K[0] / 1e6]
    hi = [ALBEDO_BOUNDS[1], np.log(HC_SCALE_BOUNDS[1]), WETNESS_BOUNDS[1],
          HEAT_CAPACITY_BOUNDS_JM3K[1] / 1e6]
    rho_c0 = float(np.clip(soil.rho_c_jm3k / 1e6, lo[3] + 0.01, hi[3] - 0.01))
    starts = [[*_albedo_hc_start(soil), w0, rho_c0] for w0 in WETNESS_STARTS]
    wet, rms_wet = _best_fit(model, starts, (lo, hi), forcing, t, obs, depth_m, bottom, dt_s)
    dry, rms_dry = fit_surface_parameters(soil, forcing, t, obs, bottom, dt_s, depth_m)
    if rms_wet > WET_RMS_RATIO * rms_dry:
        return dry, rms_dry
    return wet, rms_wet
