"""Frames of an acquisition, written so that a crash loses at most the frame in flight.

Every exposure is staged at once as a file of its own (atomically: temporary name, then
rename), ``acquisition/incoming/scan_003/pos_00012.tif`` for a scan position or
``.../bb1_004.tif`` for the fifth frame of blackbody 1 in the scan's calibration event: one
page per band, and in the first page's description the scan, position or blackbody, the
exposure time of each band and the pan/tilt read-back.

At the end of each calibration event and each scan (and when a run stops or fails, and when a
new run finds staged files of an earlier one) the staged exposures are consolidated into the
survey format: one multi-page TIFF per scan and band (``frames/scan_003_b0.tif``, pages in
mission order) or per event and band (``blackbody/event_003_b0.tif``, blackbody 1 then 2), and
``frames.csv`` / ``blackbody/frames.csv`` rewritten atomically with the rows of the other
scans kept. Each consolidated TIFF also stores which exposure each page holds, with its time
and angles, so that consolidation can be repeated after a crash at any point (new TIFF
written, table not yet) and gives the same files: the pages already consolidated are merged
with the staged ones (a staged exposure replaces a consolidated one of the same key), and the
staged files are deleted last.
"""

from __future__ import annotations

import contextlib
import os
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from clearfast_gis.survey.tables import (
    read_blackbody_frames_table,
    read_frames_table,
    write_blackbody_frames_table,
    write_frames_table,
)
from clearfast_gis.survey.tiff import read_tiff_stack, tiff_metadata, write_tiff_stack
from clearfast_gis.timeutil import format_utc, parse_utc

#: staging folder, relative to the survey folder
INCOMING = "acquisition/incoming"

POSITION = "position"
BLACKBODY = "blackbody"

_STAGED = re.compile(r"^(?:pos_(\d+)|bb([12])_(\d+))\.tif$")
_SCAN_DIR = re.compile(r"^scan_(\d+)$")
_META = "clearfast_exposures"


@dataclass(frozen=True)
class Capture:
    """One exposure of a scan position or of a blackbody.

    Attributes
    ----------
    scan : int
        Scan number (= calibration event number for blackbody frames).
    kind : str
        :data:`POSITION` or :data:`BLACKBODY`.
    index : int
        Mission position index, or blackbody number (1 heated, 2 ambient).
    repeat : int
        Frame number at a blackbody (0 for positions).
    pan_deg, tilt_deg : float
        Pan/tilt unit read-back, degrees.
    time_s : tuple of float
        UTC epoch seconds of each band's exposure.
    counts : uint16 (B, H, W)
        Raw counts.
    """

    scan: int
    kind: str
    index: int
    repeat: int
    pan_deg: float
    tilt_deg: float
    time_s: tuple[float, ...]
    counts: np.ndarray

    @property
    def key(self) -> tuple[str, int, int]:
        """``(kind, index, repeat)``: what the exposure is within its scan."""
        return self.kind, self.index, self.repeat


def staged_name(kind: str, index: int, repeat: int) -> str:
    """File name of a staged exposure: ``pos_00012.tif`` or ``bb1_004.tif``."""
    return f"pos_{index:05d}.tif" if kind == POSITION else f"bb{index}_{repeat:03d}.tif"


def scan_tiff_name(scan: int, band: int) -> str:
    """Survey-relative TIFF path of a scan and band: ``frames/scan_000_b0.tif``."""
    return f"frames/scan_{scan:03d}_b{band}.tif"


def event_tiff_name(event: int, band: int) -> str:
    """Survey-relative TIFF path of a calibration event and band:
    ``blackbody/event_000_b0.tif``."""
    return f"blackbody/event_{event:03d}_b{band}.tif"


@dataclass
class _Page:
    """A consolidated or staged exposure of one band."""

    image: np.ndarray
    time_s: float
    pan_deg: float
    tilt_deg: float


