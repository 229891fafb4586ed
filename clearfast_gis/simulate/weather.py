"""The twin's weather: a clear day, clouds, rain, wind and gusts, or a measured record.

:func:`site_forcing` turns a :class:`~clearfast_gis.simulate.config.WeatherSpec` into the
:class:`~clearfast_gis.thermal.forcing.Forcing` that drives every thermal run of the twin
and that its weather station logs:

- a clear day for the site and date (:func:`clear_sky_forcing`, air temperature and humidity
  ranges from the spec);
- clouds: a cover fraction N (constant, or linear between ``[hours_after_start, N]`` pairs)
  scales the sun by Kasten & Czeplak and raises the sky's emissivity
  (:mod:`clearfast_gis.thermal.clouds`);
- rain events: a constant rate over each event; the sky is overcast (N = 1) and the air near
  saturation (RH at least 95 %) while it rains;
- wind: the clear day's course times ``wind_scale``, with gusts (a 1-minute AR(1) series of
  relative standard deviation ``gusts`` and a 5-minute correlation time, from the seed's
  ``gusts`` stream);
- a measured record (``file``): a station's TOA5 table, read as the chain reads
  ``weather.dat`` (:func:`read_station_table`, :func:`forcing_from_weather`); it must cover
  the survey.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.simulate.config import SimConfig, WeatherSpec
from clearfast_gis.thermal.clouds import cloud_solar_factor, cloudy_sky_longwave
from clearfast_gis.thermal.forcing import Forcing, clear_sky_forcing, forcing_from_weather

#: Gusts: correlation time of the 1-minute AR(1) wind factor, seconds.
GUST_TAU_S = 300.0
#: Relative humidity while it rains, at least, percent.
RAIN_RH_PCT = 95.0


def cloud_cover_at(spec: WeatherSpec, start_s: float, time_s: np.ndarray) -> np.ndarray:
    """Cloud cover fraction (T,) at UTC ``time_s``: the spec's pairs interpolated, 0 if none,
    1 while it rains."""
    t = np.asarray(time_s, float)
    if spec.cloud_cover:
        hours = np.array([p[0] for p in spec.cloud_cover], float)
        frac = np.array([p[1] for p in spec.cloud_cover], float)
        cover = np.interp((t - start_s) / 3600.0, hours, frac)
    else:
        cover = np.zeros_like(t)
    return np.where(rain_rate_mm_h(spec, t) > 0, 1.0, cover)


def rain_rate_mm_h(spec: WeatherSpec, time_s: np.ndarray) -> np.ndarray:
    """Rain rate (T,), mm h-1: each event's total spread evenly over its duration."""
    t = np.asarray(time_s, float)
    rate = np.zeros_like(t)
    for ev in spec.rain:
        inside = (t >= ev.start_s) & (t < ev.start_s + ev.duration_s)
        rate[inside] += ev.total_mm / (ev.duration_s / 3600.0)
    return rate


def gust_factor(n: int, step_s: float, gusts: float, rng: np.random.Generator) -> np.ndarray:
    """Multiplicative wind gust factor (n,) >= 0.2: AR(1) of relative sd ``gusts``."""
    if gusts <= 0:
        return np.ones(n)
    a = float(np.exp(-step_s / GUST_TAU_S))
    e = rng.standard_normal(n) * gusts * np.sqrt(1 - a * a)
    x = np.empty(n)
    x[0] = rng.standard_normal() * gusts
    for k in range(1, n):
        x[k] = a * x[k - 1] + e[k]
    return np.maximum(1.0 + x, 0.2)


def site_forcing(config: SimConfig, start_s: float, rng: np.random.Generator) -> Forcing:
    """The twin's weather over the survey (1-minute samples; see the module docstring).

    Parameters
    ----------
    config : SimConfig
        Site, date, duration and ``weather`` spec.
    start_s : float
        Survey start, UTC epoch seconds.
    rng : numpy.random.Generator
        The seed's ``gusts`` stream.
    """
    spec = config.weather
    if spec.file:
        return measured_forcing(spec.file, start_s, config.duration_s)
    clear = clear_sky_forcing(config.latitude_deg, config.longitude_deg, start_s,
                              config.duration_s, 60.0, t_air_min_c=spec.air_temp_c[0],
                              t_air_max_c=spec.air_temp_c[1], rh_min_pct=spec.rh_pct[0],
                              rh_max_pct=spec.rh_pct[1])
    t = clear.time_s
    cover = cloud_cover_at(spec, start_s, t)
    rain = rain_rate_mm_h(spec, t)
    rh = np.where(rain > 0, np.maximum(clear.rh_pct, RAIN_RH_PCT), clear.rh_pct)
    wind = clear.wind_ms * spec.wind_scale * gust_factor(t.size, 60.0, spec.gusts, rng)
    return Forcing(t, clear.solar_wm2 * cloud_solar_factor(cover),
                   cloudy_sky_longwave(clear.air_temp_k, rh, cover), clear.air_temp_k, wind,
                   rh, rain)


def measured_forcing(file: str, start_s: float, duration_s: float) -> Forcing:
    """Forcing from a measured weather table (TOA5) covering the survey.

    Read as the chain reads a station's table
    (:func:`clearfast_gis.survey.stations.read_station_table`: columns by Campbell's standard
    names, units converted); a station profile for other column names plugs in here.

    Raises
    ------
    InvalidInput
        The file cannot be read, or does not cover the survey (within 10 minutes).
    """
    from clearfast_gis.survey.stations import read_station_table

    path = Path(file)
    forcing = forcing_from_weather(read_station_table(path).weather)
    if forcing.time_s[0] > start_s + 600 or forcing.time_s[-1] < start_s + duration_s - 600:
        raise InvalidInput("the weather record does not cover the survey period", path,
                           "TIMESTAMP")
    return forcing
