"""Campbell Scientific TOA5 weather tables (UTC timestamps).

A TOA5 file has four header lines (environment, field names, units, processing) and then one
quoted-CSV record per line; missing values are ``"NAN"``. Columns are found by name (a
station profile's names, then Campbell's standard program names,
:mod:`clearfast_gis.survey.station_profiles`) and converted to canonical units from the
units line or the profile. This toolkit writes its own names and units (:data:`COLUMNS`).
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

import numpy as np

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey._text import cell, csv_rows, read_text, to_float, to_time
from clearfast_gis.survey.plausibility import Finding, check_series
from clearfast_gis.survey.station_profiles import (
    QUANTITIES,
    WEATHER_REQUIRED,
    ColumnMap,
    StationProfile,
    map_columns,
)
from clearfast_gis.timeutil import format_utc

#: TOA5 column written by :func:`write_toa5` -> (WeatherLog attribute, unit written)
COLUMNS: dict[str, tuple[str, str]] = {
    "AirTC_Avg": ("air_temp_c", "Deg C"),
    "RH_Avg": ("rh_pct", "%"),
    "BP_hPa_Avg": ("pressure_hpa", "hPa"),
    "WS_ms_Avg": ("wind_ms", "meters/second"),
    "SlrW_Avg": ("solar_wm2", "W/m^2"),
    "IRSky_Avg": ("sky_lw_wm2", "W/m^2"),
    "Rain_mm_Tot": ("rain_mm", "mm"),
}


@dataclass(frozen=True)
class WeatherLog:
    """Weather station records, arrays of length T; NaN where the logger wrote ``NAN``.

    Attributes
    ----------
    time_s : float64 (T,)
        UTC epoch seconds of the record (end of the averaging interval).
    air_temp_c : float64 (T,)
        Air temperature, degrees C.
    rh_pct : float64 (T,)
        Relative humidity, percent.
    pressure_hpa : float64 (T,)
        Barometric pressure, hPa.
    wind_ms : float64 (T,)
        Wind speed, m/s.
    solar_wm2 : float64 (T,)
        Global solar irradiance, W/m^2.
    sky_lw_wm2 : float64 (T,)
        Sky long-wave irradiance down, W/m^2 (all NaN when the station has no pyrgeometer).
    rain_mm : float64 (T,)
        Precipitation in the interval, mm (all NaN when not logged).
    """

    time_s: np.ndarray
    air_temp_c: np.ndarray
    rh_pct: np.ndarray
    pressure_hpa: np.ndarray
    wind_ms: np.ndarray
    solar_wm2: np.ndarray
    sky_lw_wm2: np.ndarray
    rain_mm: np.ndarray

    def __len__(self) -> int:
        return int(self.time_s.shape[0])


@dataclass(frozen=True)
class StationTable:
    """A weather table read by name, values in canonical units, with where each came from.

    Attributes
    ----------
    weather : WeatherLog
        The records (quantities the table lacks are all NaN).
    columns : dict
        quantity -> :class:`~clearfast_gis.survey.station_profiles.ColumnMap` for every
        quantity found (column name, unit, conversion).
    lines : int64 (T,)
        File line of each record.
    """

    weather: WeatherLog
    columns: dict[str, ColumnMap]
    lines: np.ndarray

    def findings(self, altitude_m: float | None = None) -> list[Finding]:
        """Plausibility findings of every mapped quantity (see
        :mod:`clearfast_gis.survey.plausibility`); ``altitude_m`` sets the pressure range."""
        out: list[Finding] = []
        for q, cm in self.columns.items():
            out += check_series(q, f"{cm.column} ({q})", self.weather.time_s,
                                getattr(self.weather, q), self.lines, QUANTITIES[q][0],
                                altitude_m)
        return out


def toa5_header_lines(rows: list[list[str]], label: str) -> tuple[list[str], list[str]]:
    """The field names and units lines of TOA5 rows (stripped), after checking the header."""
    if not rows or not rows[0] or rows[0][0].strip() != "TOA5":
        raise InvalidInput('not a TOA5 file (first field should be "TOA5")', label, "line 1")
    if len(rows) < 4:
        raise InvalidInput("TOA5 header is incomplete (expected 4 header lines)", label)
    names = [h.strip() for h in rows[1]]
    if "TIMESTAMP" not in names:
        raise InvalidInput("missing column 'TIMESTAMP'", label, "line 2")
    return names, [u.strip() for u in rows[2]]


def parse_weather_table(text: str, label: str = "weather.dat",
                        profile: StationProfile | None = None,
                        required: tuple[str, ...] = WEATHER_REQUIRED) -> StationTable:
    """Parse a TOA5 weather table, its columns found by name
    (:func:`~clearfast_gis.survey.station_profiles.map_columns`: the profile, then
    Campbell's standard names) and converted to canonical units.

    Raises
    ------
    InvalidInput
        For a missing header, missing quantities (one error listing all of them and the
        file's columns), unknown units, a bad timestamp or a non-numeric value (other than
        ``NAN``).
    """
    rows = csv_rows(text, label)
    names, units = toa5_header_lines(rows, label)
    it = names.index("TIMESTAMP")
    found = map_columns(names, units, label, profile, required)
    data = rows[4:]
    n = len(data)
    time_s = np.empty(n)
    values = {q: np.full(n, np.nan) for q in QUANTITIES}
    for k, row in enumerate(data):
        line = k + 5
        time_s[k] = to_time(cell(row, it, label, line, "TIMESTAMP"), label, line, "TIMESTAMP")
        for q, cm in found.items():
            raw = to_float(cell(row, cm.index, label, line, cm.column), label, line, cm.column,
                           allow_nan=True)
            values[q][k] = cm.scale * raw + cm.offset
    return StationTable(WeatherLog(time_s=time_s, **values), found,
                        np.arange(5, 5 + n, dtype=np.int64))


def parse_toa5(text: str, label: str = "weather.dat",
               profile: StationProfile | None = None) -> WeatherLog:
    """Parse TOA5 text into a :class:`WeatherLog` in canonical units (see
    :func:`parse_weather_table`)."""
    return parse_weather_table(text, label, profile).weather


def read_toa5(path: str | os.PathLike, label: str | None = None,
              profile: StationProfile | None = None) -> WeatherLog:
    """Read a TOA5 weather file (see :func:`parse_toa5`)."""
    label = str(path) if label is None else label
    return parse_toa5(read_text(path, label), label, profile)


def _fmt(v: float) -> str:
    return '"NAN"' if not math.isfinite(v) else f"{v:.6g}"


def toa5_text(log: WeatherLog, station: str = "clearfast", table: str = "Table1min") -> str:
    """The TOA5 text of ``log`` (CRLF line endings, as the logger writes)."""
    cols = list(COLUMNS)
    head = [
        ["TOA5", station, "CR1000X", "1", "CR1000X.Std.06", "CPU:clearfast.CR1X", "1", table],
        ["TIMESTAMP", "RECORD", *cols],
        ["TS", "RN", *[COLUMNS[c][1] for c in cols]],
        ["", "", *["Tot" if c.endswith("_Tot") else "Avg" for c in cols]],
    ]
    lines = [",".join(f'"{x}"' for x in row) for row in head]
    for k in range(len(log)):
        ts = format_utc(float(log.time_s[k]), "seconds").replace("T", " ").rstrip("Z")
        vals = [_fmt(float(getattr(log, COLUMNS[c][0])[k])) for c in cols]
        lines.append(",".join([f'"{ts}"', str(k), *vals]))
    return "".join(line + "\r\n" for line in lines)


def write_toa5(path: str | os.PathLike, log: WeatherLog, station: str = "clearfast") -> os.PathLike:
    """Write ``log`` as a TOA5 file atomically."""
    return write_text(path, toa5_text(log, station))