class FrameStore:
    """Staging and consolidation of a survey folder's frames.

    Parameters
    ----------
    root : path
        Survey folder.
    frames_rel, blackbody_frames_rel : str
        Survey-relative names of the two frame tables.
    position_order : callable
        ``position_order(index) -> rank``: the order of positions in a scan (the mission's).
    """

    def __init__(self, root: str | os.PathLike, frames_rel: str = "frames.csv",
                 blackbody_frames_rel: str = "blackbody/frames.csv",
                 position_order: Callable[[int], int] = int) -> None:
        self.root = Path(root)
        self.frames_rel = frames_rel
        self.blackbody_frames_rel = blackbody_frames_rel
        self.position_order = position_order

    # -- staging ----------------------------------------------------------------------------

    def _scan_dir(self, scan: int) -> Path:
        return self.root / INCOMING / f"scan_{scan:03d}"

    def stage(self, cap: Capture) -> Path:
        """Write one exposure to its staging file (atomically)."""
        path = self._scan_dir(cap.scan) / staged_name(*cap.key)
        write_tiff_stack(path, np.asarray(cap.counts, np.uint16), {_META: {
            "scan": cap.scan, "kind": cap.kind, "index": cap.index, "repeat": cap.repeat,
            "pan_deg": cap.pan_deg, "tilt_deg": cap.tilt_deg,
            "time_utc": [format_utc(t) for t in cap.time_s]}})
        return path

    def recover(self) -> list[int]:
        """After a crash: delete half-written staging files (the exposure that was in flight)
        and consolidate what earlier runs staged; returns the scans consolidated."""
        base = self.root / INCOMING
        if base.is_dir():
            for d in base.iterdir():
                for f in d.iterdir() if d.is_dir() else ():
                    if f.name.startswith(".") and f.name.endswith(".part"):
                        with contextlib.suppress(OSError):
                            f.unlink()
        scans = self.staged_scans()
        for s in scans:
            self.consolidate(s)
        return scans

    def staged_scans(self) -> list[int]:
        """Scans with staged exposures (left by a run that did not consolidate them)."""
        base = self.root / INCOMING
        if not base.is_dir():
            return []
        return sorted(int(m.group(1)) for d in base.iterdir() if (m := _SCAN_DIR.match(d.name))
                      and any(_STAGED.match(f.name) for f in d.iterdir()))

    def _staged_files(self, scan: int) -> list[tuple[tuple[str, int, int], Path]]:
        d = self._scan_dir(scan)
        out = []
        if d.is_dir():
            for f in sorted(d.iterdir()):
                m = _STAGED.match(f.name)
                if m and m.group(1) is not None:
                    out.append(((POSITION, int(m.group(1)), 0), f))
                elif m:
                    out.append(((BLACKBODY, int(m.group(2)), int(m.group(3))), f))
        return out

    def read_staged(self, path: Path) -> Capture:
        """Read a staged exposure back."""
        meta = tiff_metadata(path)[_META]
        counts = np.array(read_tiff_stack(path))
        return Capture(int(meta["scan"]), str(meta["kind"]), int(meta["index"]),
                       int(meta["repeat"]), float(meta["pan_deg"]), float(meta["tilt_deg"]),
                       tuple(parse_utc(t) for t in meta["time_utc"]), counts)

    # -- what is there ----------------------------------------------------------------------

    def taken(self, scan: int) -> set[tuple[str, int, int]]:
        """Keys of the exposures of ``scan`` already kept, consolidated or staged."""
        keys = {k for k, _ in self._staged_files(scan)}
        fr = self._table(POSITION)
        if fr is not None:
            keys |= {(POSITION, int(p), 0) for p in fr.position[fr.scan == scan]}
        bb = self._table(BLACKBODY)
        if bb is not None:
            sel = (bb.event == scan) & (bb.band == bb.band.min()) if len(bb) else bb.event < 0
            keys |= set(_blackbody_keys(bb.blackbody[sel], bb.page[sel]))
        return keys

    def _table(self, kind: str):
        rel = self.frames_rel if kind == POSITION else self.blackbody_frames_rel
        path = self.root / rel
        if not path.exists():
            return None
        return (read_frames_table if kind == POSITION else read_blackbody_frames_table)(path,
                                                                                          rel)

    # -- consolidation ----------------------------------------------------------------------

    def consolidate(self, scan: int) -> None:
        """Merge the staged exposures of ``scan`` into the survey's TIFFs and tables, then
        delete them (safe to repeat after a crash at any point)."""
        staged = self._staged_files(scan)
        if not staged:
            return
        captures = [self.read_staged(f) for _, f in staged]
        for kind in (BLACKBODY, POSITION):
            mine = [c for c in captures if c.kind == kind]
            if mine:
                self._merge(scan, kind, mine)
        for _, f in staged:
            with contextlib.suppress(FileNotFoundError):
                f.unlink()
        with contextlib.suppress(OSError):
            self._scan_dir(scan).rmdir()
            (self.root / INCOMING).rmdir()

    def _sort_key(self, key: tuple[str, int, int]) -> tuple[int, int]:
        kind, index, repeat = key
        return (self.position_order(index), 0) if kind == POSITION else (index, repeat)

    def _merge(self, scan: int, kind: str, captures: list[Capture]) -> None:
        n_bands = captures[0].counts.shape[0]
        name = scan_tiff_name if kind == POSITION else event_tiff_name
        table = self._table(kind)
        new_rows: list[dict] = []
        order: list[tuple[str, int, int]] = []
        for b in range(n_bands):
            pages = self._consolidated(scan, kind, b, table)
            for c in captures:
                pages[c.key] = _Page(c.counts[b], c.time_s[b], c.pan_deg, c.tilt_deg)
            order = sorted(pages, key=self._sort_key)
            rel = name(scan, b)
            write_tiff_stack(self.root / rel, np.stack([pages[k].image for k in order]), {_META: {
                "scan": scan, "kind": kind, "keys": [[k[1], k[2]] for k in order],
                "time_utc": [format_utc(pages[k].time_s) for k in order],
                "pan_deg": [pages[k].pan_deg for k in order],
                "tilt_deg": [pages[k].tilt_deg for k in order]}})
            for page, k in enumerate(order):
                p = pages[k]
                if kind == POSITION:
                    new_rows.append({"scan": scan, "position": k[1], "band": b,
                                     "time_s": p.time_s, "pan_deg": p.pan_deg,
                                     "tilt_deg": p.tilt_deg, "file": rel, "page": page})
                else:
                    new_rows.append({"event": scan, "blackbody": k[1], "band": b,
                                     "time_s": p.time_s, "file": rel, "page": page})
        self._write_table(kind, table, scan, new_rows)

    def _consolidated(self, scan: int, kind: str, band: int, table
                      ) -> dict[tuple[str, int, int], _Page]:
        """The pages already consolidated for (scan, kind, band), by key."""
        rel = (scan_tiff_name if kind == POSITION else event_tiff_name)(scan, band)
        path = self.root / rel
        if not path.exists():
            return {}
        stack = read_tiff_stack(path, label=rel)
        meta = tiff_metadata(path, rel).get(_META)
        if meta is not None:  # written here: the file says what each page holds
            return {(kind, int(i), int(r)): _Page(np.array(stack[k]), parse_utc(t), float(pa),
                                                  float(ti))
                    for k, ((i, r), t, pa, ti) in enumerate(zip(
                        meta["keys"], meta["time_utc"], meta["pan_deg"], meta["tilt_deg"],
                        strict=True))}
        if table is None:  # a TIFF the table does not describe: nothing to keep
            return {}
        group = table.scan if kind == POSITION else table.event
        sel = np.flatnonzero((group == scan) & (table.band == band))
        if kind == POSITION:
            keys = [(POSITION, int(table.position[i]), 0) for i in sel]
            angles = [(float(table.pan_deg[i]), float(table.tilt_deg[i])) for i in sel]
        else:
            keys = _blackbody_keys(table.blackbody[sel], table.page[sel])
            angles = [(np.nan, np.nan)] * len(sel)
        return {k: _Page(np.array(stack[int(table.page[i])]), float(table.time_s[i]), *a)
                for k, i, a in zip(keys, sel, angles, strict=True)}

    def _write_table(self, kind: str, table, scan: int, new_rows: list[dict]) -> None:
        if kind == POSITION:
            cols = ("scan", "position", "band", "time_s", "pan_deg", "tilt_deg", "file", "page")
            group, writer, rel = "scan", write_frames_table, self.frames_rel
        else:
            cols = ("event", "blackbody", "band", "time_s", "file", "page")
            group, writer, rel = "event", write_blackbody_frames_table, self.blackbody_frames_rel
        rows: dict[str, list] = {c: [] for c in cols}
        if table is not None:
            keep = np.flatnonzero(getattr(table, group) != scan)
            for c in cols:
                rows[c] = list(getattr(table, c)[keep])
        for r in new_rows:
            for c in cols:
                rows[c].append(r[c])
        order = np.lexsort((np.asarray(rows["band"]), np.asarray(rows["page"]),
                            np.asarray(rows[group])))
        writer(self.root / rel, {c: np.asarray(rows[c], dtype=object if c == "file" else None
                                               )[order] for c in cols})


def _blackbody_keys(blackbody: np.ndarray, page: np.ndarray) -> list[tuple[str, int, int]]:
    """Keys of blackbody rows: the frame number is the rank by page within each blackbody."""
    keys: list[tuple[str, int, int]] = []
    seen: dict[int, int] = {}
    for k in np.argsort(page, kind="stable"):
        bb = int(blackbody[k])
        seen[bb] = seen.get(bb, -1) + 1
        keys.append((BLACKBODY, bb, seen[bb]))
    out: list[tuple[str, int, int]] = [keys[0]] * len(keys) if keys else []
    for rank, k in enumerate(np.argsort(page, kind="stable")):
        out[int(k)] = keys[rank]
    return out
