"""Small helpers shared by the text-format parsers: file reading, CSV rows, typed columns."""

from __future__ import annotations

import csv
import io
import math
import os
from pathlib import Path

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.timeutil import parse_utc

#: the largest text log a parser accepts (a 24 h, 10 Hz NMEA log is ~40 MB)
MAX_TEXT_BYTES = 2_000_000_000


def read_text(path: str | os.PathLike, label: str | None = None, errors: str = "strict") -> str:
    """Read a text file (UTF-8, BOM tolerated) or raise :class:`InvalidInput` naming it.

    ``errors="replace"`` reads a raw instrument log that may hold line noise: undecodable
    bytes become U+FFFD, so that their lines are skipped and counted by the parser instead of
    making the whole file unreadable.
    """
    label = str(path) if label is None else label
    p = Path(path)
    try:
        data = p.read_bytes()
    except FileNotFoundError:
        raise InvalidInput("file not found", label) from None
    except IsADirectoryError:
        raise InvalidInput("is a folder, expected a file", label) from None
    except OSError as exc:
        raise InvalidInput(f"cannot read: {exc.strerror or exc}", label) from None
    try:
        return data.decode("utf-8-sig", errors=errors)
    except UnicodeDecodeError as exc:
        raise InvalidInput(f"not UTF-8 text (byte {exc.start})", label) from None


def csv_rows(text: str, label: str) -> list[list[str]]:
    """Rows of comma-separated ``text`` (quotes honoured), blank lines dropped."""
    if "\x00" in text:
        raise InvalidInput("contains NUL bytes (binary or corrupt file)", label)
    try:
        rows = list(csv.reader(io.StringIO(text, newline="")))
    except csv.Error as exc:
        raise InvalidInput(f"not valid CSV: {exc}", label) from None
    return rows


def header_index(header: list[str], required: list[str], label: str) -> dict[str, int]:
    """Column positions of ``required`` in ``header`` (names stripped)."""
    names = [h.strip() for h in header]
    index: dict[str, int] = {}
    for col in required:
        if col not in names:
            raise InvalidInput(f"missing column {col!r} (header: {','.join(names)[:200]})",
                               label, "line 1")
        index[col] = names.index(col)
    return index


def cell(row: list[str], i: int, label: str, line: int, col: str) -> str:
    """The stripped text of column ``i`` of ``row``, or :class:`InvalidInput` if short."""
    if i >= len(row):
        raise InvalidInput(f"row has {len(row)} fields, column {col!r} missing", label,
                           f"line {line}")
    return row[i].strip()


def to_int(text: str, label: str, line: int, col: str, minimum: int | None = 0) -> int:
    """Parse an integer cell (``"3"``) with a one-line error naming line and column."""
    try:
        value = int(text)
    except ValueError:
        raise InvalidInput(f"{col}: expected an integer, got {text[:40]!r}", label,
                           f"line {line}") from None
    if minimum is not None and value < minimum:
        raise InvalidInput(f"{col}: expected an integer >= {minimum}, got {value}", label,
                           f"line {line}")
    return value


def to_float(text: str, label: str, line: int, col: str, allow_nan: bool = False) -> float:
    """Parse a float cell; ``NAN``/empty give NaN only when ``allow_nan``; inf is refused."""
    t = text.strip().strip('"')
    if allow_nan and t.upper() in ("NAN", "", "NA", "-NAN"):
        return math.nan
    try:
        value = float(t)
    except ValueError:
        raise InvalidInput(f"{col}: expected a number, got {text[:40]!r}", label,
                           f"line {line}") from None
    if math.isnan(value) and not allow_nan or math.isinf(value):
        raise InvalidInput(f"{col}: expected a finite number, got {text[:40]!r}", label,
                           f"line {line}")
    return value


def to_time(text: str, label: str, line: int, col: str) -> float:
    """Parse an ISO 8601 UTC cell to epoch seconds."""
    try:
        value = parse_utc(text.strip().strip('"'))
    except (ValueError, TypeError, OverflowError, OSError):
        raise InvalidInput(f"{col}: expected an ISO 8601 UTC time, got {text[:40]!r}", label,
                           f"line {line}") from None
    return value


def as_array(values: list, dtype) -> np.ndarray:
    """A 1-D numpy array of ``values`` (empty lists keep the dtype)."""
    return np.asarray(values, dtype=dtype).reshape(-1)
