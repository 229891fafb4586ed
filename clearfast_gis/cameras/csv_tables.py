"""Small CSV tables of a camera import (pose table, blackbody table): header checked, cells
parsed with errors naming the file, line and column."""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Sequence
from pathlib import Path

from clearfast_gis.errors import InvalidInput
from clearfast_gis.timeutil import parse_utc


def csv_records(path: Path, required: Sequence[str], columns: Sequence[str]
                ) -> list[tuple[int, dict]]:
    """(line number, stripped record) of a CSV table with a header row; the header must hold
    ``required`` and nothing outside ``columns``."""
    try:
        text = path.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        raise InvalidInput(f"cannot read: {exc}", path) from None
    reader = csv.DictReader(io.StringIO(text))
    header = [h.strip() for h in (reader.fieldnames or [])]
    missing = [c for c in required if c not in header]
    if missing:
        raise InvalidInput(f"missing column(s) {', '.join(missing)} (expected "
                           f"{','.join(columns)})", path, "line 1")
    unknown = [c for c in header if c not in columns]
    if unknown:
        raise InvalidInput(f"unknown column(s) {', '.join(unknown)}", path, "line 1")
    return [(n, {(k or "").strip(): (v or "").strip() for k, v in rec.items()})
            for n, rec in enumerate(reader, start=2)]


def table_value(rec: dict, col: str, kind, path: Path, line: int, required: bool = False):
    """Cell ``col`` of a CSV record as ``kind`` (int >= 0 or finite float); None when empty
    (an error when ``required``). Errors name the file, line and column."""
    val = rec.get(col, "")
    if val == "":
        if required:
            raise InvalidInput("empty", path, f"line {line}: {col}")
        return None
    try:
        out = kind(val)
    except ValueError:
        raise InvalidInput(f"not {'an integer' if kind is int else 'a number'}: "
                           f"{val!r}", path, f"line {line}: {col}") from None
    if kind is float and not math.isfinite(out):
        raise InvalidInput(f"not a finite number: {val!r}", path, f"line {line}: {col}")
    if kind is int and out < 0:
        raise InvalidInput(f"negative: {val!r}", path, f"line {line}: {col}")
    return out


def table_time(rec: dict, path: Path, line: int) -> float | None:
    """Cell ``time_utc`` of a CSV record as UTC epoch seconds (None when empty)."""
    val = rec.get("time_utc", "")
    if not val:
        return None
    try:
        return parse_utc(val)
    except ValueError as exc:
        raise InvalidInput(str(exc), path, f"line {line}: time_utc") from None

