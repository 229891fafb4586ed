"""The apparent contrast: what mosaics of apparent temperature show of a kinetic contrast.

The mosaics hold apparent temperature ``T_a`` (the band radiance inverted as a blackbody's). Over
a buried object the surface is the soil, of band emissivity ``eps``, reflecting the same sky as
its surroundings, so a kinetic contrast ``dT`` shows as ``dT_a = eps L'(T) / L'(T_a) dT``
(``L'`` the band radiance's derivative). The thermal model computes kinetic contrasts: the
inversion scales them by this gain. A sandy soil's emissivity in 8-9.2 um (quartz
reststrahlen) is 0.80-0.93: unscaled, the contrast came out 10-15 % low and the mines 0.1-0.4
cm too shallow with 1.15-1.3 times their diffusivity, on the truth rasters (BENCHMARKS.md,
"Depth bias by depth").

The emissivity is estimated from the survey itself: ``L(T_a) = eps L(T) + (1 - eps) S``, with
``T_a`` the mosaics' median background and ``T`` the site model's surface temperature (fitted
to the thermocouple), taking the reflected sky ``S`` as 0: ``eps ~ L(T_a) / L(T)``, the
median over the scans. The sky's share makes this an over-estimate by ``(1 - eps) S / L(T)``
(about 0.03 for a sand under a clear sky in 8-9.2 um, whose sky is some 50 K colder than the
ground): the gain is corrected most of the way, not all.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.radiometry.planck import band_radiance, band_radiance_derivative

EMISSIVITY_RANGE = (0.5, 1.0)
"""Bounds of the estimated band emissivity."""


def apparent_gain(background_app_k: ArrayLike, surface_k: ArrayLike, lambda_min_um: float,
                  lambda_max_um: float) -> np.ndarray:
    """Per-scan gain (S,) from a kinetic contrast to the apparent contrast in a band.

    Parameters
    ----------
    background_app_k : array_like, shape (S,)
        The mosaics' background apparent temperature per scan, K (NaN where unknown).
    surface_k : array_like, shape (S,)
        The site model's kinetic surface temperature at the same scans, K.
    lambda_min_um, lambda_max_um : float
        The band, micrometres.

    Returns
    -------
    ndarray, shape (S,)
        ``eps L'(T) / L'(T_a)`` (module notes); 1 where ``T_a`` is unknown, all 1 when no
        scan gives an emissivity.
    """
    ta = np.asarray(background_app_k, dtype=float)
    t = np.asarray(surface_k, dtype=float)
    ok = np.isfinite(ta) & np.isfinite(t) & (ta > 0) & (t > 0)
    if not ok.any():
        return np.ones(ta.shape)
    ratio = band_radiance(ta[ok], lambda_min_um, lambda_max_um) \
        / band_radiance(t[ok], lambda_min_um, lambda_max_um)
    eps = float(np.clip(np.median(ratio), *EMISSIVITY_RANGE))
    gain = np.ones(ta.shape)
    gain[ok] = eps * band_radiance_derivative(t[ok], lambda_min_um, lambda_max_um) \
        / band_radiance_derivative(ta[ok], lambda_min_um, lambda_max_um)
    return gain
