"""Stop-and-go execution of a scanning mission (``mission.json``, paper §2.2 and §3.3).

Each scan (started every ``scan_interval_s`` from the mission start) begins with the
calibration event of the two blackbodies when they are configured (paper §3.3: point at the
heated blackbody, take ``frames`` exposures, point at the ambient one, take as many), then
visits the mission's positions in order: move the pan/tilt unit and wait for completion, wait
``settle_s`` for the boom to stop swaying, take the time and trigger the camera, record the
unit's read-back angles. Every exposure is staged at once (:mod:`.framestore`), so a crash
loses at most the exposure in flight; calibration events and scans are consolidated into the
survey format when they end: ``frames/scan_000_b0.tif`` (page = position order),
``blackbody/event_000_b0.tif``, ``frames.csv`` and ``blackbody/frames.csv`` (rows of other
scans kept).

``run(resume=True)`` continues an interrupted mission: exposures already kept are not taken
again (but an interrupted calibration event is taken again whole: both blackbodies belong to
one moment), a scan whose window has passed (the next scan's planned start) is recorded as
missed rather than taken out of its time, and a scan interrupted within its window is
completed.

The camera is a :class:`~clearfast_gis.acquire.camera.Camera` (``capture() -> Exposure``) or a
plain callable returning one frame, (H, W) uint16 for a one-band camera or (B, H, W) for B
bands. The pan/tilt unit is anything with ``move_to(pan_deg, tilt_deg) -> (pan_deg,
tilt_deg)`` that returns after the move is complete
(:class:`~clearfast_gis.acquire.ptu.PanTiltUnit`).
"""

from __future__ import annotations

import os
import threading
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Protocol

from clearfast_gis.acquire.camera import (
    Camera,
    CameraError,
    CameraTimeout,
    Exposure,
    as_exposure,
)
from clearfast_gis.acquire.framestore import (
    BLACKBODY,
    POSITION,
    Capture,
    FrameStore,
    event_tiff_name,
    scan_tiff_name,
)
from clearfast_gis.errors import InvalidInput
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.survey.manifest import manifest_problems, write_mission, write_survey_json

#: a scan starting later than this fraction of the scan interval is reported as late
LATE_FRACTION = 0.02

__all__ = ["Blackbodies", "MissionResult", "MissionRunner", "PointingUnit", "event_tiff_name",
           "scan_tiff_name"]


class PointingUnit(Protocol):
    """What the runner needs of a pan/tilt unit."""

    def move_to(self, pan_deg: float, tilt_deg: float) -> tuple[float, float]:
        """Move, wait for completion, return the read-back (pan_deg, tilt_deg)."""
        ...


@dataclass(frozen=True)
class Blackbodies:
    """Where the calibration blackbodies are and how many exposures each gets per event.

    Attributes
    ----------
    heated, ambient : (float, float)
        (pan_deg, tilt_deg) at which the blackbody fills the field of view: 1 = heated
        (about 10 K above ambient), 2 = ambient.
    frames : int
        Exposures per blackbody and event (the paper: 10 or more).
    """

    heated: tuple[float, float]
    ambient: tuple[float, float]
    frames: int = 10

    def position(self, blackbody: int) -> tuple[float, float]:
        """(pan_deg, tilt_deg) of blackbody 1 or 2."""
        return self.heated if blackbody == 1 else self.ambient


@dataclass
class MissionResult:
    """What a run did.

    Attributes
    ----------
    scans : list of int
        Scans written (complete or, when stopped, partial).
    n_frames : int
        Scan exposures taken (positions; each gives one frame per band).
    n_calibration_frames : int
        Blackbody exposures taken (each gives one frame per band).
    late_scans : list of int
        Scans that started after their planned time by more than 2 % of the scan interval
        (at least 1 s): the previous scan overran, or the run was resumed late.
    missed_scans : list of int
        Scans skipped because their window had passed (``resume``).
    n_retries : int
        Exposures repeated after a camera timeout.
    stopped : bool
        True when a stop request ended the run early.
    last_time_s : float or None
        UTC epoch seconds of the last exposure.
    n_bands : int
        Bands per exposure (0 before the first): ``n_frames * n_bands`` rows of
        ``frames.csv``.
    """

    scans: list[int] = field(default_factory=list)
    n_frames: int = 0
    n_calibration_frames: int = 0
    late_scans: list[int] = field(default_factory=list)
    missed_scans: list[int] = field(default_factory=list)
    n_retries: int = 0
    stopped: bool = False
    last_time_s: float | None = None
    n_bands: int = 0


