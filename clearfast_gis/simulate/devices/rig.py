"""All device simulators of one twin on pseudo-terminals, a ports file, scheduled faults.

:class:`DeviceRig` is ``clearfast simulate-devices``. In its folder (the ports file's) it
writes:

- ``devices/gnss``, ``devices/ptu``, ``devices/weather``, ``devices/soil``: links to the
  pseudo-terminals (as ``/dev/serial/by-id`` links: stable across unplug and replug);
- ``camera/``: the twin camera's drop folder;
- ``mission.json`` (the twin's plan), ``setup.json`` (site, camera, platform, blackbody
  positions), ``markers.csv``, and ``truth/objects.csv`` (the scene's objects, for scoring);
- ``ports.json`` last, atomically: its appearance means the devices are ready.

Everything runs on one :class:`~.clock.TwinClock`. Faults (:class:`Fault`) switch on and off
at scene times: an unplugged device, a mute one (hung instrument, stopped camera), a burst of
line noise, a loss of the RTK fix.
"""

from __future__ import annotations

import json
import re
import threading
from dataclasses import dataclass
from pathlib import Path

from clearfast_gis.acquire.camera import DropFolderServer
from clearfast_gis.acquire.mission import Blackbodies
from clearfast_gis.acquire.ports import DEFAULT_BAUD, PORTS_FORMAT
from clearfast_gis.acquire.ptydevice import PtyDevice
from clearfast_gis.acquire.simulated import SimulatedPtu
from clearfast_gis.acquire.station import setup_document
from clearfast_gis.atomic import write_text
from clearfast_gis.simulate.devices.camera import TwinCamera
from clearfast_gis.simulate.devices.clock import TwinClock
from clearfast_gis.simulate.devices.gnss import SimulatedGnss
from clearfast_gis.simulate.devices.scheduled import ScheduledLines
from clearfast_gis.simulate.devices.templogger import SimulatedTemperatureLogger
from clearfast_gis.simulate.devices.weather import SimulatedWeatherStation
from clearfast_gis.simulate.instruments import SOIL_DEPTHS_M
from clearfast_gis.simulate.truth import write_objects
from clearfast_gis.simulate.twin import Twin
from clearfast_gis.survey.logs import write_markers
from clearfast_gis.survey.manifest import write_mission

SERIAL_DEVICES = ("gnss", "ptu", "weather", "soil")
FAULT_KINDS = ("unplug", "mute", "noise", "rtk-loss")

#: pan/tilt speed of the simulated unit, steps per scene second (about 260 degrees/s)
PTU_SPEED_STEPS_S = 5000.0
#: bytes of a line-noise burst
NOISE = bytes(range(1, 256, 7)) + b"\r\n"

_FAULT = re.compile(r"^(unplug|mute|noise):(gnss|ptu|weather|soil|camera)@([\d.]+)"
                    r"(?:\+([\d.]+))?$|^(rtk-loss)@([\d.]+)\+([\d.]+)$")


def default_blackbodies(frames: int = 10) -> Blackbodies:
    """Where the twin's blackbodies hang: behind the unit, either side, slightly up."""
    return Blackbodies(heated=(150.0, 20.0), ambient=(-150.0, 20.0), frames=frames)


@dataclass(frozen=True)
class Fault:
    """A fault of one device from ``at_s`` for ``duration_s`` scene seconds after the twin's
    start.

    ``kind``: ``unplug`` (serial devices), ``mute`` (any device, the camera too), ``noise``
    (one burst of line noise; no duration), ``rtk-loss`` (the receiver's fix drops to none).
    """

    kind: str
    device: str
    at_s: float
    duration_s: float = 0.0

    def __str__(self) -> str:
        """The ``--fault`` text (:func:`parse_fault` reads it back)."""
        if self.kind == "rtk-loss":
            return f"rtk-loss@{_secs(self.at_s)}+{_secs(self.duration_s)}"
        tail = f"+{_secs(self.duration_s)}" if self.duration_s else ""
        return f"{self.kind}:{self.device}@{_secs(self.at_s)}{tail}"


