"""Frame tables: ``frames.csv`` and ``blackbody/frames.csv``.

The columns, their order and their types come from the JSON Schemas ``frames.schema.json`` and
``blackbody_frames.schema.json`` (one row each). Tables are held column-wise as numpy arrays;
``time_utc`` becomes ``time_s`` (UTC epoch seconds).
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass, fields

import numpy as np

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey._text import cell, csv_rows, read_text, to_float, to_int, to_time
from clearfast_gis.survey.schema import load_schema
from clearfast_gis.timeutil import format_utc


@dataclass(frozen=True)
class FramesTable:
    """The frames table, one entry per (scan, position, band) frame, arrays of length N.

    Attributes
    ----------
    scan, position, band, page : int64 (N,)
        Scan number, position index in the mission, band index into ``camera.bands``, page of
        the frame in its TIFF.
    time_s : float64 (N,)
        UTC epoch seconds of the exposure.
    pan_deg, tilt_deg : float64 (N,)
        Pan/tilt unit readout, degrees.
    file : object (N,)
        TIFF path relative to the survey folder (``/`` separators).
    """

    scan: np.ndarray
    position: np.ndarray
    band: np.ndarray
    time_s: np.ndarray
    pan_deg: np.ndarray
    tilt_deg: np.ndarray
    file: np.ndarray
    page: np.ndarray

    def __len__(self) -> int:
        return int(self.scan.shape[0])

    def __getitem__(self, name: str) -> np.ndarray:
        return getattr(self, name)

    def take(self, index: np.ndarray) -> FramesTable:
        """The rows ``index`` (integer indices or boolean mask) as a new table."""
        return type(self)(**{f.name: getattr(self, f.name)[index] for f in fields(self)})

    def to_records(self) -> np.ndarray:
        """The table as a numpy structured array (``file`` as object)."""
        names = [f.name for f in fields(self)]
        dtype = [(n, getattr(self, n).dtype) for n in names]
        out = np.empty(len(self), dtype=dtype)
        for n in names:
            out[n] = getattr(self, n)
        return out


@dataclass(frozen=True)
class BlackbodyFramesTable:
    """The blackbody frames table, arrays of length N.

    Attributes
    ----------
    event, blackbody, band, page : int64 (N,)
        Calibration event, blackbody (1 heated, 2 ambient), band index, TIFF page.
    time_s : float64 (N,)
        UTC epoch seconds.
    file : object (N,)
        TIFF path relative to the survey folder.
    """

    event: np.ndarray
    blackbody: np.ndarray
    band: np.ndarray
    time_s: np.ndarray
    file: np.ndarray
    page: np.ndarray

    def __len__(self) -> int:
        return int(self.event.shape[0])

    def __getitem__(self, name: str) -> np.ndarray:
        return getattr(self, name)

    def take(self, index: np.ndarray) -> BlackbodyFramesTable:
        """The rows ``index`` (integer indices or boolean mask) as a new table."""
        return type(self)(**{f.name: getattr(self, f.name)[index] for f in fields(self)})


def _attr(col: str) -> str:
    return "time_s" if col == "time_utc" else col


def _parse(text: str, schema_name: str, label: str) -> dict[str, np.ndarray]:
    schema = load_schema(schema_name)
    columns: list[str] = schema["x-columns"]
    props = schema["properties"]
    rows = [(i + 1, r) for i, r in enumerate(csv_rows(text, label)) if any(c.strip() for c in r)]
    if not rows:
        raise InvalidInput("empty file (no header)", label)
    header = [h.strip() for h in rows[0][1]]
    missing = [c for c in columns if c not in header]
    if missing:
        raise InvalidInput(f"missing column(s) {', '.join(missing)}; expected header "
                           f"{','.join(columns)}", label, "line 1")
    pos = {c: header.index(c) for c in columns}
    out: dict[str, list] = {c: [] for c in columns}
    for line, row in rows[1:]:
        for c in columns:
            text_c = cell(row, pos[c], label, line, c)
            spec = props[c]
            if spec.get("format") == "date-time":
                out[c].append(to_time(text_c, label, line, c))
            elif spec.get("type") == "integer" or "enum" in spec:
                v = to_int(text_c, label, line, c, spec.get("minimum"))
                if "enum" in spec and v not in spec["enum"]:
                    raise InvalidInput(f"{c}: expected {spec['x-expected']}, got {v}", label,
                                       f"line {line}")
                out[c].append(v)
            elif spec.get("type") == "number":
                out[c].append(to_float(text_c, label, line, c))
            else:
                if not text_c:
                    raise InvalidInput(f"{c}: empty", label, f"line {line}")
                out[c].append(text_c.replace("\\", "/"))
    arrays: dict[str, np.ndarray] = {}
    for c in columns:
        spec = props[c]
        if spec.get("format") == "date-time" or spec.get("type") == "number":
            dtype = np.float64
        elif spec.get("type") == "integer" or "enum" in spec:
            dtype = np.int64
        else:
            dtype = object
        arr = np.empty(len(out[c]), dtype=dtype)
        arr[:] = out[c]
        arrays[_attr(c)] = arr
    return arrays


def parse_frames_table(text: str, label: str = "frames.csv") -> FramesTable:
    """Parse ``frames.csv`` text (columns of ``frames.schema.json``) into a FramesTable."""
    return FramesTable(**_parse(text, "frames", label))


def read_frames_table(path: str | os.PathLike, label: str | None = None) -> FramesTable:
    """Read ``frames.csv`` (see :func:`parse_frames_table`)."""
    label = str(path) if label is None else label
    return parse_frames_table(read_text(path, label), label)


def parse_blackbody_frames_table(text: str, label: str = "blackbody/frames.csv"
                                 ) -> BlackbodyFramesTable:
    """Parse ``blackbody/frames.csv`` text into a BlackbodyFramesTable."""
    return BlackbodyFramesTable(**_parse(text, "blackbody_frames", label))


def read_blackbody_frames_table(path: str | os.PathLike, label: str | None = None
                                ) -> BlackbodyFramesTable:
    """Read ``blackbody/frames.csv`` (see :func:`parse_blackbody_frames_table`)."""
    label = str(path) if label is None else label
    return parse_blackbody_frames_table(read_text(path, label), label)


def _columns(table, names: list[str]) -> dict[str, np.ndarray]:
    get = (lambda k: table[k]) if isinstance(table, Mapping) else (lambda k: getattr(table, k))
    out = {}
    for c in names:
        key = _attr(c)
        try:
            out[c] = np.asarray(get(key))
        except (KeyError, AttributeError):
            if c == "time_utc":
                out[c] = np.asarray(get("time_utc"))
            else:
                raise ValueError(f"frames table has no column {key!r}") from None
    n = {len(v) for v in out.values()}
    if len(n) > 1:
        raise ValueError("frames table columns differ in length")
    return out


def _table_text(table, schema_name: str) -> str:
    schema = load_schema(schema_name)
    columns: list[str] = schema["x-columns"]
    props = schema["properties"]
    cols = _columns(table, columns)
    n = len(next(iter(cols.values())))
    fmt = []
    for c in columns:
        spec = props[c]
        v = cols[c]
        if spec.get("format") == "date-time":
            if v.dtype.kind in "fiu":
                fmt.append([format_utc(float(t)) for t in v])
            else:
                fmt.append([str(t) for t in v])
        elif spec.get("type") == "integer" or "enum" in spec:
            fmt.append([str(int(x)) for x in v])
        elif spec.get("type") == "number":
            fmt.append([f"{float(x):.6f}" for x in v])
        else:
            fmt.append([str(x).replace("\\", "/") for x in v])
    lines = [",".join(columns)]
    lines += [",".join(col[k] for col in fmt) for k in range(n)]
    return "\n".join(lines) + "\n"


def write_frames_table(path: str | os.PathLike, table: FramesTable | Mapping) -> os.PathLike:
    """Write ``frames.csv`` atomically.

    Parameters
    ----------
    path : path
        Output file.
    table : FramesTable or mapping of column name -> array
        Columns ``scan, position, band, time_s`` (epoch seconds; or ``time_utc`` text),
        ``pan_deg, tilt_deg, file, page``. Angles are written to 1e-6 degree, times to the
        millisecond.
    """
    return write_text(path, _table_text(table, "frames"))


def write_blackbody_frames_table(path: str | os.PathLike,
                                 table: BlackbodyFramesTable | Mapping) -> os.PathLike:
    """Write ``blackbody/frames.csv`` atomically (columns ``event, blackbody, band, time_s,
    file, page``)."""
    return write_text(path, _table_text(table, "blackbody_frames"))
