"""Local solar time and solar elevation, to tell day scans from night scans.

NOAA's low-accuracy formulas (fractional-year series for the equation of time and the
declination; about 1 minute and 0.1 degree), enough to sort scans into day and night.
"""

from __future__ import annotations

import numpy as np

__all__ = ["local_solar_hour", "solar_elevation_deg"]

_DAY_S = 86400.0


def _fractional_year_rad(time_s: np.ndarray) -> np.ndarray:
    t = np.asarray(time_s, dtype=np.float64)
    stamps = np.floor(t).astype("datetime64[s]")
    year_start = stamps.astype("datetime64[Y]")
    doy = (stamps - year_start).astype(np.float64) / _DAY_S
    year_len = (year_start + np.timedelta64(1, "Y") - year_start).astype("timedelta64[D]")
    return 2.0 * np.pi / year_len.astype(np.float64) * doy


def _equation_of_time_min(gamma: np.ndarray) -> np.ndarray:
    return 229.18 * (0.000075 + 0.001868 * np.cos(gamma) - 0.032077 * np.sin(gamma)
                     - 0.014615 * np.cos(2 * gamma) - 0.040849 * np.sin(2 * gamma))


def local_solar_hour(time_s: np.ndarray | float, longitude_deg: float) -> np.ndarray:
    """Local apparent solar time in hours [0, 24) (12 = solar noon).

    Parameters
    ----------
    time_s : array_like
        UTC epoch seconds.
    longitude_deg : float
        Longitude, degrees east positive.
    """
    t = np.asarray(time_s, dtype=np.float64)
    gamma = _fractional_year_rad(t)
    utc_min = np.mod(t, _DAY_S) / 60.0
    solar_min = utc_min + 4.0 * float(longitude_deg) + _equation_of_time_min(gamma)
    return np.mod(solar_min / 60.0, 24.0)


def solar_elevation_deg(time_s: np.ndarray | float, latitude_deg: float,
                        longitude_deg: float) -> np.ndarray:
    """Solar elevation above the horizon, degrees (no refraction).

    Parameters
    ----------
    time_s : array_like
        UTC epoch seconds.
    latitude_deg, longitude_deg : float
        Site position, degrees (north and east positive).
    """
    t = np.asarray(time_s, dtype=np.float64)
    gamma = _fractional_year_rad(t)
    decl = (0.006918 - 0.399912 * np.cos(gamma) + 0.070257 * np.sin(gamma)
            - 0.006758 * np.cos(2 * gamma) + 0.000907 * np.sin(2 * gamma)
            - 0.002697 * np.cos(3 * gamma) + 0.00148 * np.sin(3 * gamma))
    hour_angle = np.radians(15.0 * (local_solar_hour(t, longitude_deg) - 12.0))
    lat = np.radians(latitude_deg)
    sin_el = np.sin(lat) * np.sin(decl) + np.cos(lat) * np.cos(decl) * np.cos(hour_angle)
    return np.degrees(np.arcsin(np.clip(sin_el, -1.0, 1.0)))