def _secs(x: float) -> str:
    """Seconds as plain digits (``3600``, ``0.25``), never in exponent form."""
    x = float(x)
    return str(int(x)) if x.is_integer() else f"{x:.6f}".rstrip("0").rstrip(".")


def parse_fault(text: str) -> Fault:
    """Parse ``unplug:gnss@3600+60``, ``mute:camera@7200+30``, ``noise:weather@100`` or
    ``rtk-loss@5400+300`` (scene seconds after the twin's start).

    Raises
    ------
    ValueError
        For anything else (an unplugged camera, a noisy camera, a fault without duration that
        needs one).
    """
    m = _FAULT.match(text.strip())
    if not m:
        raise ValueError(f"expected KIND:DEVICE@SECONDS[+SECONDS] or rtk-loss@SECONDS+SECONDS, "
                         f"got {text!r}")
    if m.group(5):
        return Fault("rtk-loss", "gnss", float(m.group(6)), float(m.group(7)))
    kind, device, at, dur = m.group(1), m.group(2), float(m.group(3)), m.group(4)
    if device == "camera" and kind != "mute":
        raise ValueError(f"the camera can only be muted, got {text!r}")
    if kind != "noise" and dur is None:
        raise ValueError(f"{kind} needs a duration (+SECONDS), got {text!r}")
    return Fault(kind, device, at, float(dur or 0.0))


