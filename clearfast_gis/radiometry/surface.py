"""Radiance leaving a grey surface: emission plus reflected sky (definition of apparent
temperature, paper section 3.6)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.radiometry.table import BandTable


def surface_leaving_radiance(
    t_k: ArrayLike, emissivity: ArrayLike, sky_radiance: ArrayLike, table: BandTable
) -> np.ndarray:
    """Band radiance leaving an opaque grey (Lambertian-reflecting) surface.

    ``L = eps B_band(T) + (1 - eps) L_sky``: emission at the surface temperature plus the
    reflected sky. The apparent temperature of the surface is the blackbody temperature of
    ``L``, so emissivity below 1 lowers it under a cold sky.

    Parameters
    ----------
    t_k : array_like
        Surface (kinetic) temperature, kelvin, e.g. (H, W).
    emissivity : array_like
        Band emissivity in [0, 1] (broadcast).
    sky_radiance : array_like
        Band radiance of the sky hemisphere seen by the surface, W m-2 sr-1 (broadcast);
        e.g. ``table.radiance(T_sky)`` for a sky of effective temperature ``T_sky``.
    table : BandTable
        The band.

    Returns
    -------
    ndarray of float64
        Surface-leaving radiance, W m-2 sr-1.
    """
    eps = np.asarray(emissivity, dtype=np.float64)
    return eps * table.radiance(t_k) + (1.0 - eps) * np.asarray(sky_radiance, dtype=np.float64)
