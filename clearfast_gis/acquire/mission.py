"""Stop-and-go execution of a scanning mission (``mission.json``, paper §2.2).

For each scan (started every ``scan_interval_s`` from the mission start) and each position in
the mission's order: move the pan/tilt unit and wait for completion, wait ``settle_s`` for the
boom to stop swaying, take the time and trigger the camera, then record the unit's read-back
angles. At the end of each scan the frames are written as the survey format expects: one
multi-page uint16 TIFF per scan and band (``frames/scan_000_b0.tif``, page = position order)
and ``frames.csv`` rewritten atomically with every row so far (rows of earlier runs kept, so
an interrupted mission can be continued with ``scans=``). A scan's frames are held in memory
until it ends (P x B x H x W x 2 bytes: 171 MB per band for 261 positions of 640 x 512).

The camera is a callable returning one frame: (H, W) uint16 for a one-band camera or
(B, H, W) uint16 for B bands (filter wheel or multi-sensor). The pan/tilt unit is anything
with ``move_to(pan_deg, tilt_deg) -> (pan_deg, tilt_deg)`` that returns after the move is
complete (:class:`~clearfast_gis.acquire.ptu.PanTiltUnit`).
"""

from __future__ import annotations

import os
import threading
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Protocol

import numpy as np

from clearfast_gis.errors import ClearfastError, InvalidInput
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.survey.manifest import manifest_problems, write_mission, write_survey_json
from clearfast_gis.survey.tables import read_frames_table, write_frames_table
from clearfast_gis.survey.tiff import write_tiff_stack

FRAME_COLUMNS = ("scan", "position", "band", "time_s", "pan_deg", "tilt_deg", "file", "page")


class PointingUnit(Protocol):
    """What the runner needs of a pan/tilt unit."""

    def move_to(self, pan_deg: float, tilt_deg: float) -> tuple[float, float]:
        """Move, wait for completion, return the read-back (pan_deg, tilt_deg)."""
        ...


@dataclass
class MissionResult:
    """What a run did.

    Attributes
    ----------
    scans : list of int
        Scans written (complete or, when stopped, partial).
    n_frames : int
        Frames taken (positions; each gives one row per band).
    late_scans : list of int
        Scans that started after their planned time (the previous scan overran).
    stopped : bool
        True when a stop request ended the run early.
    """

    scans: list[int] = field(default_factory=list)
    n_frames: int = 0
    late_scans: list[int] = field(default_factory=list)
    stopped: bool = False


def scan_tiff_name(scan: int, band: int) -> str:
    """Survey-relative TIFF path of a scan and band: ``frames/scan_000_b0.tif``."""
    return f"frames/scan_{scan:03d}_b{band}.tif"


def _as_bands(frame: object, expected: tuple[int, ...] | None, source: str) -> np.ndarray:
    """The camera's frame as a (B, H, W) uint16 array, checked against earlier frames."""
    a = np.asarray(frame)
    if a.dtype != np.uint16 or a.ndim not in (2, 3):
        raise ClearfastError(f"camera returned a {a.shape} {a.dtype} array, expected "
                             "(H, W) or (B, H, W) uint16", "camera")
    if a.ndim == 2:
        a = a[None]
    if expected is not None and a.shape != expected:
        raise ClearfastError(f"camera returned a frame of shape {a.shape}, expected {expected} "
                             f"(bands, H, W) from {source}", "camera")
    return a


