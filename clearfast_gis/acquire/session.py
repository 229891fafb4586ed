"""One acquisition: instruments, survey clock, mission and survey folder together.

:func:`run_acquisition` is ``clearfast acquire``:

1. read the mission and the station set-up; check the survey folder (a new one, or an
   acquisition of the same mission to resume); open every port and the camera; set up the
   pan/tilt unit (resolution and limits from the unit) and check every mission and blackbody
   position against its limits. Nothing is written before all of this has succeeded;
2. start the loggers (GNSS receiver, polled weather station, thermocouple logger with the
   blackbody sensors), each in its own thread, reconnecting a lost port;
3. take the survey clock from the receiver's UTC (:class:`~.clock.GnssClock`);
4. wait (at most ``warmup_s``) until every instrument has reported once, so that the logs
   begin before the first frame;
5. write ``acquisition/session.json`` (planned start, mission checksum, one entry per run),
   ``markers.csv``, ``mission.json`` and ``survey.json``;
6. run the mission stop-and-go with the calibration event each scan (:class:`~.mission.
   MissionRunner`, resuming what an earlier run left);
7. keep logging until every log reaches past the last frame (at most ``tail_s``), so that the
   logs cover the frames, then stop everything cleanly.

Everything that happens goes to ``acquisition/events.csv``. A stop request (Ctrl-C, SIGTERM)
ends the run after the exposure in flight; running the same command again resumes it.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import shutil
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

from clearfast_gis.acquire.camera import CameraSpec, open_camera
from clearfast_gis.acquire.clock import GnssClock, HostClock
from clearfast_gis.acquire.events import EventLog
from clearfast_gis.acquire.gnss import GnssLogger
from clearfast_gis.acquire.mission import MissionResult, MissionRunner
from clearfast_gis.acquire.ports import PortSpec, open_port
from clearfast_gis.acquire.ptu import PanTiltUnit, PtuLimitError
from clearfast_gis.acquire.soil import ThermocoupleLogger
from clearfast_gis.acquire.station import StationSetup, read_setup
from clearfast_gis.acquire.weather import WeatherStationLogger
from clearfast_gis.atomic import write_text
from clearfast_gis.errors import ClearfastError, InvalidInput
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.survey._text import read_text
from clearfast_gis.survey.manifest import DEFAULT_FILES, parse_json, read_mission
from clearfast_gis.survey.station_profiles import read_station_profile
from clearfast_gis.survey.stations import PROFILE_KEY, PROFILE_NAME
from clearfast_gis.timeutil import format_utc, parse_utc

SESSION_REL = "acquisition/session.json"
EVENTS_REL = "acquisition/events.csv"


@dataclass
class AcquisitionConfig:
    """What ``clearfast acquire`` was asked to do.

    Attributes
    ----------
    survey_dir : Path
        The survey folder (new, or an acquisition to resume).
    mission_path, setup_path : Path
        ``mission.json`` (from ``clearfast plan``) and ``setup.json``.
    ports : dict
        Instrument (``gnss``, ``ptu``, ``weather``, ``soil``) -> :class:`PortSpec`; the
        pan/tilt unit is required.
    camera : CameraSpec
        The camera.
    time_scale : float
        Survey seconds per wall second (1 with real instruments; a device simulator's factor).
    start_s : float, optional
        Planned start of scan 0, UTC epoch seconds (default: now; a resumed acquisition keeps
        its own).
    scans : list of int, optional
        The scans to take (default: all of the mission's).
    gnss_wait_s : float
        Wall seconds to wait for the receiver's first time sentence.
    warmup_s, tail_s : float
        Survey seconds to wait for every instrument's first record before the mission and for
        records past the last frame after it.
    weather_poll_s : float
        Survey seconds between weather station polls.
    reconnect_s : float
        Wall seconds the pan/tilt unit may stay unreachable before the run fails.
    station_profile : Path, optional
        Station profile of the weather station and the thermocouple logger: the weather
        logger maps the station's columns with it; it is copied into the survey folder as
        ``station_profile.json`` and named in ``survey.json`` (``files.station_profile``), so
        that ``validate`` and ``process`` read the logs with it.
    """

    survey_dir: Path
    mission_path: Path
    setup_path: Path
    ports: dict
    camera: CameraSpec
    time_scale: float = 1.0
    start_s: float | None = None
    scans: list[int] | None = None
    gnss_wait_s: float = 30.0
    warmup_s: float = 900.0
    tail_s: float = 900.0
    weather_poll_s: float = 60.0
    reconnect_s: float = 60.0
    station_profile: Path | None = None


@dataclass
class AcquisitionSummary:
    """What a run did: the mission result, the instruments' counts and the events."""

    result: MissionResult
    resumed: bool
    instruments: dict = field(default_factory=dict)
    events: dict = field(default_factory=dict)
    stopped: bool = False


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _check_folder(root: Path, mission_sha: str) -> dict | None:
    """The earlier session of a folder to resume (None for a new folder).

    Raises
    ------
    InvalidInput
        For a folder holding something else, or another mission's acquisition.
    """
    session_path = root / SESSION_REL
    if session_path.exists():
        doc = parse_json(read_text(session_path, SESSION_REL), SESSION_REL)
        if not isinstance(doc, dict) or doc.get("format") != "clearfast-acquisition":
            raise InvalidInput("not an acquisition session file", session_path)
        if doc.get("mission_sha256") != mission_sha:
            raise InvalidInput("holds the acquisition of another mission; give the same "
                               "mission.json to resume, or another folder", root)
        return doc
    if root.exists() and (not root.is_dir() or any(root.iterdir())):
        raise InvalidInput("exists and is not an acquisition folder (choose a new folder)",
                           root)
    return None


class _Instruments:
    """The loggers of one run, their threads, and their ports."""

    def __init__(self) -> None:
        self.loggers: list = []
        self.ports: list = []
        self.stop = threading.Event()
        self.threads: list[threading.Thread] = []

    def start(self) -> None:
        self.threads = [lg.start(self.stop) for lg in self.loggers]

    def close(self) -> None:
        self.stop.set()
        for t in self.threads:
            t.join(timeout=10.0)
        for lg in self.loggers:  # idempotent; needed when a logger never ran
            with contextlib.suppress(ClearfastError):
                lg.close_logs()
        for p in self.ports:
            with contextlib.suppress(Exception):
                p.close()
        for lg in self.loggers:
            with contextlib.suppress(Exception):
                lg.port.close()

    def last_record_s(self) -> dict[str, float | None]:
        """UTC of each instrument's latest record (None before its first)."""
        out: dict[str, float | None] = {}
        for lg in self.loggers:
            if isinstance(lg, GnssLogger):
                out["gnss"] = lg.time_s
            elif isinstance(lg, WeatherStationLogger):
                out["weather"] = None if lg.last is None else lg.last["time_s"]
            elif isinstance(lg, ThermocoupleLogger):
                out["soil"] = None if lg.last is None else lg.last[0]
                if lg.blackbody_log is not None:
                    out["blackbody"] = (None if lg.last_blackbody is None
                                        else lg.last_blackbody[0])
        return out


def _preflight(ptu: PanTiltUnit, mission: dict, setup: StationSetup, label: str) -> None:
    """Check every mission and blackbody position against the unit's limits."""
    targets = [(f"positions.{k}", f"position {p['index']}", p["pan_deg"], p["tilt_deg"])
               for k, p in enumerate(mission["positions"])]
    for bb in (1, 2):
        pan, tilt = setup.blackbodies.position(bb)
        targets.append((f"blackbodies.{'heated' if bb == 1 else 'ambient'}",
                        f"blackbody {bb}", pan, tilt))
    for fld, what, pan, tilt in targets:
        try:
            ptu.check_position(float(pan), float(tilt))
        except PtuLimitError as exc:
            where = label if fld.startswith("positions") else setup.label
            raise InvalidInput(f"{what}: {exc.message.removeprefix('pan/tilt unit: ')} "
                               f"({ptu.name})", where, fld) from None


def run_acquisition(cfg: AcquisitionConfig, progress: Progress = NULL_PROGRESS,
                    stop: threading.Event | None = None) -> AcquisitionSummary:
    """Run (or resume) an acquisition; see the module docstring.

    Raises
    ------
    InvalidInput
        For a bad mission, set-up or folder, or a position outside the unit's limits.
    PortError, CameraError
        For a port or camera that cannot be opened (before anything is written).
    ClearfastError
        When an instrument fails during the run (what was taken is kept).
    """
    stop = stop if stop is not None else threading.Event()
    root = Path(cfg.survey_dir)
    mission_label = str(cfg.mission_path)
    mission = read_mission(cfg.mission_path, mission_label)
    setup = read_setup(cfg.setup_path)
    previous = _check_folder(root, _sha256(cfg.mission_path))
    n_scans = int(mission["n_scans"])
    if cfg.scans is not None and any(not 0 <= k < n_scans for k in cfg.scans):
        raise InvalidInput(f"--scans asks for scan {max(cfg.scans)}; the mission has scans 0 to "
                           f"{n_scans - 1}", mission_label, "n_scans")
    if "ptu" not in cfg.ports:
        raise InvalidInput("no pan/tilt unit port (--ptu)", field="ptu", exit_code=2)
    if cfg.time_scale != 1.0 and "gnss" not in cfg.ports:
        raise InvalidInput("a time scale other than 1 needs the GNSS receiver's clock (--gnss)",
                           field="time_scale", exit_code=2)

    # -- open and check everything before writing anything -------------------------------
    inst = _Instruments()
    opened: dict = {}
    camera = None
    deferred: list[tuple[str, str, str]] = []  # events before the log exists
    try:
        for kind, spec in cfg.ports.items():
            opened[kind] = open_port(spec)
            inst.ports.append(opened[kind])
        clock = GnssClock(cfg.time_scale) if "gnss" in cfg.ports else HostClock()
        camera = open_camera(cfg.camera, clock=lambda: _safe_now(clock))
        ptu = PanTiltUnit(opened["ptu"], reopen=_reopener(cfg.ports["ptu"]),
                          reconnect_s=cfg.reconnect_s, retry_s=_retry_s(cfg),
                          on_event=lambda *e: deferred.append(e))
        ptu.initialize()
        _preflight(ptu, mission, setup, mission_label)
    except BaseException:
        inst.close()
        if camera is not None:
            camera.close()
        raise

    root.mkdir(parents=True, exist_ok=True)
    events = EventLog(root / EVENTS_REL, clock.now,
                      echo=lambda s, e, d: progress.message(f"{s}: {e} {d}".rstrip()))
    ptu.on_event = events
    for e in deferred:
        events(*e)
    try:
        return _run(cfg, mission, mission_label, setup, previous, inst, opened, clock, camera,
                    ptu, events, progress, stop)
    finally:
        inst.close()
        with contextlib.suppress(Exception):
            ptu.port.close()  # reopened after a reconnection: not among inst.ports
        with contextlib.suppress(Exception):
            camera.close()
        events.close()


def _safe_now(clock) -> float:
    try:
        return clock.now()
    except ClearfastError:
        return time.time()


def _reopener(spec: PortSpec):
    return lambda: open_port(spec)


def _retry_s(cfg: AcquisitionConfig) -> float:
    """Wall seconds between attempts to reopen a lost port: 1 s in real time, less when the
    survey clock runs faster (a device simulator), so that little survey time is lost."""
    return min(1.0, max(0.005, 2.0 / cfg.time_scale))


def _run(cfg: AcquisitionConfig, mission: dict, mission_label: str, setup: StationSetup,
         previous: dict | None, inst: _Instruments, opened: dict, clock, camera,
         ptu: PanTiltUnit, events: EventLog, progress: Progress, stop: threading.Event
         ) -> AcquisitionSummary:
    root = Path(cfg.survey_dir)
    files = dict(DEFAULT_FILES)
    profile = None
    if cfg.station_profile is not None:
        profile = read_station_profile(cfg.station_profile)
        write_text(root / PROFILE_NAME, Path(cfg.station_profile).read_text(encoding="utf-8"))
    elif (root / PROFILE_NAME).exists():  # a resumed acquisition keeps its profile
        profile = read_station_profile(root / PROFILE_NAME, PROFILE_NAME)
    if "gnss" in opened:
        inst.loggers.append(GnssLogger(opened["gnss"], root / files["gnss"],
                                       on_time=clock.observe, reopen=_reopener(cfg.ports["gnss"]),
                                       retry_s=_retry_s(cfg), on_event=events))
    if "weather" in opened:
        inst.loggers.append(WeatherStationLogger(
            opened["weather"], root / files["weather"], clock=clock.now,
            poll_interval_s=cfg.weather_poll_s, reopen=_reopener(cfg.ports["weather"]),
            retry_s=_retry_s(cfg), on_event=events, profile=profile))
    if "soil" in opened:
        inst.loggers.append(ThermocoupleLogger(
            opened["soil"], root / files["soil"], setup.soil_depths_m,
            blackbody_path=root / files["blackbody_log"], reopen=_reopener(cfg.ports["soil"]),
            retry_s=_retry_s(cfg), on_event=events))
    for kind in ("gnss", "weather", "soil"):
        if kind not in opened:
            progress.message(f"no {kind} port: the survey will lack {files[kind]}")
    events("acquire", "start", f"{'resumed' if previous else 'new'} acquisition of "
           f"{mission_label} into {root}")
    inst.start()

    if isinstance(clock, GnssClock) and not clock.wait_ready(cfg.gnss_wait_s):
        raise ClearfastError(f"no UTC time (RMC or ZDA sentence) from the GNSS receiver within "
                             f"{cfg.gnss_wait_s:g} s", cfg.ports["gnss"].port)
    lim = ptu.limits_deg()
    events("ptu", "opened", f"resolution {ptu.pan_resolution_deg * 3600:g}/"
           f"{ptu.tilt_resolution_deg * 3600:g} arcsec per step" + (
               "" if lim is None else f", pan {lim[0]:.2f} to {lim[1]:.2f} deg, "
               f"tilt {lim[2]:.2f} to {lim[3]:.2f} deg"))

    _warm_up(cfg, inst, clock, stop, progress)
    now = clock.now()
    interval = float(mission["scan_interval_s"])
    if previous is not None:
        start_s = parse_utc(previous["start_utc"])
        if cfg.start_s is not None and abs(cfg.start_s - start_s) > 0.5:
            raise InvalidInput(f"resuming an acquisition planned to start at "
                               f"{previous['start_utc']}; --start differs", root, "start")
        session = previous
    else:
        start_s = now if cfg.start_s is None else float(cfg.start_s)
        session = {"format": "clearfast-acquisition", "format_version": 1,
                   "mission_sha256": _sha256(cfg.mission_path),
                   "start_utc": format_utc(start_s), "runs": []}
    run_info = {"started_utc": format_utc(now), "time_scale": cfg.time_scale,
                "ports": {k: str(v) for k, v in cfg.ports.items()}, "camera": str(cfg.camera)}
    session["runs"].append(run_info)
    write_text(root / SESSION_REL, json.dumps(session, indent=1) + "\n")
    if setup.markers is not None:
        shutil.copyfile(setup.markers, root / files["markers"])
    survey_id = setup.document.get("survey_id") or root.name
    manifest = setup.manifest(survey_id, min(start_s, now),
                              start_s + int(mission["n_scans"]) * interval)
    if profile is not None:
        manifest["files"][PROFILE_KEY] = PROFILE_NAME

    runner = MissionRunner(mission, ptu, camera, root, manifest=manifest,
                           settle_s=setup.settle_s, clock=clock.now, sleep=clock.sleep,
                           progress=progress, stop=stop, blackbodies=setup.blackbodies,
                           on_event=events, max_sleep_s=max(1.0, 0.25 * clock.time_scale))
    result = runner.run(scans=cfg.scans, start_s=start_s, resume=True)
    if not stop.is_set() and result.last_time_s is not None:
        _tail(cfg, inst, clock, stop, result.last_time_s, progress)
    events("acquire", "end", f"{result.n_frames} position and {result.n_calibration_frames} "
           f"blackbody exposures, scans {result.scans}, missed {result.missed_scans}"
           + (" (stopped)" if stop.is_set() else ""))
    run_info["ended_utc"] = format_utc(_safe_now(clock))
    run_info["exposures"] = result.n_frames
    run_info["calibration_exposures"] = result.n_calibration_frames
    run_info["stopped"] = stop.is_set()
    write_text(root / SESSION_REL, json.dumps(session, indent=1) + "\n")
    instruments = {lg.kind: lg.status() for lg in inst.loggers}
    instruments["ptu"] = {"port": ptu.name, "reconnects": ptu.n_reconnects}
    return AcquisitionSummary(result, previous is not None, instruments, dict(events.counts),
                              stop.is_set())


def _wait_for_logs(inst: _Instruments, clock, stop: threading.Event, limit_s: float,
                   ready, what: str, progress: Progress) -> None:
    """Wait (survey seconds) until ``ready(last_record_times)`` or ``limit_s`` passes."""
    deadline = clock.now() + limit_s
    while not stop.is_set() and not ready(inst.last_record_s()):
        if clock.now() > deadline:
            late = [k for k, v in inst.last_record_s().items() if not ready({k: v})]
            progress.message(f"{what}: still nothing from {', '.join(late)} after "
                             f"{limit_s:g} s; going on")
            return
        clock.wait(stop, min(5.0, limit_s / 20.0))


def _warm_up(cfg: AcquisitionConfig, inst: _Instruments, clock, stop: threading.Event,
             progress: Progress) -> None:
    """Every instrument's first record before the first frame (the logs cover the frames)."""
    _wait_for_logs(inst, clock, stop, cfg.warmup_s,
                   lambda last: all(v is not None for v in last.values()),
                   "waiting for the instruments", progress)


def _tail(cfg: AcquisitionConfig, inst: _Instruments, clock, stop: threading.Event,
          last_frame_s: float, progress: Progress) -> None:
    """Every instrument's records past the last frame."""
    _wait_for_logs(inst, clock, stop, cfg.tail_s,
                   lambda last: all(v is not None and v >= last_frame_s
                                    for v in last.values()),
                   "logging past the last frame", progress)
