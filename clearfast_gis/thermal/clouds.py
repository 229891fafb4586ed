"""Clouds: how a cloud cover fraction changes the sun and the sky the ground sees.

- Short-wave (Kasten & Czeplak 1980, Solar Energy 24, 177-189): global irradiance under a
  cloud cover fraction N (0 clear .. 1 overcast) is ``G = G_clear (1 - 0.75 N^3.4)``; a full
  overcast lets 25 % through.
- Long-wave: the clear-sky emissivity (Brutsaert 1975, :func:`clear_sky_emissivity`) raised by
  the cloud base's emission, ``eps = eps_clear (1 + 0.22 N^2)`` (Bolz 1949, as used by
  TVA 1972 and Iziomon et al. 2003, J. Atmos. Sol.-Terr. Phys. 65, 1107-1116), at most 1.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.thermal.forcing import clear_sky_emissivity
from clearfast_gis.units import STEFAN_BOLTZMANN


def cloud_solar_factor(cloud_cover: ArrayLike) -> np.ndarray:
    """Share of the clear-sky global irradiance that reaches the ground, ``1 - 0.75 N^3.4``."""
    n = np.clip(np.asarray(cloud_cover, dtype=float), 0.0, 1.0)
    return 1.0 - 0.75 * n**3.4


def cloudy_sky_emissivity(air_temp_k: ArrayLike, rh_pct: ArrayLike,
                          cloud_cover: ArrayLike) -> np.ndarray:
    """Sky emissivity under a cloud cover N: ``eps_clear (1 + 0.22 N^2)``, at most 1."""
    n = np.clip(np.asarray(cloud_cover, dtype=float), 0.0, 1.0)
    return np.minimum(clear_sky_emissivity(air_temp_k, rh_pct) * (1.0 + 0.22 * n**2), 1.0)


def cloudy_sky_longwave(air_temp_k: ArrayLike, rh_pct: ArrayLike,
                        cloud_cover: ArrayLike) -> np.ndarray:
    """Down-welling long-wave irradiance under a cloud cover N, W m-2."""
    t = np.asarray(air_temp_k, dtype=float)
    return cloudy_sky_emissivity(t, rh_pct, cloud_cover) * STEFAN_BOLTZMANN * t**4