class MissionRunner:
    """Runs a mission stop-and-go and writes the frames of a survey folder.

    Parameters
    ----------
    mission : dict
        ``mission.json`` content (validated against ``mission.schema.json``).
    ptu : PointingUnit
        The pan/tilt unit.
    camera : callable
        ``camera() -> (H, W) or (B, H, W) uint16``: triggers one exposure.
    survey_dir : path
        Survey folder (created if missing); ``mission.json`` is written there.
    manifest : dict, optional
        ``survey.json`` content (site and camera are not known to the runner); validated and
        written when given, and its ``files`` names and camera resolution/bands are used.
    settle_s : float
        Wait after each move before the exposure, seconds.
    clock, sleep : callable
        UTC clock (epoch seconds) and sleep function; inject a fake clock for tests.
    progress : Progress
        Reports one step per position.
    stop : threading.Event, optional
        Checked before every position; set it to end the run after the current frame.

    Raises
    ------
    InvalidInput
        ``mission.json: <field>: <message>`` for an invalid mission (or ``survey.json`` for an
        invalid manifest).
    """

    def __init__(self, mission: dict, ptu: PointingUnit, camera: Callable[[], np.ndarray],
                 survey_dir: str | os.PathLike, manifest: dict | None = None,
                 settle_s: float = 0.5, clock: Callable[[], float] = time.time,
                 sleep: Callable[[float], None] = time.sleep,
                 progress: Progress = NULL_PROGRESS,
                 stop: threading.Event | None = None) -> None:
        for doc, schema, label in ((mission, "mission", "mission.json"),
                                   (manifest, "survey", "survey.json")):
            if doc is None:
                continue
            problems = manifest_problems(doc, schema)
            if problems:
                raise InvalidInput(problems[0][1], label, problems[0][0])
        if not settle_s >= 0:
            raise ValueError(f"settle_s must be >= 0, got {settle_s}")
        self.mission = mission
        self.manifest = manifest
        self.ptu = ptu
        self.camera = camera
        self.root = Path(survey_dir)
        self.settle_s = float(settle_s)
        self.clock = clock
        self.sleep = sleep
        self.progress = progress
        self.stop = stop if stop is not None else threading.Event()
        files = (manifest or {}).get("files", {})
        self.frames_rel = files.get("frames", "frames.csv")
        self.mission_rel = files.get("mission", "mission.json")
        self._expected: tuple[int, ...] | None = None
        self._expected_from = ""
        if manifest is not None:
            self._expected_from = "survey.json camera"
            w, h = manifest["camera"]["resolution"]
            self._expected = (len(manifest["camera"]["bands"]), int(h), int(w))

    def _existing_rows(self) -> dict[str, list]:
        rows: dict[str, list] = {c: [] for c in FRAME_COLUMNS}
        path = self.root / self.frames_rel
        if path.exists():
            table = read_frames_table(path, self.frames_rel)
            for c in FRAME_COLUMNS:
                rows[c] = list(getattr(table, c))
        return rows

    def _wait_until(self, t_s: float) -> None:
        while not self.stop.is_set():
            left = t_s - self.clock()
            if left <= 0:
                return
            self.sleep(min(left, 1.0))

    def run(self, scans: Iterable[int] | None = None, start_s: float | None = None
            ) -> MissionResult:
        """Run the mission's scans (default all) and write their frames.

        Parameters
        ----------
        scans : iterable of int, optional
            Scan numbers to take (e.g. ``range(5, n_scans)`` to continue a run); rows of other
            scans already in ``frames.csv`` are kept.
        start_s : float, optional
            UTC epoch seconds of scan 0's planned start (default: now).
        """
        n_scans = int(self.mission["n_scans"])
        interval = float(self.mission["scan_interval_s"])
        todo = list(range(n_scans)) if scans is None else [int(s) for s in scans]
        bad = [s for s in todo if not 0 <= s < n_scans]
        if bad:
            raise InvalidInput(f"scan {bad[0]} is not in the mission (0 to {n_scans - 1})",
                               "mission.json", "n_scans")
        self.root.mkdir(parents=True, exist_ok=True)
        write_mission(self.root / self.mission_rel, self.mission)
        if self.manifest is not None:
            write_survey_json(self.root / "survey.json", self.manifest)
        rows = self._existing_rows()
        start = self.clock() if start_s is None else float(start_s)
        positions = self.mission["positions"]
        result = MissionResult()
        self.progress.start("mission", len(todo) * len(positions))
        try:
            for scan in todo:
                if self.stop.is_set():
                    result.stopped = True
                    break
                planned = start + scan * interval
                if self.clock() > planned + 1.0:
                    result.late_scans.append(scan)
                    self.progress.message(f"scan {scan} starts "
                                          f"{self.clock() - planned:.0f} s late")
                self._wait_until(planned)
                taken = self._scan(scan, positions, rows, result)
                if taken:
                    result.scans.append(scan)
                if taken < len(positions):
                    result.stopped = True
                    break
        finally:
            self.progress.close()
        return result

    def _scan(self, scan: int, positions: list[dict], rows: dict[str, list],
              result: MissionResult) -> int:
        """Take one scan; the frames taken are written even when a device fails midway."""
        stack: np.ndarray | None = None
        new: dict[str, list] = {c: [] for c in FRAME_COLUMNS}
        page = 0
        try:
            for pos in positions:
                if self.stop.is_set():
                    break
                pan_deg, tilt_deg = self.ptu.move_to(float(pos["pan_deg"]),
                                                     float(pos["tilt_deg"]))
                if self.settle_s > 0:
                    self.sleep(self.settle_s)
                t_s = self.clock()
                frame = _as_bands(self.camera(), self._expected, self._expected_from)
                self._expected, self._expected_from = frame.shape, "the first frame"
                if stack is None:
                    stack = np.empty((frame.shape[0], len(positions), *frame.shape[1:]),
                                     np.uint16)
                stack[:, page] = frame
                for band in range(frame.shape[0]):
                    for c, v in zip(FRAME_COLUMNS, (scan, int(pos["index"]), band, t_s,
                                                    pan_deg, tilt_deg,
                                                    scan_tiff_name(scan, band), page),
                                    strict=True):
                        new[c].append(v)
                page += 1
                result.n_frames += 1
                self.progress.advance(1, scan=scan, position=int(pos["index"]))
        finally:
            if page and stack is not None:
                self._write_scan(scan, stack[:, :page], new, rows)
        return page

    def _write_scan(self, scan: int, stack: np.ndarray, new: dict[str, list],
                    rows: dict[str, list]) -> None:
        """TIFFs of one scan (B, P, H, W) and ``frames.csv`` with its rows replaced."""
        for band in range(stack.shape[0]):
            write_tiff_stack(self.root / scan_tiff_name(scan, band), stack[band])
        keep = [i for i, s in enumerate(rows["scan"]) if int(s) != scan]
        for c in FRAME_COLUMNS:
            rows[c] = [rows[c][i] for i in keep] + new[c]
        write_frames_table(self.root / self.frames_rel, {
            c: np.asarray(rows[c], dtype=object if c == "file" else None)
            for c in FRAME_COLUMNS})
