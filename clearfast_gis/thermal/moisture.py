"""Water at the soil surface: vapour pressure, dew point, evaporation and the wet layer.

The latent heat flux of a bare soil follows the bulk transfer formula with the Lewis analogy
(heat and vapour carried by the same eddies) and a surface wetness factor::

    LE = beta(theta) * h_c / gamma * (e_sat(T_s) - e_a)        W m-2 (> 0: evaporation)

``h_c`` is the convective coefficient of the sensible heat flux (W m-2 K-1), ``gamma`` the
psychrometric constant (hPa K-1), ``e_sat`` the Magnus saturation vapour pressure and ``e_a``
the air's vapour pressure (hPa). ``beta`` is the wetness factor of Lee & Pielke (1992, J. Appl.
Meteor. 31, 480-484): ``0.25 (1 - cos(pi theta / theta_fc))^2`` below field capacity, 1 above.
When the surface is colder than the dew point (``e_sat(T_s) < e_a``) water condenses on it
(dew) whatever its wetness: ``beta = 1``.

The surface layer's volumetric water content follows the force-restore equation of Deardorff
(1978, J. Geophys. Res. 83, 1889-1903)::

    d theta / dt = -C1 (E - P) / (rho_w d1) - C2 (theta - theta_deep) / tau

with ``E = LE / L_v`` (kg m-2 s-1), ``P`` the rain rate, ``d1 = 0.1 m``, ``tau = 1 day``,
``C1 = 0.5``, ``C2 = 0.9``; theta is kept between 0 and saturation (the rest runs off). The
heat solver (:func:`clearfast_gis.thermal._kernels.march`) integrates it step by step with the
surface temperature; the functions here are its reference and the documentation's.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.units import STANDARD_PRESSURE_HPA, ZERO_CELSIUS_K

#: Magnus formula over water (Alduchov & Eskridge 1996): ``A exp(B t / (t + C))`` hPa, t in C.
MAGNUS_A_HPA = 6.1094
MAGNUS_B = 17.625
MAGNUS_C_C = 243.04
#: Latent heat of vaporisation of water near 20 C, J kg-1.
LATENT_HEAT_JKG = 2.45e6
#: Density of liquid water, kg m-3.
WATER_DENSITY_KGM3 = 1000.0
#: Specific heat of liquid water, J kg-1 K-1 (rain's sensible heat).
WATER_HEAT_JKGK = 4186.0
#: Specific heat of air at constant pressure, J kg-1 K-1.
AIR_HEAT_JKGK = 1005.0
#: Deardorff (1978) force-restore constants: C1, C2, layer depth d1 (m), restore time (s).
DEARDORFF_C1 = 0.5
DEARDORFF_C2 = 0.9
DEARDORFF_D1_M = 0.1
DEARDORFF_TAU_S = 86400.0
#: The inversion's surface layer when the soil's texture is not known: field capacity and
#: saturation, m3 m-3 (between the soil types' 0.05-0.36 and 0.30-0.50, ``thermal/soils.py``).
#: The wetness factor depends on ``theta / theta_fc`` only; these set the drying rate.
GENERIC_FIELD_CAPACITY = 0.2
GENERIC_SATURATION = 0.45


def saturation_vapour_pressure_hpa(t_k: ArrayLike) -> np.ndarray:
    """Saturation vapour pressure over water (Magnus, Alduchov & Eskridge 1996), hPa."""
    t_c = np.asarray(t_k, dtype=float) - ZERO_CELSIUS_K
    return MAGNUS_A_HPA * np.exp(MAGNUS_B * t_c / (t_c + MAGNUS_C_C))


def saturation_slope_hpa_k(t_k: ArrayLike) -> np.ndarray:
    """Slope ``d e_sat / dT`` of the Magnus formula, hPa K-1."""
    t_c = np.asarray(t_k, dtype=float) - ZERO_CELSIUS_K
    return saturation_vapour_pressure_hpa(t_k) * MAGNUS_B * MAGNUS_C_C / (t_c + MAGNUS_C_C) ** 2


def vapour_pressure_hpa(t_k: ArrayLike, rh_pct: ArrayLike) -> np.ndarray:
    """Vapour pressure of air at temperature ``t_k`` (K) and relative humidity (%), hPa."""
    return np.asarray(rh_pct, dtype=float) / 100.0 * saturation_vapour_pressure_hpa(t_k)


def dew_point_k(t_k: ArrayLike, rh_pct: ArrayLike) -> np.ndarray:
    """Dew point of air (the Magnus formula inverted), K.

    Parameters
    ----------
    t_k : array_like
        Air temperature, K.
    rh_pct : array_like
        Relative humidity, percent (> 0).
    """
    e = np.maximum(vapour_pressure_hpa(t_k, rh_pct), 1e-6)
    g = np.log(e / MAGNUS_A_HPA)
    return MAGNUS_C_C * g / (MAGNUS_B - g) + ZERO_CELSIUS_K


def psychrometric_hpa_k(pressure_hpa: float = STANDARD_PRESSURE_HPA) -> float:
    """Psychrometric constant ``gamma = c_p P / (0.622 L_v)``, hPa K-1 (0.67 at sea level)."""
    return AIR_HEAT_JKGK * float(pressure_hpa) / (0.622 * LATENT_HEAT_JKG)


def wetness_factor(theta: ArrayLike, theta_fc: float) -> np.ndarray:
    """Evaporation efficiency of a soil surface (Lee & Pielke 1992), 0..1.

    ``0.25 (1 - cos(pi theta / theta_fc))^2`` for volumetric water ``theta`` below field
    capacity ``theta_fc`` (both m3 m-3), 1 at or above it.
    """
    x = np.clip(np.asarray(theta, dtype=float) / theta_fc, 0.0, 1.0)
    return 0.25 * (1.0 - np.cos(np.pi * x)) ** 2


def latent_heat_flux_wm2(surface_k: ArrayLike, air_k: ArrayLike, rh_pct: ArrayLike,
                         hc_wm2k: ArrayLike, beta: ArrayLike,
                         pressure_hpa: float = STANDARD_PRESSURE_HPA) -> np.ndarray:
    """Latent heat flux leaving the surface, W m-2 (negative: dew forming).

    ``beta h_c / gamma (e_sat(T_s) - e_a)``, with ``beta = 1`` where the surface is below
    the dew point. Arrays broadcast; temperatures K, humidity %, ``h_c`` W m-2 K-1.
    """
    deficit = saturation_vapour_pressure_hpa(surface_k) - vapour_pressure_hpa(air_k, rh_pct)
    b = np.where(deficit < 0.0, 1.0, np.asarray(beta, dtype=float))
    return b * np.asarray(hc_wm2k, dtype=float) / psychrometric_hpa_k(pressure_hpa) * deficit


@dataclass(frozen=True)
class SurfaceWater:
    """Water of a soil's surface layer (force-restore, Deardorff 1978).

    Attributes
    ----------
    theta_deep : float
        Volumetric water content the layer relaxes to (the soil's moisture), m3 m-3.
    theta_fc : float
        Field capacity, m3 m-3 (evaporation at the potential rate above it).
    theta_sat : float
        Saturation (porosity), m3 m-3.
    theta_start : float or None
        Surface water at the start of the spin-up, m3 m-3 (default ``theta_deep``).
    """

    theta_deep: float
    theta_fc: float
    theta_sat: float
    theta_start: float | None = None

    def __post_init__(self) -> None:
        if not (0 < self.theta_fc <= self.theta_sat <= 1 and 0 <= self.theta_deep
                <= self.theta_sat):
            raise ValueError("expected 0 <= theta_deep <= theta_sat, 0 < theta_fc <= theta_sat")

    def kernel_parameters(self) -> np.ndarray:
        """``[theta_fc, theta_sat, theta_deep, C1 / (rho_w d1), C2 / tau]`` for the solver."""
        return np.array([self.theta_fc, self.theta_sat, self.theta_deep,
                         DEARDORFF_C1 / (WATER_DENSITY_KGM3 * DEARDORFF_D1_M),
                         DEARDORFF_C2 / DEARDORFF_TAU_S])


def surface_water_of_wetness(wetness: float) -> SurfaceWater:
    """The inversion's surface layer (:data:`GENERIC_FIELD_CAPACITY`,
    :data:`GENERIC_SATURATION`) at relative wetness ``wetness`` = theta / theta_fc (0 dry,
    1 at field capacity and above: evaporation at the potential rate), clipped to saturation.
    """
    theta = min(max(float(wetness), 0.0) * GENERIC_FIELD_CAPACITY, GENERIC_SATURATION)
    return SurfaceWater(theta_deep=theta, theta_fc=GENERIC_FIELD_CAPACITY,
                        theta_sat=GENERIC_SATURATION)
