"""Band radiance of the clear sky, apportioned from the broadband sky long-wave irradiance.

The weather station (and the forcing) give the hemispherical sky long-wave irradiance
``E_sky`` (W m-2, 4-100 um). Its broadband effective emissivity is
``eps_sky = E_sky / (sigma T_air^4)`` (0.7-0.85 for a clear sky). Inside the 8-13 um window
the clear sky is far more transparent than on average: the opaque water-vapour and CO2 bands
outside the window carry most of ``E_sky``. Following the two-stream window split of
Brunt-type clear-sky models (e.g. Berdahl & Martin 1984, Sol. Energy 32, which give window
emissivities of 0.2-0.5 for broadband values of 0.7-0.85), the window's band emissivity is

    eps_band = 1 - k (1 - eps_sky),   k = 2.5, clipped to [0.05, 1],

so a sky of broadband emissivity 0.78 has a window emissivity of 0.45, and an overcast sky
(eps_sky -> 1) becomes a black body at air temperature in every band. The sky band radiance
(isotropic hemisphere, as seen by a Lambertian reflector) is then
``L_sky = eps_band B_band(T_air)``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.radiometry.table import BandTable
from clearfast_gis.units import STEFAN_BOLTZMANN

#: Window-opacity ratio k of the apportioning rule.
WINDOW_FACTOR = 2.5


def sky_band_emissivity(sky_lw_wm2: ArrayLike, t_air_k: ArrayLike) -> np.ndarray:
    """Clear-sky emissivity inside the long-wave window from the broadband sky irradiance.

    Parameters
    ----------
    sky_lw_wm2 : array_like
        Sky long-wave irradiance, W m-2.
    t_air_k : array_like
        Air temperature near the ground, kelvin.

    Returns
    -------
    ndarray
        Band emissivity of the sky hemisphere, 0.05-1.
    """
    eps = np.asarray(sky_lw_wm2, float) / (STEFAN_BOLTZMANN * np.asarray(t_air_k, float) ** 4)
    return np.clip(1.0 - WINDOW_FACTOR * (1.0 - np.clip(eps, 0.0, 1.0)), 0.05, 1.0)


def sky_band_radiance(sky_lw_wm2: ArrayLike, t_air_k: ArrayLike, table: BandTable) -> np.ndarray:
    """Sky band radiance ``eps_band B_band(T_air)``, W m-2 sr-1 (see the module notes)."""
    return sky_band_emissivity(sky_lw_wm2, t_air_k) * table.radiance(t_air_k)
