"""Field instruments' logs: weather station (TOA5), soil thermocouples, blackbody sensors.

Each log is the simulated truth sampled at the instrument's rate plus its sensor noise:
air temperature 0.1 K, humidity 1 %, pressure 0.2 hPa, wind 0.1 m/s, pyranometer 2 %,
pyrgeometer 3 W m-2; thermocouples 0.05 K; blackbody PT100 sensors 0.02 K. Values are
rounded as the loggers write them.
"""

from __future__ import annotations

import numpy as np

from clearfast_gis.survey.logs import BlackbodyLog, SoilLog
from clearfast_gis.survey.toa5 import WeatherLog
from clearfast_gis.units import ZERO_CELSIUS_K

#: Thermocouple depths, metres.
SOIL_DEPTHS_M = (0.02, 0.05, 0.10, 0.20, 0.50)
#: Heated blackbody set point above the air temperature, kelvin.
BB1_ABOVE_AIR_K = 10.0
#: Thermal time constant of the unheated blackbody, seconds.
BB2_TAU_S = 1200.0


def station_pressure_hpa(time_s: np.ndarray, altitude_m: float) -> np.ndarray:
    """Barometric pressure at the site: standard atmosphere at ``altitude_m`` plus the
    semidiurnal tide (+-1 hPa, maxima near 10 and 22 h UTC+2)."""
    p0 = 1013.25 * (1.0 - 2.25577e-5 * altitude_m) ** 5.25588
    return p0 + 1.0 * np.cos(4.0 * np.pi * (np.asarray(time_s) + 7200.0 - 36000.0) / 86400.0)


def weather_log(time_s: np.ndarray, air_temp_k: np.ndarray, rh_pct: np.ndarray,
                pressure_hpa: np.ndarray, wind_ms: np.ndarray, solar_wm2: np.ndarray,
                sky_lw_wm2: np.ndarray, rng: np.random.Generator,
                rain_mm_h: np.ndarray | None = None) -> WeatherLog:
    """The weather station's 1-minute records (true values plus sensor noise), all (T,).

    ``rain_mm_h`` (the true rain rate, mm h-1) gives the gauge's totals per record (0.1 mm
    tipping-bucket resolution, accumulated so that no rain is lost).
    """
    n = len(time_s)

    def noisy(x: np.ndarray, sigma: np.ndarray | float) -> np.ndarray:
        return np.asarray(x, float) + rng.standard_normal(n) * sigma

    solar = np.clip(noisy(solar_wm2, 0.02 * np.asarray(solar_wm2)), 0.0, None)
    return WeatherLog(
        time_s=np.asarray(time_s, float),
        air_temp_c=np.round(noisy(air_temp_k, 0.1) - ZERO_CELSIUS_K, 2),
        rh_pct=np.round(np.clip(noisy(rh_pct, 1.0), 0.0, 100.0), 1),
        pressure_hpa=np.round(noisy(pressure_hpa, 0.2), 1),
        wind_ms=np.round(np.clip(noisy(wind_ms, 0.1), 0.0, None), 2),
        solar_wm2=np.round(solar, 1),
        sky_lw_wm2=np.round(noisy(sky_lw_wm2, 3.0), 1),
        rain_mm=gauge_totals_mm(time_s, rain_mm_h),
    )


def gauge_totals_mm(time_s: np.ndarray, rain_mm_h: np.ndarray | None,
                    bucket_mm: float = 0.1) -> np.ndarray:
    """Tipping-bucket totals per record (T,), mm: the rain since the previous record in whole
    tips, the remainder carried over."""
    t = np.asarray(time_s, float)
    if rain_mm_h is None:
        return np.zeros(t.size)
    rate = np.asarray(rain_mm_h, float)
    dt_h = np.diff(t, prepend=t[0] - (t[1] - t[0] if t.size > 1 else 60.0)) / 3600.0
    cum = np.cumsum(rate * dt_h)
    tips = np.floor(cum / bucket_mm + 1e-9)
    return np.round(np.diff(tips, prepend=0.0) * bucket_mm, 1)


def soil_log(time_s: np.ndarray, depth_m: np.ndarray, temp_k: np.ndarray,
             rng: np.random.Generator) -> SoilLog:
    """Thermocouple records: true temperatures (T, D) kelvin plus 0.05 K noise, degrees C."""
    t = np.asarray(temp_k, float) - ZERO_CELSIUS_K
    return SoilLog(time_s=np.asarray(time_s, float), depth_m=np.asarray(depth_m, float),
                   temp_c=np.round(t + 0.05 * rng.standard_normal(t.shape), 3))


def blackbody_truth_k(time_s: np.ndarray, air_temp_k: np.ndarray
                      ) -> tuple[np.ndarray, np.ndarray]:
    """True blackbody temperatures on a regular time grid (T,), kelvin.

    The heated blackbody is regulated at air temperature + :data:`BB1_ABOVE_AIR_K`; the
    unheated one follows the air with a first-order lag of :data:`BB2_TAU_S`.
    """
    t = np.asarray(time_s, float)
    air = np.asarray(air_temp_k, float)
    bb1 = air + BB1_ABOVE_AIR_K
    bb2 = np.empty_like(air)
    bb2[0] = air[0]
    for k in range(1, t.size):
        a = np.exp(-(t[k] - t[k - 1]) / BB2_TAU_S)
        bb2[k] = a * bb2[k - 1] + (1.0 - a) * air[k]
    return bb1, bb2


def blackbody_log(time_s: np.ndarray, bb1_k: np.ndarray, bb2_k: np.ndarray,
                  rng: np.random.Generator) -> BlackbodyLog:
    """Blackbody sensor records: true temperatures plus 0.02 K noise, degrees C."""
    n = len(time_s)
    return BlackbodyLog(
        time_s=np.asarray(time_s, float),
        bb1_c=np.round(bb1_k - ZERO_CELSIUS_K + 0.02 * rng.standard_normal(n), 3),
        bb2_c=np.round(bb2_k - ZERO_CELSIUS_K + 0.02 * rng.standard_normal(n), 3))
