"""Sun position and clear-sky irradiance.

The sun position follows the NOAA solar calculator (Meeus, *Astronomical Algorithms*, 1991,
ch. 25 low-precision series; about 0.01 deg in declination, a few seconds in the equation of
time for 1950-2050). Elevations are geometric (no refraction); sunrise and sunset use the
standard -0.833 deg horizon that accounts for refraction and the solar radius.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

DAY_S = 86400.0
"""Seconds in a day."""


def _sun_terms(time_s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Solar declination (rad) and equation of time (minutes) at UTC epoch seconds."""
    jd = time_s / DAY_S + 2440587.5
    jc = (jd - 2451545.0) / 36525.0
    mean_long = np.radians((280.46646 + jc * (36000.76983 + jc * 0.0003032)) % 360.0)
    mean_anom = np.radians(357.52911 + jc * (35999.05029 - 0.0001537 * jc))
    ecc = 0.016708634 - jc * (0.000042037 + 0.0000001267 * jc)
    centre = (
        np.sin(mean_anom) * (1.914602 - jc * (0.004817 + 0.000014 * jc))
        + np.sin(2 * mean_anom) * (0.019993 - 0.000101 * jc)
        + np.sin(3 * mean_anom) * 0.000289
    )
    omega = np.radians(125.04 - 1934.136 * jc)
    app_long = np.radians(np.degrees(mean_long) + centre - 0.00569 - 0.00478 * np.sin(omega))
    mean_obliq = 23.0 + (26.0 + (21.448 - jc * (46.815 + jc * (0.00059 - jc * 0.001813))) / 60) / 60
    obliq = np.radians(mean_obliq + 0.00256 * np.cos(omega))
    decl = np.arcsin(np.sin(obliq) * np.sin(app_long))
    y = np.tan(obliq / 2) ** 2
    eot_rad = (
        y * np.sin(2 * mean_long)
        - 2 * ecc * np.sin(mean_anom)
        + 4 * ecc * y * np.sin(mean_anom) * np.cos(2 * mean_long)
        - 0.5 * y * y * np.sin(4 * mean_long)
        - 1.25 * ecc * ecc * np.sin(2 * mean_anom)
    )
    return decl, 4.0 * np.degrees(eot_rad)


def solar_position(
    lat_deg: float, lon_deg: float, time_s: ArrayLike
) -> tuple[np.ndarray, np.ndarray]:
    """Sun elevation and azimuth seen from a site.

    Parameters
    ----------
    lat_deg, lon_deg : float
        Site latitude (north positive) and longitude (east positive), degrees.
    time_s : array_like, shape (T,)
        UTC epoch seconds.

    Returns
    -------
    elevation_deg : ndarray, shape (T,)
        Geometric elevation above the horizon, degrees (negative at night).
    azimuth_deg : ndarray, shape (T,)
        Azimuth clockwise from true north, degrees in [0, 360).
    """
    t = np.asarray(time_s, dtype=float)
    decl, eot_min = _sun_terms(t)
    tod_min = np.mod(t, DAY_S) / 60.0
    solar_min = np.mod(tod_min + eot_min + 4.0 * lon_deg, 1440.0)
    hour_angle = np.radians(solar_min / 4.0 - 180.0)
    lat = np.radians(lat_deg)
    sin_el = np.sin(lat) * np.sin(decl) + np.cos(lat) * np.cos(decl) * np.cos(hour_angle)
    elevation = np.degrees(np.arcsin(np.clip(sin_el, -1.0, 1.0)))
    az_south = np.arctan2(
        np.sin(hour_angle), np.cos(hour_angle) * np.sin(lat) - np.tan(decl) * np.cos(lat)
    )
    azimuth = np.mod(np.degrees(az_south) + 180.0, 360.0)
    return elevation, azimuth


def sun_times(lat_deg: float, lon_deg: float, day_s: float) -> tuple[float, float, float]:
    """Sunrise, solar noon and sunset of the UTC day containing ``day_s``.

    Parameters
    ----------
    lat_deg, lon_deg : float
        Site, degrees.
    day_s : float
        Any UTC epoch second of the day.

    Returns
    -------
    sunrise_s, noon_s, sunset_s : float
        UTC epoch seconds. In polar day or night, sunrise = sunset = noon -/+ 12 h or noon.
    """
    midnight = np.floor(day_s / DAY_S) * DAY_S
    decl, eot = _sun_terms(np.asarray(midnight + DAY_S / 2))
    noon = midnight + (720.0 - 4.0 * lon_deg - float(eot)) * 60.0
    decl, eot = _sun_terms(np.asarray(noon))
    noon = midnight + (720.0 - 4.0 * lon_deg - float(eot)) * 60.0
    lat = np.radians(lat_deg)
    cos_h = (np.cos(np.radians(90.833)) - np.sin(lat) * np.sin(decl)) / (
        np.cos(lat) * np.cos(decl)
    )
    half_day_s = float(np.degrees(np.arccos(np.clip(cos_h, -1.0, 1.0)))) * 4.0 * 60.0
    return noon - half_day_s, noon, noon + half_day_s


def clear_sky_ghi(elevation_deg: ArrayLike, scale: float = 1.0) -> np.ndarray:
    """Clear-sky global horizontal irradiance (Haurwitz 1945 model).

    ``GHI = 1098 sin(e) exp(-0.059 / sin(e))`` W m-2 for elevation e > 0, else 0.

    Parameters
    ----------
    elevation_deg : array_like
        Sun elevation, degrees.
    scale : float
        Multiplier for a hazier (< 1) or clearer (> 1) sky.

    Returns
    -------
    ndarray
        Irradiance on a horizontal surface, W m-2, same shape as ``elevation_deg``.
    """
    s = np.sin(np.radians(np.asarray(elevation_deg, dtype=float)))
    out = np.zeros_like(s)
    day = s > 1e-3
    out[day] = 1098.0 * s[day] * np.exp(-0.059 / s[day])
    return scale * out
