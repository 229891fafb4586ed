"""Atmospheric transmittance and path radiance over a short horizontal or slant path (Eq. 4).

MODTRAN (the paper's model) is not available; the band transmittance is the water-vapour model
that radiometric long-wave thermal cameras use (FLIR Systems; published in W. Minkina and
S. Dudzik, *Infrared Thermography: Errors and Uncertainties*, Wiley 2009, section 2.4):

    tau = X exp(-sqrt(d) (a1 + b1 sqrt(w))) + (1 - X) exp(-sqrt(d) (a2 + b2 sqrt(w)))

with ``d`` the path length in metres and ``w`` the water-vapour content from relative humidity
``RH`` (%) and air temperature ``t`` (degrees C) by FLIR's saturation fit

    w = RH / 100 * exp(1.5587 + 6.939e-2 t - 2.7816e-4 t^2 + 6.8455e-7 t^3)

(``w`` ~ 17.1 at 20 degrees C and saturation, close to both the saturation vapour pressure in
mmHg and the saturation vapour density in g m-3). Constants, as stored by FLIR cameras in
their radiometric metadata (``AtmosphericTransX/Alpha1/Alpha2/Beta1/Beta2``):
``X = 1.9, a1 = 0.006569, a2 = 0.01262, b1 = -0.002276, b2 = -0.00667`` (per sqrt(m)).
The constants describe the 7.5-13 um long-wave window; the model is used for bands inside
7.5-14 um only.

Pressure scaling (this package's addition, the model itself is for sea level): in the
strong-line (square-root) regime of pressure-broadened lines the band absorption scales with
``sqrt(p / p0)`` (Goody and Yung, *Atmospheric Radiation*, 2nd ed., 1989, section 4.4), so the
exponents are multiplied by ``sqrt(p / 1013.25 hPa)``.

For 20 m in humid mild air (20-30 degrees C, 80-90 % RH) the model gives 3.4-4.8 % attenuation;
the paper quotes "in the order of 10 %" for MODTRAN at ~20 m.

Path radiance is the emission of an isothermal path at air temperature: ``I_a = (1 - tau)
B_band(T_air)``; the camera sees ``I_c = tau I_surf + I_a`` (Eq. 4).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry.table import BandTable
from clearfast_gis.units import STANDARD_PRESSURE_HPA

FLIR_X = 1.9
FLIR_A1_PER_SQRT_M = 0.006569
FLIR_A2_PER_SQRT_M = 0.01262
FLIR_B1 = -0.002276
FLIR_B2 = -0.00667
LW_WINDOW_UM = (7.5, 14.0)
"""Band limits (um) inside which the long-wave constants apply."""
MAX_PATH_M = 1000.0
"""Longest path the model is used for, metres."""


def water_vapour_content(t_air_k: ArrayLike, rh_pct: ArrayLike) -> np.ndarray:
    """FLIR's water-vapour content ``w`` from air temperature and relative humidity.

    Parameters
    ----------
    t_air_k : array_like
        Air temperature, kelvin.
    rh_pct : array_like
        Relative humidity, percent (0-100); broadcast against ``t_air_k``.

    Returns
    -------
    ndarray of float64
        ``w`` (about mmHg of vapour pressure), shape of the broadcast inputs.
    """
    t_c = np.asarray(t_air_k, dtype=np.float64) - 273.15
    rh = np.asarray(rh_pct, dtype=np.float64)
    return rh / 100.0 * np.exp(1.5587 + 6.939e-2 * t_c - 2.7816e-4 * t_c**2
                               + 6.8455e-7 * t_c**3)


def atmospheric_transmittance(
    path_m: ArrayLike,
    t_air_k: ArrayLike,
    rh_pct: ArrayLike,
    pressure_hpa: ArrayLike,
    lambda_min_um: float,
    lambda_max_um: float,
) -> np.ndarray:
    """Band transmittance of an air path (see the module notes for model and sources).

    Parameters
    ----------
    path_m : array_like
        Path length camera-to-surface, metres (0 to 1000), e.g. (P, H, W) slant ranges.
    t_air_k : array_like
        Air temperature, kelvin.
    rh_pct : array_like
        Relative humidity, percent.
    pressure_hpa : array_like
        Air pressure, hPa.
    lambda_min_um, lambda_max_um : float
        Band limits, micrometres; must lie inside 7.5-14 um.

    Returns
    -------
    ndarray of float64
        Transmittance in (0, 1], shape of the broadcast inputs; NaN where an input is NaN.
    """
    lo, hi = LW_WINDOW_UM
    if not (lo <= lambda_min_um < lambda_max_um <= hi):
        raise InvalidInput(
            f"the transmittance model covers {lo}-{hi} um, band is "
            f"{lambda_min_um}-{lambda_max_um} um", field="band")
    d = np.asarray(path_m, dtype=np.float64)
    if np.any(d < 0) or np.any(d > MAX_PATH_M):
        raise InvalidInput(f"path length must be within 0-{MAX_PATH_M:g} m", field="path_m")
    rh = np.asarray(rh_pct, dtype=np.float64)
    if np.any(rh < 0) or np.any(rh > 100):
        raise InvalidInput("relative humidity must be within 0-100 %", field="rh_pct")
    p = np.asarray(pressure_hpa, dtype=np.float64)
    if np.any(p <= 0):
        raise InvalidInput("pressure must be positive", field="pressure_hpa")
    tau = water_vapour_transmittance(d * (p / STANDARD_PRESSURE_HPA),
                                     water_vapour_content(t_air_k, rh))
    return np.clip(tau, 1e-6, 1.0)


def water_vapour_transmittance(
    path_m: ArrayLike,
    w: ArrayLike,
    x: float = FLIR_X,
    a1: float = FLIR_A1_PER_SQRT_M,
    a2: float = FLIR_A2_PER_SQRT_M,
    b1: float = FLIR_B1,
    b2: float = FLIR_B2,
) -> np.ndarray:
    """The two-term water-vapour transmittance ``X exp(-sqrt(d)(a1 + b1 sqrt(w))) + ...``.

    The one definition of the model's formula (module notes), used with the defaults by
    :func:`atmospheric_transmittance` and with a camera's own stored constants by
    :mod:`clearfast_gis.radiometry.flir`.

    Parameters
    ----------
    path_m : array_like
        Path length ``d``, metres (already scaled for pressure where wanted).
    w : array_like
        Water-vapour content from :func:`water_vapour_content` (broadcast).
    x, a1, a2, b1, b2 : float
        The model's constants (``a``, ``b`` per sqrt(m)).

    Returns
    -------
    ndarray of float64
        Transmittance (not clipped), shape of the broadcast inputs.
    """
    s = np.sqrt(np.asarray(path_m, dtype=np.float64))
    sw = np.sqrt(np.asarray(w, dtype=np.float64))
    return x * np.exp(-s * (a1 + b1 * sw)) + (1.0 - x) * np.exp(-s * (a2 + b2 * sw))


def path_radiance(tau: ArrayLike, t_air_k: ArrayLike, table: BandTable) -> np.ndarray:
    """Radiance emitted by an isothermal air path, ``I_a = (1 - tau) B_band(T_air)``.

    Parameters
    ----------
    tau : array_like
        Band transmittance.
    t_air_k : array_like
        Air temperature, kelvin (broadcast against ``tau``).
    table : BandTable
        The band.

    Returns
    -------
    ndarray of float64
        Path radiance, W m-2 sr-1.
    """
    return (1.0 - np.asarray(tau, dtype=np.float64)) * table.radiance(t_air_k)


def observed_radiance(
    surface_radiance: ArrayLike, tau: ArrayLike, t_air_k: ArrayLike, table: BandTable
) -> np.ndarray:
    """Radiance reaching the camera (Eq. 4 forward): ``I_c = tau I_surf + (1 - tau) B(T_air)``.

    Parameters
    ----------
    surface_radiance : array_like
        Radiance leaving the surface towards the camera, W m-2 sr-1, e.g. (P, H, W).
    tau : array_like
        Band transmittance of the path (broadcast).
    t_air_k : array_like
        Air temperature, kelvin (broadcast).
    table : BandTable
        The band.

    Returns
    -------
    ndarray of float64
        At-camera radiance, W m-2 sr-1.
    """
    tau = np.asarray(tau, dtype=np.float64)
    return tau * np.asarray(surface_radiance, dtype=np.float64) + path_radiance(
        tau, t_air_k, table)


def correct_atmosphere(
    radiance: ArrayLike, tau: ArrayLike, t_air_k: ArrayLike, table: BandTable
) -> np.ndarray:
    """Surface radiance from calibrated radiance (Eq. 4 solved): ``(I_c - I_a) / tau``.

    Parameters
    ----------
    radiance : array_like
        Calibrated at-camera radiance ``I_c``, W m-2 sr-1, e.g. (P, H, W).
    tau : array_like
        Band transmittance, in (0, 1] (broadcast).
    t_air_k : array_like
        Air temperature, kelvin (broadcast).
    table : BandTable
        The band.

    Returns
    -------
    ndarray
        Surface radiance ``I_surf``, W m-2 sr-1, float32 for float32 input, else float64;
        NaN stays NaN.
    """
    r = np.asarray(radiance)
    dtype = np.float32 if r.dtype == np.float32 else np.float64
    tau = np.asarray(tau, dtype=np.float64)
    i_a = path_radiance(tau, t_air_k, table)
    return ((r.astype(np.float64) - i_a) / tau).astype(dtype, copy=False)
