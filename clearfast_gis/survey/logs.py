"""Small CSV logs of the survey folder: soil thermocouples, blackbody temperatures, markers."""

from __future__ import annotations

import csv
import io
import math
import os
import re
from dataclasses import dataclass

import numpy as np

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey._text import (
    cell,
    csv_rows,
    header_index,
    read_text,
    to_float,
    to_time,
)
from clearfast_gis.survey.station_profiles import StationProfile, unit_conversion
from clearfast_gis.survey.toa5 import toa5_header_lines
from clearfast_gis.timeutil import format_utc

_SOIL_COL = re.compile(r"^T_(\d+(?:\.\d+)?)m_C$")


@dataclass(frozen=True)
class SoilLog:
    """Soil thermocouple temperatures.

    Attributes
    ----------
    time_s : float64 (T,)
        UTC epoch seconds.
    depth_m : float64 (D,)
        Thermocouple depths below the surface, metres, increasing.
    temp_c : float64 (T, D)
        Temperatures, degrees C; NaN where the logger wrote NAN or nothing.
    columns : tuple of str
        The file's column of each depth (same order as ``depth_m``), for messages; empty
        for a log that did not come from a file.
    """

    time_s: np.ndarray
    depth_m: np.ndarray
    temp_c: np.ndarray
    columns: tuple[str, ...] = ()


@dataclass(frozen=True)
class BlackbodyLog:
    """Blackbody temperature readouts, one record a minute.

    Attributes
    ----------
    time_s : float64 (T,)
        UTC epoch seconds.
    bb1_c, bb2_c : float64 (T,)
        Heated (1) and ambient (2) blackbody temperatures, degrees C.
    """

    time_s: np.ndarray
    bb1_c: np.ndarray
    bb2_c: np.ndarray


@dataclass(frozen=True)
class Markers:
    """Surveyed reference points (WGS84).

    Attributes
    ----------
    id : tuple of str (M,)
    lat_deg, lon_deg : float64 (M,)
    description : tuple of str (M,)
    """

    id: tuple[str, ...]
    lat_deg: np.ndarray
    lon_deg: np.ndarray
    description: tuple[str, ...]

    def __len__(self) -> int:
        return len(self.id)


def _data_rows(text: str, label: str) -> tuple[list[str], list[tuple[int, list[str]]]]:
    rows = csv_rows(text, label)
    numbered = [(i + 1, r) for i, r in enumerate(rows) if any(c.strip() for c in r)]
    if not numbered:
        raise InvalidInput("empty file (no header)", label)
    return [h.strip() for h in numbered[0][1]], numbered[1:]


def parse_soil_log(text: str, label: str = "soil.csv",
                   profile: StationProfile | None = None) -> SoilLog:
    """Parse ``time_utc,T_<depth>m_C,...`` CSV text, or a logger's TOA5 thermocouple table
    with the depths of its columns in a station profile (``soil.depths``), into a
    :class:`SoilLog` sorted by depth, degrees C."""
    if text.lstrip('\ufeff"').startswith("TOA5"):
        return _parse_soil_toa5(text, label, profile)
    header, rows = _data_rows(text, label)
    if not header or header[0] != "time_utc":
        raise InvalidInput("first column must be 'time_utc'", label, "line 1")
    depths: list[float] = []
    for name in header[1:]:
        m = _SOIL_COL.match(name)
        if not m:
            raise InvalidInput(f"column {name[:40]!r} is not T_<depth>m_C", label, "line 1")
        depths.append(float(m.group(1)))
    if not depths:
        raise InvalidInput("no thermocouple column (T_<depth>m_C)", label, "line 1")
    if len(set(depths)) != len(depths):
        raise InvalidInput("two columns have the same depth", label, "line 1")
    t = np.empty(len(rows))
    temp = np.empty((len(rows), len(depths)))
    for k, (line, row) in enumerate(rows):
        t[k] = to_time(row[0], label, line, "time_utc")
        for j in range(len(depths)):
            col = header[j + 1]
            temp[k, j] = to_float(cell(row, j + 1, label, line, col), label, line, col,
                                  allow_nan=True)
    order = np.argsort(depths)
    return SoilLog(time_s=t, depth_m=np.asarray(depths)[order], temp_c=temp[:, order],
                   columns=tuple(header[1 + int(j)] for j in order))