class MissionRunner:
    """Runs a mission stop-and-go and writes the frames of a survey folder.

    Parameters
    ----------
    mission : dict
        ``mission.json`` content (validated against ``mission.schema.json``).
    ptu : PointingUnit
        The pan/tilt unit.
    camera : Camera or callable
        The camera (``capture() -> Exposure``), or ``camera() -> (H, W) or (B, H, W)
        uint16``.
    survey_dir : path
        Survey folder (created if missing); ``mission.json`` is written there.
    manifest : dict, optional
        ``survey.json`` content; validated and written when given, and its ``files`` names and
        camera resolution/bands are used.
    settle_s : float
        Wait after each move before the exposure, seconds.
    clock, sleep : callable
        UTC clock (epoch seconds) and sleep function in the same seconds; the survey clock in
        the field (:mod:`.clock`), a fake clock in tests.
    progress : Progress
        Reports one step per exposure.
    stop : threading.Event, optional
        Checked before every exposure; set it to end the run after the current one.
    blackbodies : Blackbodies, optional
        The calibration event at the start of each scan; none without it.
    on_event : callable, optional
        ``on_event("mission", event, detail)`` for late and missed scans, moves and retries.
    capture_retries : int
        Exposures repeated after a camera timeout before the run fails.
    max_sleep_s : float
        Longest single ``sleep`` while waiting for a scan (so that a stop is noticed).

    Raises
    ------
    InvalidInput
        ``mission.json: <field>: <message>`` for an invalid mission (or ``survey.json`` for an
        invalid manifest).
    """

    def __init__(self, mission: dict, ptu: PointingUnit, camera: Camera | Callable,
                 survey_dir: str | os.PathLike, manifest: dict | None = None,
                 settle_s: float = 0.5, clock: Callable[[], float] = time.time,
                 sleep: Callable[[float], None] = time.sleep,
                 progress: Progress = NULL_PROGRESS,
                 stop: threading.Event | None = None,
                 blackbodies: Blackbodies | None = None,
                 on_event: Callable[[str, str, str], None] | None = None,
                 capture_retries: int = 1, max_sleep_s: float = 1.0) -> None:
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
        self.capture = camera.capture if hasattr(camera, "capture") else camera
        self.root = Path(survey_dir)
        self.settle_s = float(settle_s)
        self.clock = clock
        self.sleep = sleep
        self.progress = progress
        self.stop = stop if stop is not None else threading.Event()
        self.blackbodies = blackbodies
        self.on_event = on_event
        self.capture_retries = int(capture_retries)
        self.max_sleep_s = float(max_sleep_s)
        files = (manifest or {}).get("files", {})
        self.mission_rel = files.get("mission", "mission.json")
        self.positions = list(mission["positions"])
        rank = {int(p["index"]): k for k, p in enumerate(self.positions)}
        self.store = FrameStore(self.root, files.get("frames", "frames.csv"),
                                files.get("blackbody_frames", "blackbody/frames.csv"),
                                position_order=lambda i: rank.get(int(i), len(rank) + int(i)))
        self._expected: tuple[int, ...] | None = None
        self._expected_from = ""
        self._first_frame = True
        self._radiometry = None
        if manifest is not None and "radiometry" in manifest["camera"]:
            from clearfast_gis.radiometry.camera import CameraRadiometry

            self._radiometry = CameraRadiometry.from_manifest(manifest["camera"]["radiometry"])
        if manifest is not None:
            self._expected_from = "survey.json camera"
            w, h = manifest["camera"]["resolution"]
            self._expected = (len(manifest["camera"]["bands"]), int(h), int(w))

    def _event(self, event: str, detail: str) -> None:
        if self.on_event is not None:
            self.on_event("mission", event, detail)

    def _wait_until(self, t_s: float) -> None:
        while not self.stop.is_set():
            left = t_s - self.clock()
            if left <= 0:
                return
            self.sleep(min(left, self.max_sleep_s))

    def scan_keys(self, scan: int) -> list[tuple[str, int, int]]:
        """The exposures of a scan in the order they are taken: blackbody 1 and 2 (when
        configured), then the mission's positions."""
        keys: list[tuple[str, int, int]] = []
        if self.blackbodies is not None:
            keys = [(BLACKBODY, bb, r) for bb in (1, 2) for r in range(self.blackbodies.frames)]
        return keys + [(POSITION, int(p["index"]), 0) for p in self.positions]

    def _todo(self, scan: int, resume: bool) -> list[tuple[str, int, int]]:
        """The exposures of a scan still to take. A calibration event is taken whole: an
        interrupted one is taken again (both blackbodies belong to one moment)."""
        keys = self.scan_keys(scan)
        if not resume:
            return keys
        taken = self.store.taken(scan)
        redo_event = any(k[0] == BLACKBODY and k not in taken for k in keys)
        return [k for k in keys if k not in taken or (redo_event and k[0] == BLACKBODY)]

    def run(self, scans: Iterable[int] | None = None, start_s: float | None = None,
            resume: bool = False) -> MissionResult:
        """Run the mission's scans (default all) and write their frames.

        Parameters
        ----------
        scans : iterable of int, optional
            Scan numbers to take (e.g. ``range(5, n_scans)``); rows of other scans already in
            ``frames.csv`` are kept.
        start_s : float, optional
            UTC epoch seconds of scan 0's planned start (default: now).
        resume : bool
            Take only the exposures not yet kept, and skip scans whose window (until the next
            scan's planned start) has passed.
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
        self.store.recover()  # what a run that crashed left
        start = self.clock() if start_s is None else float(start_s)
        plan = {s: self._todo(s, resume) for s in todo}
        result = MissionResult()
        self.progress.start("acquire", sum(len(v) for v in plan.values()))
        try:
            for scan in todo:
                if self.stop.is_set():
                    result.stopped = True
                    break
                keys = plan[scan]
                if not keys:
                    continue
                planned = start + scan * interval
                now = self.clock()
                if resume and now > planned + interval:
                    result.missed_scans.append(scan)
                    self._event("missed", f"scan {scan}: its window ended "
                                f"{now - planned - interval:.0f} s ago")
                    self.progress.advance(len(keys), scan=scan, missed=True)
                    continue
                if now > planned + max(1.0, LATE_FRACTION * interval):
                    result.late_scans.append(scan)
                    self.progress.message(f"scan {scan} starts {now - planned:.0f} s late")
                    self._event("late", f"scan {scan} starts {now - planned:.0f} s late")
                self._wait_until(planned)
                taken = self._scan(scan, keys, result)
                if taken:
                    result.scans.append(scan)
                if taken < len(keys):
                    result.stopped = True
                    break
        finally:
            self.progress.close()
        return result

    def _note_radiometry(self, exposure: Exposure) -> None:
        """A radiometric camera's own calibration goes into ``survey.json``
        (``camera.radiometry``) with the first frame; every later frame must carry the same
        (one survey, one camera setting), and counts never mix with radiometric frames."""
        rad = exposure.radiometry
        if self._first_frame:
            self._first_frame = False
            if self._radiometry is None and rad is not None:
                self._radiometry = rad
                if self.manifest is not None:
                    self.manifest["camera"]["radiometry"] = rad.to_manifest()
                    self.manifest["camera"]["bit_depth"] = 16
                    if self.blackbodies is None:  # a radiometric camera needs none
                        for key in ("blackbody_frames", "blackbody_log"):
                            self.manifest["files"].pop(key, None)
                    write_survey_json(self.root / "survey.json", self.manifest)
                self._event("radiometry", f"camera radiometry {rad.kind} from the first frame")
                return
        if rad != self._radiometry:
            raise CameraError("the camera's radiometry differs from the survey's (Planck "
                              "constants, scale, or counts mixed with radiometric frames)",
                              "camera")

    def _expose(self, result: MissionResult) -> tuple[Exposure, float]:
        """Trigger the camera (again after a timeout, up to ``capture_retries`` times); the
        exposure and the trigger time."""
        attempt = 0
        while True:
            t_s = self.clock()
            try:
                return as_exposure(self.capture(), "camera"), t_s
            except CameraTimeout as exc:
                attempt += 1
                if attempt > self.capture_retries:
                    raise
                result.n_retries += 1
                self._event("retry", exc.one_line())

    def _scan(self, scan: int, keys: list[tuple[str, int, int]], result: MissionResult) -> int:
        """Take one scan's exposures; what was taken is consolidated even when a device fails
        midway."""
        pointing: dict[int, tuple[float, float]] = {
            int(p["index"]): (float(p["pan_deg"]), float(p["tilt_deg"])) for p in self.positions}
        taken = 0
        current: tuple[float, float] | None = None
        readback = (float("nan"), float("nan"))
        try:
            for n, (kind, index, repeat) in enumerate(keys):
                if self.stop.is_set():
                    break
                target = pointing[index] if kind == POSITION else \
                    self.blackbodies.position(index)
                if target != current:
                    readback = self.ptu.move_to(*target)
                    current = target
                    self._event("move", f"scan {scan} {kind} {index}: pan {target[0]:.3f} tilt "
                                f"{target[1]:.3f} -> {readback[0]:.3f} {readback[1]:.3f}")
                    if self.settle_s > 0:
                        self.sleep(self.settle_s)
                exposure, t_s = self._expose(result)
                counts = exposure.counts
                if self._expected is not None and counts.shape != self._expected:
                    raise CameraError(f"camera returned a frame of shape {counts.shape}, "
                                      f"expected {self._expected} (bands, H, W) from "
                                      f"{self._expected_from}", "camera")
                self._expected, self._expected_from = counts.shape, "the first frame"
                self._note_radiometry(exposure)
                times = exposure.time_s or (t_s,) * counts.shape[0]
                self.store.stage(Capture(scan, kind, index, repeat, float(readback[0]),
                                         float(readback[1]), times, counts))
                result.last_time_s = max(times)
                result.n_bands = counts.shape[0]
                taken += 1
                if kind == POSITION:
                    result.n_frames += 1
                else:
                    result.n_calibration_frames += 1
                    if n + 1 < len(keys) and keys[n + 1][0] == POSITION:
                        self.store.consolidate(scan)  # the calibration event is complete
                self.progress.advance(1, scan=scan, kind=kind, index=index)
        finally:
            if taken:
                self.store.consolidate(scan)
        return taken