class DeviceRig:
    """The twin's instruments on pseudo-terminals and a drop folder (see the module docstring).

    Parameters
    ----------
    twin : Twin
        The digital twin.
    folder : path
        Where the links, drop folder, set-up files and ports file go.
    time_scale : float
        Scene seconds per wall second.
    start_s : float, optional
        Scene UTC at start (default: the twin's start).
    blackbodies : Blackbodies, optional
        Blackbody positions (default :func:`default_blackbodies`).
    faults : sequence of Fault
        Scheduled faults.

    Attributes
    ----------
    clock : TwinClock
    devices : dict
        Device name -> :class:`~clearfast_gis.acquire.ptydevice.PtyDevice`.
    gnss, ptu : SimulatedGnss, SimulatedPtu
    camera : TwinCamera
    server : DropFolderServer
    log : list of str
        Faults switched on and off, with their scene times.
    """

    def __init__(self, twin: Twin, folder: str | Path, time_scale: float = 1.0,
                 start_s: float | None = None, blackbodies: Blackbodies | None = None,
                 faults: tuple[Fault, ...] | list[Fault] = ()) -> None:
        self.twin = twin
        self.folder = Path(folder)
        self.blackbodies = blackbodies or default_blackbodies(twin.config.blackbody_frames)
        self.faults = list(faults)
        self.log: list[str] = []
        self.clock = TwinClock(twin.start_s if start_s is None else start_s, time_scale)
        now = self.clock.now
        self.gnss = SimulatedGnss(twin.gnss_log(), now)
        self.ptu = SimulatedPtu(speed_steps_s=PTU_SPEED_STEPS_S, clock=now)
        engines = {"gnss": self.gnss, "ptu": self.ptu,
                   "weather": SimulatedWeatherStation(twin.weather_log(), now),
                   "soil": SimulatedTemperatureLogger(twin.soil_log(), twin.blackbody_log(),
                                                      now)}
        self.devices = {name: PtyDevice(engine, link=self.folder / "devices" / name, name=name)
                        for name, engine in engines.items()}
        self.camera = TwinCamera(twin, self.pointing, now, self.blackbodies,
                                 hold=self.clock.paused)
        self.server = DropFolderServer(self.camera, self.folder / "camera")
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    @property
    def ports_file(self) -> Path:
        """``<folder>/ports.json``."""
        return self.folder / "ports.json"

    def pointing(self) -> tuple[float, float]:
        """The simulated unit's true (pan_deg, tilt_deg) now."""
        pan, tilt = self.ptu.position_steps()
        return (pan * self.ptu.pan.resolution_arcsec / 3600.0,
                tilt * self.ptu.tilt.resolution_arcsec / 3600.0)

    @property
    def finished(self) -> bool:
        """True once the twin clock is past the twin's end."""
        return self.clock.now() > self.twin.end_s

    # -- files ------------------------------------------------------------------------------

    def _write_files(self) -> None:
        t = self.twin
        self.folder.mkdir(parents=True, exist_ok=True)
        write_mission(self.folder / "mission.json", t.mission)
        manifest = t.manifest(f"{t.config.name}-seed{t.seed}-acquired",
                              f"acquired from the device simulators (preset {t.config.name})")
        write_text(self.folder / "setup.json", json.dumps(setup_document(
            manifest, self.blackbodies, settle_s=0.5, soil_depths_m=SOIL_DEPTHS_M), indent=1)
            + "\n")
        write_markers(self.folder / "markers.csv", t.markers())
        write_objects(self.folder / "truth" / "objects.csv", t.objects, t.origin)

    def _write_ports(self) -> None:
        doc = {"format": PORTS_FORMAT, "format_version": 1,
               "description": f"device simulators of the twin (preset {self.twin.config.name}, "
                              f"seed {self.twin.seed}), time scale {self.clock.time_scale:g}"}
        for name in SERIAL_DEVICES:
            doc[name] = f"{self.devices[name].path},{DEFAULT_BAUD[name]}"
        doc.update({"camera": f"drop:{self.folder / 'camera'}", "mission": "mission.json",
                    "setup": "setup.json", "time_scale": self.clock.time_scale})
        write_text(self.ports_file, json.dumps(doc, indent=1) + "\n")

    # -- running ----------------------------------------------------------------------------

    def start(self) -> DeviceRig:
        """Write the files, start every device and the fault schedule, then the ports file
        (an earlier run's is removed first: its appearance means ready)."""
        self.ports_file.unlink(missing_ok=True)
        self._write_files()
        for f in self.faults:
            if f.kind == "rtk-loss":
                t0 = self.twin.start_s + f.at_s
                self.gnss.lose_fix(t0, t0 + f.duration_s, 0)
        self.clock.restart()  # scene time starts now, not when the twin was set up
        for dev in self.devices.values():
            if isinstance(dev.engine, ScheduledLines):  # built while the clock ran on
                dev.engine.restart()
            dev.start()
        self.server.start()
        self._thread = threading.Thread(target=self._schedule, daemon=True,
                                        name="clearfast-sim-faults")
        self._thread.start()
        self._write_ports()
        return self

    def _schedule(self) -> None:
        active: set[int] = set()
        done: set[int] = set()
        while not self._stop.wait(0.002):
            elapsed = self.clock.now() - self.twin.start_s
            for k, f in enumerate(self.faults):
                if k in done:
                    continue
                if k not in active and elapsed >= f.at_s:
                    self.set_fault(f, True)
                    active.add(k)
                    if f.kind in ("noise", "rtk-loss"):
                        done.add(k)
                elif k in active and elapsed >= f.at_s + f.duration_s:
                    self.set_fault(f, False)
                    done.add(k)

    def set_fault(self, fault: Fault, on: bool) -> None:
        """Switch a fault on or off now."""
        self.log.append(f"{self.clock.now() - self.twin.start_s:.0f} s {fault} "
                        f"{'on' if on else 'off'}")
        if fault.kind == "rtk-loss":
            pass  # the receiver has it from the start, to the epoch (see start())
        elif fault.kind == "mute":
            target = self.server if fault.device == "camera" else self.devices[fault.device]
            target.mute = on
        elif fault.kind == "unplug":
            (self.devices[fault.device].unplug if on else self.devices[fault.device].replug)()
        elif fault.kind == "noise":
            self.devices[fault.device].inject(NOISE)

    def stop(self) -> None:
        """Stop the schedule, the camera and every device (their links disappear)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
        self.server.stop()
        for dev in self.devices.values():
            dev.stop()

    def __enter__(self) -> DeviceRig:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()

