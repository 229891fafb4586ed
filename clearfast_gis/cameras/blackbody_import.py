"""Blackbody frames of a radiometric camera mission, brought into an imported survey.

``clearfast import ... --blackbody blackbody.csv --blackbody-log temperatures.csv``: the
blackbody table names each blackbody frame by camera file and frame number (never by
position) with its calibration event, its blackbody (1 = heated, 2 = ambient) and optionally
its time (else the file's own time tag). The files are camera files of any supported format,
found beside the table (``file`` relative to its folder). The blackbody log is the raw-count
surveys' ``blackbody/temperatures.csv`` (``time_utc,bb1_c,bb2_c``). In the survey they become
``blackbody/event_NNN_b0.tif`` stacks (the camera's stored counts, as the survey frames) with
``blackbody/frames.csv``, so that the chain's per-event camera check
(:mod:`clearfast_gis.radiometry.camera_check`) applies to the imported survey.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from clearfast_gis.cameras import RadiometricFrame, read_frames
from clearfast_gis.cameras.csv_tables import csv_records, table_time, table_value
from clearfast_gis.errors import InvalidInput

BLACKBODY_COLUMNS = ("file", "frame", "event", "blackbody", "time_utc")
"""Columns of the blackbody table; ``file``, ``event`` and ``blackbody`` are required."""
FRAMES_TABLE = "blackbody/frames.csv"
LOG_NAME = "blackbody/temperatures.csv"


@dataclass(frozen=True)
class BlackbodyRow:
    """One row of the blackbody table (``line`` for messages)."""

    line: int
    path: Path
    frame: int
    event: int
    blackbody: int
    time_s: float | None


def read_blackbody_table(path: Path) -> list[BlackbodyRow]:
    """The blackbody table ``file,frame,event,blackbody,time_utc`` (``frame`` default 0,
    ``time_utc`` may be empty). Refused, naming the file and line: an unknown file, a
    blackbody other than 1 or 2, a (file, frame) twice, an event without both blackbodies."""
    path = Path(path)
    rows: list[BlackbodyRow] = []
    seen: dict[tuple[Path, int], int] = {}
    for n, rec in csv_records(path, ("file", "event", "blackbody"), BLACKBODY_COLUMNS):
        if not rec.get("file"):
            raise InvalidInput("empty", path, f"line {n}: file")
        file = path.parent / rec["file"]
        if not file.is_file():
            raise InvalidInput(f"no camera file {rec['file']} beside the table", path,
                               f"line {n}: file")
        bb = table_value(rec, "blackbody", int, path, n, True)
        if bb not in (1, 2):
            raise InvalidInput(f"not 1 (heated) or 2 (ambient): {rec['blackbody']!r}", path,
                               f"line {n}: blackbody")
        row = BlackbodyRow(n, file, table_value(rec, "frame", int, path, n) or 0,
                           table_value(rec, "event", int, path, n, True), bb,
                           table_time(rec, path, n))
        key = (file.resolve(), row.frame)
        if key in seen:
            raise InvalidInput(f"file {rec['file']} frame {row.frame} already on line "
                               f"{seen[key]}", path, f"line {n}")
        seen[key] = n
        rows.append(row)
    if not rows:
        raise InvalidInput("no blackbody frames", path)
    for ev in sorted({r.event for r in rows}):
        of_event = [r for r in rows if r.event == ev]
        for bb in (1, 2):
            if not any(r.blackbody == bb for r in of_event):
                raise InvalidInput(f"event {ev} has no frame of blackbody {bb}", path,
                                   f"line {of_event[0].line}")
    return rows


def read_blackbody_frames(rows: list[BlackbodyRow], table: Path, read: dict
                          ) -> list[tuple[BlackbodyRow, RadiometricFrame]]:
    """The camera frame of every row. ``read`` holds the keyword arguments of
    :func:`clearfast_gis.cameras.read_frames` (unit, scale)."""
    by_file: dict[Path, list[RadiometricFrame]] = {}
    out = []
    for r in rows:
        if r.path not in by_file:
            by_file[r.path] = read_frames(r.path, **read)
        found = [f for f in by_file[r.path] if f.index == r.frame]
        if not found:
            raise InvalidInput(f"{r.path.name} has no frame {r.frame}", table,
                               f"line {r.line}: frame")
        out.append((r, found[0]))
    return out


def blackbody_stacks(matched: list[tuple[BlackbodyRow, RadiometricFrame, float]],
                     counts) -> tuple[dict[str, np.ndarray], dict[str, list]]:
    """The survey's blackbody stacks and ``blackbody/frames.csv`` columns.

    Parameters
    ----------
    matched : list of (row, frame, time_s)
        Every blackbody frame with its UTC epoch time.
    counts : callable
        Frame -> (H, W) uint16 stored counts (as the survey frames are stored).

    Returns
    -------
    stacks : dict
        Relative path ``blackbody/event_NNN_b0.tif`` -> (P, H, W) uint16, blackbody 1's
        frames first, each in table order.
    table : dict
        Columns ``event, blackbody, band, time_s, file, page``.
    """
    stacks: dict[str, np.ndarray] = {}
    table: dict[str, list] = {k: [] for k in ("event", "blackbody", "band", "time_s", "file",
                                              "page")}
    for ev in sorted({m[0].event for m in matched}):
        sel = sorted((m for m in matched if m[0].event == ev),
                     key=lambda m: (m[0].blackbody, m[0].line))
        rel = f"blackbody/event_{ev:03d}_b0.tif"
        stacks[rel] = np.stack([counts(m[1]) for m in sel])
        for page, (row, _fr, t) in enumerate(sel):
            for k, v in (("event", ev), ("blackbody", row.blackbody), ("band", 0),
                         ("time_s", t), ("file", rel), ("page", page)):
                table[k].append(v)
    return stacks, table
