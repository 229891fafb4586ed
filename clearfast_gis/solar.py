"""Local solar time: the one helper for "what hour of the solar day was this scan".

Two clocks are in use, deliberately, because changing either would change products:

- :func:`local_solar_hour`, apparent solar time (12 = the sun's transit, from the sun model of
  :func:`clearfast_gis.thermal.solar.sun_times`, equation of time included): the detector's
  day/night polarity of a blob (``detection.features``, windows [9, 17) and [20, 6) h);
- :func:`mean_solar_hour`, mean solar time (UTC shifted by longitude / 15 h, no equation of
  time, within ~16 min of the apparent one): the day and night contrasts of the suspect
  records (``export.records``, windows [10, 16] and [22, 5] h) and the day and night scans
  shown in the report (``export.products``, nearest to 13 h and 3 h).
"""

from __future__ import annotations

import numpy as np

from clearfast_gis.thermal.solar import sun_times

__all__ = ["local_solar_hour", "mean_solar_hour"]


def local_solar_hour(time_s: np.ndarray | float, longitude_deg: float,
                     latitude_deg: float = 0.0) -> np.ndarray:
    """Local apparent solar time in hours [0, 24) (12 = solar noon).

    Derived from the solar noon of :func:`clearfast_gis.thermal.solar.sun_times` (the one sun
    model of the package): ``12 + (t - noon) / 3600`` wrapped to [0, 24), with the noon of the
    UTC day containing ``t``.

    Parameters
    ----------
    time_s : array_like, shape (N,) or scalar
        UTC epoch seconds.
    longitude_deg : float
        Longitude, degrees east positive.
    latitude_deg : float
        Latitude, degrees (does not change the solar noon; passed through to ``sun_times``).

    Returns
    -------
    ndarray, same shape as ``time_s``, hours.

    Examples
    --------
    >>> t = 1763208000.0  # 2025-11-15 12:00 UTC
    >>> round(float(local_solar_hour(t, 0.0)), 2)  # the equation of time: +15.4 min
    12.26
    """
    t = np.asarray(time_s, dtype=np.float64)
    days = np.floor(t / 86400.0)
    noon = np.empty_like(t)
    for day in np.unique(days):
        noon[days == day] = sun_times(latitude_deg, longitude_deg, float(day) * 86400.0)[1]
    return np.mod(12.0 + (t - noon) / 3600.0, 24.0)


def mean_solar_hour(time_s: np.ndarray | float, longitude_deg: float) -> np.ndarray:
    """Local mean solar time in hours [0, 24): UTC hour of day plus ``longitude_deg / 15``.

    Parameters
    ----------
    time_s : array_like, shape (N,) or scalar
        UTC epoch seconds.
    longitude_deg : float
        Longitude, degrees east positive.

    Returns
    -------
    ndarray, same shape as ``time_s``, hours.

    Examples
    --------
    >>> float(mean_solar_hour(1763208000.0, -75.0))  # 12:00 UTC at 75 deg W
    7.0
    """
    return (np.asarray(time_s, dtype=np.float64) / 3600.0 + longitude_deg / 15.0) % 24.0
