"""Physical plausibility of logged values: ranges, pressure at the site's altitude, stuck
sensors and spikes.

Each check is a pure function over one series (values in the canonical units of
:data:`clearfast_gis.survey.station_profiles.QUANTITIES`, soil temperature in deg C) and
returns :class:`Finding` records naming the file line, column and value, so that a unit
mix-up (147 W/m^2 read as 147 deg C, 3.5 m/s read as 3.5 hPa) is a problem, never data.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: physical ranges, canonical units (pressure: see :func:`pressure_range_hpa`)
RANGES: dict[str, tuple[float, float]] = {
    "air_temp_c": (-60.0, 60.0),  # recorded extremes -89.2 (Vostok) and 56.7 deg C
    "rh_pct": (0.0, 105.0),  # capacitive sensors read a few % over 100 in fog
    "wind_ms": (0.0, 75.0),
    "solar_wm2": (-30.0, 1500.0),  # night offsets of thermopiles are a few W/m^2 negative
    "sky_lw_wm2": (40.0, 600.0),
    "rain_mm": (0.0, 300.0),
    "soil_temp_c": (-40.0, 85.0),
    # field blackbodies: an ambient plate and a heated one (extended-area sources reach
    # +125 to +150 deg C); below -40 deg C nothing in the survey works
    "blackbody_temp_c": (-40.0, 150.0),
}

#: largest difference of a station's pressure from the standard atmosphere at the site's
#: altitude, hPa (deep lows and strong highs are within +-60 hPa of it)
PRESSURE_TOLERANCE_HPA = 70.0

#: pressure range when the altitude is not known, hPa (summit of Everest to the Dead Sea)
PRESSURE_ANY_HPA = (300.0, 1100.0)

#: a series that holds one value this long (and over at least STUCK_MIN_RECORDS records) is
#: a stuck sensor, seconds; only for quantities that always change (temperatures, pressure)
STUCK_S = 6 * 3600.0
STUCK_MIN_RECORDS = 10
STUCK_QUANTITIES = ("air_temp_c", "pressure_hpa", "soil_temp_c")

#: a value this far from both neighbours (in the same direction), while they agree, is a
#: spike; neighbours must lie within SPIKE_WINDOW_S of it
SPIKES: dict[str, float] = {"air_temp_c": 8.0, "rh_pct": 40.0, "pressure_hpa": 15.0,
                            "soil_temp_c": 5.0, "sky_lw_wm2": 150.0,
                            "blackbody_temp_c": 5.0}
SPIKE_WINDOW_S = 3600.0


@dataclass(frozen=True)
class Finding:
    """One implausible stretch of a series: the first file line, the column, the value."""

    line: int
    column: str
    value: float
    message: str

    def text(self) -> str:
        """``column: message`` for a problem line."""
        return f"{self.column}: {self.message}"


def pressure_range_hpa(altitude_m: float | None) -> tuple[float, float]:
    """Plausible station pressure at ``altitude_m`` (metres above sea level), hPa: the
    standard atmosphere (ICAO) +- :data:`PRESSURE_TOLERANCE_HPA`; without an altitude,
    :data:`PRESSURE_ANY_HPA`."""
    if altitude_m is None or not np.isfinite(altitude_m):
        return PRESSURE_ANY_HPA
    p = 1013.25 * (1.0 - 2.25577e-5 * float(altitude_m)) ** 5.25588
    return p - PRESSURE_TOLERANCE_HPA, p + PRESSURE_TOLERANCE_HPA


def check_series(quantity: str, column: str, time_s: np.ndarray, values: np.ndarray,
                 lines: np.ndarray, unit: str, altitude_m: float | None = None
                 ) -> list[Finding]:
    """Range, stuck-sensor and spike findings of one series.

    Parameters
    ----------
    quantity : str
        Key of :data:`RANGES` or ``pressure_hpa``.
    column : str
        Column name for messages (e.g. ``"BP_mbar_Avg (pressure_hpa)"``).
    time_s, values, lines : ndarray (T,)
        Record times (UTC epoch seconds), values in canonical units (NaN = missing) and the
        file line of each record.
    unit : str
        Canonical unit, for messages.
    altitude_m : float, optional
        Site altitude above sea level, metres (pressure range).
    """
    v = np.asarray(values, dtype=float)
    t = np.asarray(time_s, dtype=float)
    out: list[Finding] = []
    lo, hi = pressure_range_hpa(altitude_m) if quantity == "pressure_hpa" else RANGES[quantity]
    bad = np.isfinite(v) & ((v < lo) | (v > hi))
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        where = f" at {altitude_m:g} m" if quantity == "pressure_hpa" and altitude_m is not \
            None else ""
        out.append(Finding(int(lines[k]), column, float(v[k]),
                           f"{int(bad.sum())} value(s) outside {lo:.6g}..{hi:.6g} {unit}{where}, "
                           f"first line {int(lines[k])}: {v[k]:.6g} {unit} (wrong column or "
                           "unit?)"))
    if quantity in STUCK_QUANTITIES:
        out += _stuck(column, t, v, lines, unit)
    if quantity in SPIKES:
        out += _spikes(column, t, v, lines, unit, SPIKES[quantity])
    return out


def _stuck(column: str, t: np.ndarray, v: np.ndarray, lines: np.ndarray,
           unit: str) -> list[Finding]:
    ok = np.flatnonzero(np.isfinite(v))
    if ok.size < STUCK_MIN_RECORDS:
        return []
    vv = v[ok]
    change = np.flatnonzero(np.diff(vv) != 0.0) + 1
    starts = np.concatenate([[0], change])
    ends = np.concatenate([change, [vv.size]])
    for a, b in zip(starts, ends, strict=True):
        if b - a >= STUCK_MIN_RECORDS and t[ok[b - 1]] - t[ok[a]] >= STUCK_S:
            k = ok[a]
            return [Finding(int(lines[k]), column, float(v[k]),
                            f"stuck sensor: {v[k]:.6g} {unit} for {b - a} records "
                            f"({(t[ok[b - 1]] - t[k]) / 3600.0:.1f} h) from line {int(lines[k])}")]
    return []


def _spikes(column: str, t: np.ndarray, v: np.ndarray, lines: np.ndarray, unit: str,
            jump: float) -> list[Finding]:
    ok = np.flatnonzero(np.isfinite(v))
    if ok.size < 3:
        return []
    tt, vv = t[ok], v[ok]
    d_prev = vv[1:-1] - vv[:-2]
    d_next = vv[1:-1] - vv[2:]
    near = (tt[1:-1] - tt[:-2] <= SPIKE_WINDOW_S) & (tt[2:] - tt[1:-1] <= SPIKE_WINDOW_S)
    spike = near & (np.abs(d_prev) > jump) & (np.abs(d_next) > jump) & \
        (np.sign(d_prev) == np.sign(d_next)) & (np.abs(vv[2:] - vv[:-2]) < 0.5 * jump)
    if not spike.any():
        return []
    idx = np.flatnonzero(spike) + 1
    k = ok[idx[0]]
    return [Finding(int(lines[k]), column, float(v[k]),
                    f"{idx.size} spike(s) of more than {jump:g} {unit} from both neighbours, "
                    f"first line {int(lines[k])}: {v[k]:.6g} {unit}")]
