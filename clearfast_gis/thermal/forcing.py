"""Surface forcing: the weather that drives the soil's energy balance.

Either from a weather-station log (:func:`forcing_from_weather`) or a synthetic clear day for
any site and date (:func:`clear_sky_forcing`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.errors import InvalidInput
from clearfast_gis.thermal.moisture import saturation_vapour_pressure_hpa
from clearfast_gis.thermal.solar import DAY_S, clear_sky_ghi, solar_position, sun_times
from clearfast_gis.units import STEFAN_BOLTZMANN, ZERO_CELSIUS_K

#: The channels of a :class:`Forcing`, in order.
CHANNELS = ("time_s", "solar_wm2", "sky_lw_wm2", "air_temp_k", "wind_ms", "rh_pct", "rain_mm_h")


@dataclass(frozen=True)
class Forcing:
    """Weather at the site, sampled at increasing UTC times.

    Attributes
    ----------
    time_s : ndarray, shape (T,)
        UTC epoch seconds, strictly increasing.
    solar_wm2 : ndarray, shape (T,)
        Global irradiance on the horizontal ground, W m-2.
    sky_lw_wm2 : ndarray, shape (T,)
        Down-welling sky long-wave irradiance, W m-2.
    air_temp_k : ndarray, shape (T,)
        Air temperature, K.
    wind_ms : ndarray, shape (T,)
        Wind speed, m s-1.
    rh_pct : ndarray, shape (T,)
        Relative humidity, percent.
    rain_mm_h : ndarray, shape (T,), optional
        Rain rate, mm h-1 (= kg m-2 h-1); default none.
    """

    time_s: np.ndarray
    solar_wm2: np.ndarray
    sky_lw_wm2: np.ndarray
    air_temp_k: np.ndarray
    wind_ms: np.ndarray
    rh_pct: np.ndarray
    rain_mm_h: np.ndarray | None = None

    def __post_init__(self) -> None:
        if self.rain_mm_h is None:
            object.__setattr__(self, "rain_mm_h", np.zeros(np.shape(self.time_s)))
        names = CHANNELS
        arrays = {n: np.asarray(getattr(self, n), dtype=float) for n in names}
        n = arrays["time_s"].shape
        for name, arr in arrays.items():
            if arr.ndim != 1 or arr.shape != n:
                raise InvalidInput(f"expected a 1-D array of {n[0]} values", field=name)
            if not np.all(np.isfinite(arr)):
                raise InvalidInput("values must be finite", field=name)
            object.__setattr__(self, name, arr)
        if n[0] < 2 or np.any(np.diff(arrays["time_s"]) <= 0):
            raise InvalidInput("at least 2 strictly increasing times needed", field="time_s")
        if np.any(arrays["rain_mm_h"] < 0):
            raise InvalidInput("rain rate must not be negative", field="rain_mm_h")

    def at(self, time_s: ArrayLike) -> dict[str, np.ndarray]:
        """Every channel linearly interpolated to ``time_s`` (any order; held past the ends).

        Returns a dict with keys ``solar_wm2``, ``sky_lw_wm2``, ``air_temp_k``, ``wind_ms``,
        ``rh_pct``, ``rain_mm_h``, arrays shaped like ``time_s``.
        """
        t = np.asarray(time_s, dtype=float)
        names = CHANNELS[1:]
        return {n: np.interp(t, self.time_s, getattr(self, n)) for n in names}

    def daily_mean_air_k(self) -> float:
        """Time-weighted mean air temperature over the first 24 h (or the whole record), K."""
        t = self.time_s
        end = min(t[-1], t[0] + DAY_S)
        grid = np.linspace(t[0], end, 289)
        return float(np.mean(np.interp(grid, t, self.air_temp_k)))


def clear_sky_emissivity(air_temp_k: ArrayLike, rh_pct: ArrayLike) -> np.ndarray:
    """Clear-sky atmospheric emissivity (Brutsaert 1975): ``1.24 (e_a / T_a)^(1/7)``, <= 1.

    Parameters
    ----------
    air_temp_k : array_like
        Screen-level air temperature, K.
    rh_pct : array_like
        Relative humidity, percent.

    Returns
    -------
    ndarray
        Effective emissivity of the sky, dimensionless (~0.7-0.85).
    """
    t = np.asarray(air_temp_k, dtype=float)
    e_a = np.asarray(rh_pct, dtype=float) / 100.0 * saturation_vapour_pressure_hpa(t)
    return np.minimum(1.24 * np.power(np.maximum(e_a, 1e-3) / t, 1.0 / 7.0), 1.0)


def clear_sky_longwave(air_temp_k: ArrayLike, rh_pct: ArrayLike) -> np.ndarray:
    """Clear-sky down-welling long-wave irradiance ``eps_sky sigma T_a^4``, W m-2."""
    t = np.asarray(air_temp_k, dtype=float)
    return clear_sky_emissivity(t, rh_pct) * STEFAN_BOLTZMANN * t**4


def diurnal_air_temperature_k(
    time_s: np.ndarray,
    sunrise_s: float,
    t_max_s: float,
    t_min_k: float,
    t_max_k: float,
) -> np.ndarray:
    """A 24-h periodic air-temperature course: minimum at sunrise, maximum at ``t_max_s``.

    Half-cosine rise from sunrise to the maximum and half-cosine fall to the next sunrise
    (continuous with a continuous first derivative).

    Parameters
    ----------
    time_s : ndarray, shape (T,)
        UTC epoch seconds.
    sunrise_s, t_max_s : float
        Times of the minimum and the maximum on one day, UTC epoch seconds.
    t_min_k, t_max_k : float
        Minimum and maximum, K.

    Returns
    -------
    ndarray, shape (T,)
        Air temperature, K.
    """
    rise = t_max_s - sunrise_s
    fall = DAY_S - rise
    phase = np.mod(time_s - sunrise_s, DAY_S)
    amp = t_max_k - t_min_k
    up = t_min_k + amp * (1 - np.cos(np.pi * phase / rise)) / 2
    down = t_max_k - amp * (1 - np.cos(np.pi * (phase - rise) / fall)) / 2
    return np.where(phase < rise, up, down)


def clear_sky_forcing(
    lat_deg: float,
    lon_deg: float,
    start_s: float,
    duration_s: float,
    step_s: float = 60.0,
    t_air_min_c: float = 10.0,
    t_air_max_c: float = 23.0,
    rh_min_pct: float = 60.0,
    rh_max_pct: float = 70.0,
    wind_day_ms: float = 3.0,
    wind_night_ms: float = 1.0,
    t_max_after_noon_s: float = 7200.0,
    solar_scale: float = 1.0,
) -> Forcing:
    """A clear, calm-to-breezy day for any site and date.

    Solar irradiance from the sun's position (:func:`solar_position`) and the Haurwitz
    clear-sky model; air temperature minimum at sunrise and maximum ``t_max_after_noon_s``
    after solar noon; relative humidity inverse to the air temperature; wind ``wind_day_ms``
    with the sun high and ``wind_night_ms`` at night; sky long-wave from the Brutsaert
    clear-sky emissivity. The defaults give the clear mid-November day at 35 N of the
    design guide (solar peak ~590 W m-2, air 10-23 C, sky 280-320 W m-2).

    Parameters
    ----------
    lat_deg, lon_deg : float
        Site, degrees.
    start_s, duration_s, step_s : float
        First sample (UTC epoch seconds), length and sampling interval, seconds.
    t_air_min_c, t_air_max_c : float
        Daily air-temperature range, degrees C.
    rh_min_pct, rh_max_pct : float
        Humidity at the warmest and at the coolest time, percent.
    wind_day_ms, wind_night_ms : float
        Wind speed with the sun at its highest and at night, m s-1.
    t_max_after_noon_s : float
        Lag of the air-temperature maximum after solar noon, s.
    solar_scale : float
        Multiplier on the clear-sky irradiance (haze).

    Returns
    -------
    Forcing
    """
    if duration_s <= 0 or step_s <= 0:
        raise InvalidInput("duration and step must be positive", field="duration_s")
    t = start_s + np.arange(0.0, duration_s + 0.5 * step_s, step_s)
    elev, _ = solar_position(lat_deg, lon_deg, t)
    solar = clear_sky_ghi(elev, solar_scale)
    sunrise, noon, _ = sun_times(lat_deg, lon_deg, start_s + duration_s / 2)
    t_min_k = t_air_min_c + ZERO_CELSIUS_K
    t_max_k = t_air_max_c + ZERO_CELSIUS_K
    air = diurnal_air_temperature_k(t, sunrise, noon + t_max_after_noon_s, t_min_k, t_max_k)
    warm = (air - t_min_k) / max(t_max_k - t_min_k, 1e-9)
    rh = rh_max_pct - (rh_max_pct - rh_min_pct) * warm
    noon_elev, _ = solar_position(lat_deg, lon_deg, np.array([noon]))
    sin_noon = max(np.sin(np.radians(noon_elev[0])), 1e-3)
    day = np.clip(np.sin(np.radians(elev)) / sin_noon, 0.0, 1.0)
    wind = wind_night_ms + (wind_day_ms - wind_night_ms) * np.sqrt(day)
    sky = clear_sky_longwave(air, rh)
    return Forcing(t, solar, sky, air, wind, rh)


def _field(log: Any, name: str) -> np.ndarray | None:
    if isinstance(log, Mapping):
        value = log.get(name)
    else:
        value = getattr(log, name, None)
    return None if value is None else np.asarray(value, dtype=float)


def _fill_gaps(t: np.ndarray, values: np.ndarray, name: str) -> np.ndarray | None:
    ok = np.isfinite(values)
    if not ok.any():
        return None
    if ok.all():
        return values
    return np.interp(t, t[ok], values[ok])


def forcing_from_weather(weather_log: Any) -> Forcing:
    """Forcing from a weather-station log, with gaps filled.

    Parameters
    ----------
    weather_log : object or mapping
        Arrays ``time_s``, ``air_temp_c``, ``rh_pct``, ``wind_ms``, ``solar_wm2`` and
        optionally ``sky_lw_wm2`` and ``pressure_hpa`` (e.g. the ``WeatherLog`` of
        ``clearfast_gis.survey.read_toa5``), all shape (T,). NaN marks missing records.

    Returns
    -------
    Forcing
        Gaps linearly interpolated; negative solar readings (night offsets) set to 0; the sky
        long-wave estimated from air temperature and humidity (Brutsaert clear sky) where the
        log has none; the rain rate from ``rain_mm`` (totals per record; missing records and
        a log without a gauge count as no rain).

    Raises
    ------
    InvalidInput
        When a required channel is absent or entirely missing, or times do not increase.
    """
    t = _field(weather_log, "time_s")
    if t is None or t.ndim != 1 or t.size < 2:
        raise InvalidInput("weather log needs at least 2 records", field="time_s")
    order = np.argsort(t, kind="stable")
    t = t[order]
    keep = np.concatenate([[True], np.diff(t) > 0])
    t = t[keep]
    out: dict[str, np.ndarray] = {}
    for name in ("air_temp_c", "rh_pct", "wind_ms", "solar_wm2", "sky_lw_wm2"):
        raw = _field(weather_log, name)
        if raw is None:
            if name == "sky_lw_wm2":
                continue
            raise InvalidInput("channel missing from the weather log", field=name)
        if raw.shape != order.shape:
            raise InvalidInput("length differs from time_s", field=name)
        filled = _fill_gaps(t, raw[order][keep], name)
        if filled is None:
            if name == "sky_lw_wm2":
                continue
            raise InvalidInput("channel has no valid value", field=name)
        out[name] = filled
    air_k = out["air_temp_c"] + ZERO_CELSIUS_K
    rh = np.clip(out["rh_pct"], 0.0, 100.0)
    sky = out.get("sky_lw_wm2")
    if sky is None:
        sky = clear_sky_longwave(air_k, rh)
    rain = _field(weather_log, "rain_mm")
    rate = None
    if rain is not None and rain.shape == order.shape and np.isfinite(rain).any():
        rate = rain_rate_mm_h(t, np.nan_to_num(rain[order][keep], nan=0.0))
    return Forcing(t, np.maximum(out["solar_wm2"], 0.0), sky, air_k,
                   np.maximum(out["wind_ms"], 0.0), rh, rate)


def rain_rate_mm_h(time_s: np.ndarray, rain_mm: np.ndarray) -> np.ndarray:
    """Rain rate (mm h-1) from totals per record (mm in the interval ending at each record).

    ``time_s`` (T,) increasing UTC seconds; the first record's interval is taken equal to the
    second's. Negative totals (a gauge's noise) count as none.
    """
    dt = np.diff(time_s)
    interval = np.concatenate([dt[:1], dt])
    return np.maximum(np.asarray(rain_mm, dtype=float), 0.0) / (interval / 3600.0)