#: soil temperature columns whose name states the depth (``Tsoil_5cm_Avg``, ``TC_10cm``,
#: ``SoilT_0.05m``, ``T_0.050m_C``): recognised without a profile
_DEPTH_NAME = re.compile(r"^(?:t|ts|tsoil|soilt|soiltemp|tc|temp)_?(\d+(?:\.\d+)?)(cm|mm|m)"
                         r"(?:_c)?(?:_avg)?$", re.IGNORECASE)
_DEPTH_UNIT_M = {"cm": 0.01, "mm": 0.001, "m": 1.0}


def _depths_from_names(names: list[str]) -> dict[str, float]:
    """Columns whose name states a depth (see :data:`_DEPTH_NAME`) -> depth, metres."""
    out = {}
    for n in names:
        m = _DEPTH_NAME.match(n.strip())
        if m:
            out[n.strip()] = float(m.group(1)) * _DEPTH_UNIT_M[m.group(2).lower()]
    return out


def _parse_soil_toa5(text: str, label: str, profile: StationProfile | None) -> SoilLog:
    """A TOA5 thermocouple table: columns and depths from the station profile, else from
    column names that state the depth."""
    rows = csv_rows(text, label)
    names, units = toa5_header_lines(rows, label)
    depths = profile.soil_columns if profile is not None else None
    if not depths:
        depths = _depths_from_names(names)
        if len(set(depths.values())) != len(depths):
            raise InvalidInput("two columns have the same depth", label, "line 2")
    if not depths:
        raise InvalidInput("a TOA5 table as the soil log needs the depth of each thermocouple "
                           f"column; the file has columns {', '.join(names)}; give them in a "
                           'station profile: "soil": {"unit": "deg C", "depths": [{"column": '
                           '"<name>", "depth_m": 0.05}, ...]} (docs/acquire.md)', label,
                           "line 2")
    lower = {n.lower(): i for i, n in enumerate(names)}
    absent = [c for c in depths if c.lower() not in lower]
    if absent:
        raise InvalidInput(f"profile column(s) {', '.join(absent)} not in the file; the file "
                           f"has columns {', '.join(names)}", label, "line 2")
    cols = sorted(depths, key=lambda c: depths[c])
    idx = [lower[c.lower()] for c in cols]
    soil_unit = profile.soil_unit if profile is not None else None
    conv = [unit_conversion(soil_unit or (units[i] if i < len(units) else ""),
                            "soil_temp_c", label, f"line 3: {names[i]}") for i in idx]
    it = names.index("TIMESTAMP")
    data = rows[4:]
    t = np.empty(len(data))
    temp = np.empty((len(data), len(cols)))
    for k, row in enumerate(data):
        line = k + 5
        t[k] = to_time(cell(row, it, label, line, "TIMESTAMP"), label, line, "TIMESTAMP")
        for j, (i, (scale, offset)) in enumerate(zip(idx, conv, strict=True)):
            raw = to_float(cell(row, i, label, line, names[i]), label, line, names[i],
                           allow_nan=True)
            temp[k, j] = scale * raw + offset
    return SoilLog(time_s=t, depth_m=np.array([depths[c] for c in cols]), temp_c=temp,
                   columns=tuple(names[i] for i in idx))


def read_soil_log(path: str | os.PathLike, label: str | None = None,
                  profile: StationProfile | None = None) -> SoilLog:
    """Read a soil thermocouple log (see :func:`parse_soil_log`)."""
    label = str(path) if label is None else label
    return parse_soil_log(read_text(path, label), label, profile)


def _fmt(v: float) -> str:
    return "NAN" if not math.isfinite(v) else f"{v:.4f}"


