"""The apparent contrast: what mosaics of apparent temperature show of a kinetic contrast.

The mosaics hold apparent temperature ``T_a`` (the surface-leaving band radiance inverted as a
blackbody's). Over a buried object the surface is the soil, of band emissivity ``eps``,
reflecting the same sky ``S`` (band radiance) as its surroundings:

    L(T_a) = eps L(T) + (1 - eps) S,

so a kinetic contrast ``dT`` shows as ``dT_a = eps L'(T) / L'(T_a) dT`` (``L'`` the band
radiance's derivative). The thermal model computes kinetic contrasts: the inversion scales them
by this gain. A sandy soil's emissivity in 8-9.2 um (quartz reststrahlen) is 0.80-0.93:
unscaled, the contrast came out 10-15 % low and the mines 0.1-0.4 cm too shallow with
1.15-1.3 times their diffusivity, on the truth rasters (BENCHMARKS.md, "Depth bias by depth").

The emissivity is estimated from the survey's own records, scan by scan:

    eps = (L(T_a) - S) / (L(T) - S),

``T_a`` the mosaics' median background, ``T`` the site model's kinetic surface temperature
(fitted to the thermocouple) and ``S`` the sky's band radiance from the weather log's sky
long-wave irradiance and air temperature (:func:`sky_band_radiance`, the window apportioning of
:mod:`clearfast_gis.simulate.sky`: a documented clear-sky rule, the same one the simulator's
twin renders its sky with, fed here by the logged channels only). The median over the scans
whose ground is at least :data:`MIN_SKY_GAP_K` warmer than the sky's band brightness is kept
(near it the ratio is 0 / 0). Without the sky term (``S = 0``) the ratio over-estimates
``eps`` by ``(1 - eps) S / L(T)`` and recovered about a third of the gain on the demo surveys.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.radiometry.planck import (
    band_radiance,
    band_radiance_derivative,
    band_temperature,
)
from clearfast_gis.simulate.sky import sky_band_emissivity
from clearfast_gis.thermal.forcing import Forcing

EMISSIVITY_RANGE = (0.5, 1.0)
"""Bounds of the estimated band emissivity."""

MIN_SKY_GAP_K = 5.0
"""Least excess, K, of the ground's kinetic temperature over the sky's band brightness
temperature for a scan to give an emissivity (the ratio's denominator)."""


def sky_band_radiance(forcing: Forcing, time_s: ArrayLike, lambda_min_um: float,
                      lambda_max_um: float) -> np.ndarray:
    """The sky's band radiance (W m-2 sr-1) at ``time_s`` (S,) UTC epoch s, from the logged sky
    long-wave irradiance and air temperature: ``eps_band B_band(T_air)``
    (:func:`clearfast_gis.simulate.sky.sky_band_emissivity`); band edges in micrometres."""
    at = forcing.at(np.asarray(time_s, dtype=float))
    return sky_band_emissivity(at["sky_lw_wm2"], at["air_temp_k"]) \
        * band_radiance(at["air_temp_k"], lambda_min_um, lambda_max_um)


def band_emissivity_estimate(background_app_k: ArrayLike, surface_k: ArrayLike,
                             sky_radiance: ArrayLike, lambda_min_um: float,
                             lambda_max_um: float) -> float:
    """The ground's band emissivity from its apparent and kinetic temperature and the sky.

    Parameters
    ----------
    background_app_k, surface_k : array_like, shape (S,)
        The mosaics' background apparent temperature and the site model's kinetic surface
        temperature per scan, K (NaN where unknown).
    sky_radiance : array_like, shape (S,) or scalar
        The sky's band radiance per scan, W m-2 sr-1 (0: no reflected sky).
    lambda_min_um, lambda_max_um : float
        The band, micrometres.

    Returns
    -------
    float
        Median over the usable scans of ``(L(T_a) - S) / (L(T) - S)``, clipped to
        :data:`EMISSIVITY_RANGE`; NaN when no scan is usable.
    """
    ta = np.asarray(background_app_k, dtype=float)
    t = np.asarray(surface_k, dtype=float)
    s = np.broadcast_to(np.asarray(sky_radiance, dtype=float), ta.shape)
    ok = np.isfinite(ta) & np.isfinite(t) & np.isfinite(s) & (ta > 0) & (t > 0)
    if not ok.any():
        return float("nan")
    l_t = band_radiance(t[ok], lambda_min_um, lambda_max_um)
    s_ok = s[ok]
    sky_t = np.where(s_ok > 0, band_temperature(np.maximum(s_ok, 1e-9), lambda_min_um,
                                                lambda_max_um), 0.0)
    use = t[ok] - sky_t >= MIN_SKY_GAP_K
    if not use.any():
        return float("nan")
    ratio = (band_radiance(ta[ok], lambda_min_um, lambda_max_um) - s_ok) / (l_t - s_ok)
    return float(np.clip(np.median(ratio[use]), *EMISSIVITY_RANGE))


def apparent_gain(background_app_k: ArrayLike, surface_k: ArrayLike, lambda_min_um: float,
                  lambda_max_um: float, sky_radiance: ArrayLike = 0.0) -> np.ndarray:
    """Per-scan gain (S,) from a kinetic contrast to the apparent contrast in a band.

    Parameters
    ----------
    background_app_k : array_like, shape (S,)
        The mosaics' background apparent temperature per scan, K (NaN where unknown).
    surface_k : array_like, shape (S,)
        The site model's kinetic surface temperature at the same scans, K.
    lambda_min_um, lambda_max_um : float
        The band, micrometres.
    sky_radiance : array_like, shape (S,) or scalar
        The sky's band radiance per scan, W m-2 sr-1 (:func:`sky_band_radiance`); 0 takes the
        reflected sky as nothing (an over-estimate of the emissivity, module notes).

    Returns
    -------
    ndarray, shape (S,)
        ``eps L'(T) / L'(T_a)`` (module notes); 1 where ``T_a`` is unknown, all 1 when no
        scan gives an emissivity.
    """
    ta = np.asarray(background_app_k, dtype=float)
    t = np.asarray(surface_k, dtype=float)
    eps = band_emissivity_estimate(ta, t, sky_radiance, lambda_min_um, lambda_max_um)
    gain = np.ones(ta.shape)
    if not np.isfinite(eps):
        return gain
    ok = np.isfinite(ta) & np.isfinite(t) & (ta > 0) & (t > 0)
    gain[ok] = eps * band_radiance_derivative(t[ok], lambda_min_um, lambda_max_um) \
        / band_radiance_derivative(ta[ok], lambda_min_um, lambda_max_um)
    return gain
