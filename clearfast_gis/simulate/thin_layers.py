"""Surface temperature of thin layers: vegetation canopies and marker plates.

Both have negligible heat capacity on the scale of the survey's time steps (a leaf's time
constant is seconds, a 5 mm plate's a few minutes), so their temperature is the root of a
steady energy balance, solved by Newton iterations vectorised over time.

- Canopy (a leaf layer seen from above, exchanging on both faces; Campbell & Norman 1998,
  *An Introduction to Environmental Biophysics*, ch. 14)::

      a_s S + eps (E_sky + sigma T_g^4) = 2 eps sigma T^4 + 2 h_c (T - T_air) + LE

  with solar absorptance ``a_s = 0.5``, ``LE = 0.35 a_s S`` (transpiration), ``h_c = 5.7 +
  3.8 v`` per face and ``T_g`` the soil surface beneath.
- Plate lying on the ground (top face exchanges with sky and air, bottom face with the soil
  through a contact conductance ``h_g = 15`` W m-2 K-1)::

      (1 - A) S + eps E_sky = eps sigma T^4 + h_c (T - T_air) + h_g (T - T_g)
"""

from __future__ import annotations

import numpy as np

from clearfast_gis.thermal.canopy import LEAF_EMISSIVITY
from clearfast_gis.units import STEFAN_BOLTZMANN as SIGMA

LEAF_SOLAR_ABSORPTANCE = 0.5
LEAF_LATENT_FRACTION = 0.35
PLATE_CONTACT_WM2K = 15.0


def _solve(gain: np.ndarray, rad_coef: float, lin_coef: np.ndarray, t0: np.ndarray) -> np.ndarray:
    """Root of ``gain = rad_coef sigma T^4 + lin_coef T`` by Newton from ``t0``."""
    t = np.asarray(t0, float).copy()
    for _ in range(8):
        f = rad_coef * SIGMA * t**4 + lin_coef * t - gain
        t = t - f / (4.0 * rad_coef * SIGMA * t**3 + lin_coef)
    return t


def leaf_temperature_k(solar_wm2: np.ndarray, sky_lw_wm2: np.ndarray, air_temp_k: np.ndarray,
                       wind_ms: np.ndarray, ground_k: np.ndarray) -> np.ndarray:
    """Canopy temperature, kelvin, for forcing arrays of shape (T,) (see the module notes).

    Parameters
    ----------
    solar_wm2, sky_lw_wm2 : ndarray (T,)
        Global solar and sky long-wave irradiance, W m-2.
    air_temp_k : ndarray (T,)
        Air temperature, kelvin.
    wind_ms : ndarray (T,)
        Wind speed, m/s.
    ground_k : ndarray (T,)
        Soil surface temperature beneath the canopy, kelvin.
    """
    h_c = 5.7 + 3.8 * np.asarray(wind_ms, float)
    a_s = LEAF_SOLAR_ABSORPTANCE
    eps = LEAF_EMISSIVITY
    gain = (a_s * (1.0 - LEAF_LATENT_FRACTION) * solar_wm2
            + eps * (sky_lw_wm2 + SIGMA * np.asarray(ground_k, float) ** 4)
            + 2.0 * h_c * air_temp_k)
    return _solve(gain, 2.0 * eps, 2.0 * h_c, air_temp_k)


def plate_temperature_k(solar_wm2: np.ndarray, sky_lw_wm2: np.ndarray, air_temp_k: np.ndarray,
                        wind_ms: np.ndarray, ground_k: np.ndarray, albedo: float,
                        emissivity: float) -> np.ndarray:
    """Temperature of a thin plate lying on the soil, kelvin, for forcing arrays (T,).

    Parameters are as for :func:`leaf_temperature_k`, plus the plate's solar ``albedo`` and
    thermal ``emissivity`` (broadband).
    """
    h_c = 5.7 + 3.8 * np.asarray(wind_ms, float)
    gain = ((1.0 - albedo) * solar_wm2 + emissivity * sky_lw_wm2 + h_c * air_temp_k
            + PLATE_CONTACT_WM2K * np.asarray(ground_k, float))
    return _solve(gain, emissivity, h_c + PLATE_CONTACT_WM2K, np.asarray(ground_k, float))