def write_soil_log(path: str | os.PathLike, log: SoilLog) -> os.PathLike:
    """Write a :class:`SoilLog` as CSV atomically (depth in the column names, 3 decimals)."""
    temp = np.asarray(log.temp_c, dtype=float).reshape(len(log.time_s), len(log.depth_m))
    lines = ["time_utc," + ",".join(f"T_{d:.3f}m_C" for d in log.depth_m)]
    for k, t in enumerate(log.time_s):
        lines.append(format_utc(float(t), "seconds") + "," +
                     ",".join(_fmt(float(v)) for v in temp[k]))
    return write_text(path, "\n".join(lines) + "\n")


def parse_blackbody_log(text: str, label: str = "blackbody/temperatures.csv") -> BlackbodyLog:
    """Parse ``time_utc,bb1_c,bb2_c`` CSV text into a :class:`BlackbodyLog`."""
    header, rows = _data_rows(text, label)
    idx = header_index(header, ["time_utc", "bb1_c", "bb2_c"], label)
    n = len(rows)
    t, b1, b2 = np.empty(n), np.empty(n), np.empty(n)
    for k, (line, row) in enumerate(rows):
        t[k] = to_time(cell(row, idx["time_utc"], label, line, "time_utc"), label, line,
                       "time_utc")
        b1[k] = to_float(cell(row, idx["bb1_c"], label, line, "bb1_c"), label, line, "bb1_c")
        b2[k] = to_float(cell(row, idx["bb2_c"], label, line, "bb2_c"), label, line, "bb2_c")
    return BlackbodyLog(time_s=t, bb1_c=b1, bb2_c=b2)


def read_blackbody_log(path: str | os.PathLike, label: str | None = None) -> BlackbodyLog:
    """Read ``blackbody/temperatures.csv`` (see :func:`parse_blackbody_log`)."""
    label = str(path) if label is None else label
    return parse_blackbody_log(read_text(path, label), label)


def write_blackbody_log(path: str | os.PathLike, log: BlackbodyLog) -> os.PathLike:
    """Write a :class:`BlackbodyLog` as CSV atomically."""
    lines = ["time_utc,bb1_c,bb2_c"]
    for t, a, b in zip(log.time_s, log.bb1_c, log.bb2_c, strict=True):
        lines.append(f"{format_utc(float(t), 'seconds')},{float(a):.4f},{float(b):.4f}")
    return write_text(path, "\n".join(lines) + "\n")


def parse_markers(text: str, label: str = "markers.csv") -> Markers:
    """Parse ``id,lat_deg,lon_deg,description`` CSV text into :class:`Markers`."""
    header, rows = _data_rows(text, label)
    idx = header_index(header, ["id", "lat_deg", "lon_deg"], label)
    ids, lat, lon, desc = [], [], [], []
    di = header.index("description") if "description" in header else None
    for line, row in rows:
        ids.append(cell(row, idx["id"], label, line, "id"))
        la = to_float(cell(row, idx["lat_deg"], label, line, "lat_deg"), label, line, "lat_deg")
        lo = to_float(cell(row, idx["lon_deg"], label, line, "lon_deg"), label, line, "lon_deg")
        if not (-90 <= la <= 90 and -180 <= lo <= 180):
            raise InvalidInput("lat_deg/lon_deg: outside WGS84 range", label, f"line {line}")
        lat.append(la)
        lon.append(lo)
        desc.append(row[di].strip() if di is not None and di < len(row) else "")
    return Markers(id=tuple(ids), lat_deg=np.asarray(lat, dtype=float),
                   lon_deg=np.asarray(lon, dtype=float), description=tuple(desc))


def read_markers(path: str | os.PathLike, label: str | None = None) -> Markers:
    """Read ``markers.csv`` (see :func:`parse_markers`)."""
    label = str(path) if label is None else label
    return parse_markers(read_text(path, label), label)


def write_markers(path: str | os.PathLike, markers: Markers) -> os.PathLike:
    """Write :class:`Markers` as CSV atomically (9 decimals of a degree, about 0.1 mm)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["id", "lat_deg", "lon_deg", "description"])
    for i, la, lo, d in zip(markers.id, markers.lat_deg, markers.lon_deg, markers.description,
                            strict=True):
        w.writerow([i, f"{float(la):.9f}", f"{float(lo):.9f}", d])
    return write_text(path, buf.getvalue())
