"""Surface-flux parameters from mine-free background pixels or a shallow thermocouple."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numpy.typing import ArrayLike
from scipy.optimize import least_squares

from clearfast_gis.errors import InvalidInput
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.thermal.forward import Bottom, simulate_background
from clearfast_gis.thermal.materials import Soil


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
    t = np.asarray(time_s, dtype=float)
    obs = np.asarray(background_k, dtype=float)
    if t.ndim != 1 or obs.shape != t.shape or t.size < 4:
        raise InvalidInput("need >= 4 scans with one temperature each", field="background_k")
    ok = np.isfinite(obs)
    if ok.sum() < 4:
        raise InvalidInput("fewer than 4 valid temperatures", field="background_k")

    def model(p: np.ndarray) -> Soil:
        return replace(soil, albedo=float(p[0]), hc_scale=float(np.exp(p[1])))

    def resid(p: np.ndarray) -> np.ndarray:
        if depth_m > 0:
            run = simulate_background(model(p), forcing, t[ok], depths_m=(depth_m,),
                                      bottom=bottom, dt_s=dt_s)
            return run.profile_k[:, 0] - obs[ok]
        run = simulate_background(model(p), forcing, t[ok], bottom=bottom, dt_s=dt_s)
        return run.surface_k - obs[ok]

    x0 = [float(np.clip(soil.albedo, 0.03, 0.69)),
          float(np.clip(np.log(soil.hc_scale), np.log(0.21), np.log(4.9)))]
    sol = least_squares(resid, x0, bounds=([0.02, np.log(0.2)], [0.7, np.log(5.0)]),
                        diff_step=1e-3)
    return model(sol.x), float(np.sqrt(np.mean(sol.fun**2)))
