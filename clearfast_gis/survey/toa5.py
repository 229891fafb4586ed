"""Campbell Scientific TOA5 weather tables (1-minute records, UTC timestamps).

A TOA5 file has four header lines (environment, field names, units, processing) and then one
quoted-CSV record per line; missing values are ``"NAN"``. Columns are found by name; the units
row is checked against the units this toolkit expects.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

import numpy as np

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey._text import cell, csv_rows, read_text, to_float, to_time
from clearfast_gis.timeutil import format_utc

#: TOA5 column -> (WeatherLog attribute, accepted units (lower case), required)
COLUMNS: dict[str, tuple[str, tuple[str, ...], bool]] = {
    "AirTC_Avg": ("air_temp_c", ("deg c", "degc", "°c", "c"), True),
    "RH_Avg": ("rh_pct", ("%",), True),
    "BP_hPa_Avg": ("pressure_hpa", ("hpa", "mbar", "mb"), True),
    "WS_ms_Avg": ("wind_ms", ("meters/second", "m/s"), True),
    "SlrW_Avg": ("solar_wm2", ("w/m^2", "w/m2", "w m-2"), True),
    "IRSky_Avg": ("sky_lw_wm2", ("w/m^2", "w/m2", "w m-2"), False),
    "Rain_mm_Tot": ("rain_mm", ("mm",), False),
}

#: units written by :func:`write_toa5`
UNITS_OUT = {"AirTC_Avg": "Deg C", "RH_Avg": "%", "BP_hPa_Avg": "hPa",
             "WS_ms_Avg": "meters/second", "SlrW_Avg": "W/m^2", "IRSky_Avg": "W/m^2",
             "Rain_mm_Tot": "mm"}


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


def parse_toa5(text: str, label: str = "weather.dat") -> WeatherLog:
    """Parse TOA5 text into a :class:`WeatherLog` (see module docstring).

    Raises
    ------
    InvalidInput
        For a missing header, a missing required column, unexpected units, a bad timestamp or
        a non-numeric value (other than ``NAN``).
    """
    rows = csv_rows(text, label)
    if not rows or not rows[0] or rows[0][0].strip() != "TOA5":
        raise InvalidInput('not a TOA5 file (first field should be "TOA5")', label, "line 1")
    if len(rows) < 4:
        raise InvalidInput("TOA5 header is incomplete (expected 4 header lines)", label)
    names = [h.strip() for h in rows[1]]
    units = [u.strip() for u in rows[2]]
    if "TIMESTAMP" not in names:
        raise InvalidInput("missing column 'TIMESTAMP'", label, "line 2")
    it = names.index("TIMESTAMP")
    found: dict[str, int] = {}
    for col, (_, accepted, required) in COLUMNS.items():
        if col not in names:
            if required:
                raise InvalidInput(f"missing column {col!r}", label, "line 2")
            continue
        i = names.index(col)
        unit = units[i].lower() if i < len(units) else ""
        if unit not in accepted:
            raise InvalidInput(f"{col}: unit {unit!r}, expected {UNITS_OUT[col]!r}", label,
                               "line 3")
        found[col] = i
    data = rows[4:]
    n = len(data)
    time_s = np.empty(n)
    values = {col: np.full(n, np.nan) for col in COLUMNS}
    for k, row in enumerate(data):
        line = k + 5
        time_s[k] = to_time(cell(row, it, label, line, "TIMESTAMP"), label, line, "TIMESTAMP")
        for col, i in found.items():
            values[col][k] = to_float(cell(row, i, label, line, col), label, line, col,
                                      allow_nan=True)
    return WeatherLog(time_s=time_s, **{COLUMNS[c][0]: v for c, v in values.items()})


def read_toa5(path: str | os.PathLike, label: str | None = None) -> WeatherLog:
    """Read a TOA5 weather file (see :func:`parse_toa5`)."""
    label = str(path) if label is None else label
    return parse_toa5(read_text(path, label), label)


def _fmt(v: float) -> str:
    return '"NAN"' if not math.isfinite(v) else f"{v:.6g}"


def toa5_text(log: WeatherLog, station: str = "clearfast", table: str = "Table1min") -> str:
    """The TOA5 text of ``log`` (CRLF line endings, as the logger writes)."""
    cols = list(COLUMNS)
    head = [
        ["TOA5", station, "CR1000X", "1", "CR1000X.Std.06", "CPU:clearfast.CR1X", "1", table],
        ["TIMESTAMP", "RECORD", *cols],
        ["TS", "RN", *[UNITS_OUT[c] for c in cols]],
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
