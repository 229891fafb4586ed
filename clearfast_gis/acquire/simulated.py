"""Simulated instruments for tests and dry runs: a PTU peer and a manual clock.

:class:`SimulatedPtu` answers the FLIR PTU ASCII protocol (see :mod:`.ptu`) with a motion
model (constant speed per axis, position limits, echo and terse/verbose feedback like a real
unit). It is a pure protocol engine (:meth:`SimulatedPtu.feed` bytes in,
:meth:`SimulatedPtu.pending_output` bytes out); :class:`~.ptydevice.PtyDevice` serves it on a
pseudo-terminal, so a driver opens the slave device name exactly as it would open
``/dev/ttyUSB0`` (:func:`simulated_ptu_device`).
"""

from __future__ import annotations

import contextlib
import re
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass

from clearfast_gis.acquire.ptu import PtuReply, format_reply
from clearfast_gis.acquire.ptydevice import PtyDevice, pty_pair

__all__ = ["ManualClock", "SimulatedPtu", "pty_pair", "simulated_ptu_device"]

_COMMAND = re.compile(r"^([A-Z]+)(-?\d+)?$")


@dataclass
class _Axis:
    name: str
    resolution_arcsec: float
    min_steps: int
    max_steps: int
    speed_steps_s: float
    start: float = 0.0
    target: float = 0.0
    t0: float = 0.0

    def position(self, now: float) -> float:
        d = self.target - self.start
        travel = self.speed_steps_s * max(0.0, now - self.t0)
        if travel >= abs(d):
            return self.target
        return self.start + (travel if d > 0 else -travel)

    def arrival(self) -> float:
        return self.t0 + abs(self.target - self.start) / self.speed_steps_s

    def move(self, target: int, now: float) -> None:
        self.start = self.position(now)
        self.target = float(target)
        self.t0 = now


class SimulatedPtu:
    """A pan/tilt unit speaking the PTU ASCII protocol (the other end of the driver).

    Parameters
    ----------
    pan_resolution_arcsec, tilt_resolution_arcsec : float
        Arc seconds per step (PTU-D46 half-step value by default, 0.0514 degree).
    pan_limits_steps, tilt_limits_steps : (int, int)
        Minimum and maximum positions, steps (default pan +-159 degrees, tilt -103 to +31
        degrees: a head mounted to look down).
    speed_steps_s : float
        Speed of both axes, steps per second.
    echo : bool
        Echo commands (a real unit's power-on default).
    terse : bool
        Terse feedback (``* 1000``) rather than verbose (``* Current Pan position is 1000``).
    clock : callable
        Monotonic clock, seconds.

    Attributes
    ----------
    mute : bool
        When True the unit reads commands but never answers (a hung unit, for timeouts).
    received : list of str
        Every command received, upper case, in order.
    """

    def __init__(self, pan_resolution_arcsec: float = 185.1428,
                 tilt_resolution_arcsec: float = 185.1428,
                 pan_limits_steps: tuple[int, int] = (-3090, 3090),
                 tilt_limits_steps: tuple[int, int] = (-2000, 604),
                 speed_steps_s: float = 20000.0, echo: bool = True, terse: bool = False,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.pan = _Axis("Pan", pan_resolution_arcsec, *pan_limits_steps, speed_steps_s)
        self.tilt = _Axis("Tilt", tilt_resolution_arcsec, *tilt_limits_steps, speed_steps_s)
        self.echo = echo
        self.terse = terse
        self.mute = False
        self.received: list[str] = []
        self._clock = clock
        self._token = bytearray()
        self._out: list[tuple[float, bytes]] = []
        self._lock = threading.Lock()

    def position_steps(self) -> tuple[float, float]:
        """Current (pan, tilt) positions, steps (fractional while moving)."""
        now = self._clock()
        return self.pan.position(now), self.tilt.position(now)

    # -- protocol engine --------------------------------------------------------------------

    def feed(self, data: bytes) -> None:
        """Take bytes from the driver; complete commands are answered (see
        :meth:`pending_output`)."""
        with self._lock:
            for b in data:
                if b in b" \r\n":
                    if self._token:
                        self._handle(self._token.decode("ascii", "replace").strip())
                        self._token.clear()
                else:
                    self._token.append(b)

    def pending_output(self) -> bytes:
        """Bytes due to be sent now."""
        now = self._clock()
        with self._lock:
            due = [o for o in self._out if o[0] <= now]
            self._out = [o for o in self._out if o[0] > now]
        return b"".join(o[1] for o in due)

    def _say(self, text: str, at: float | None = None) -> None:
        if not self.mute:
            self._out.append((self._clock() if at is None else at, text.encode("ascii")))

    def _reply(self, ok: bool, text: str = "", at: float | None = None) -> None:
        self._say(format_reply(PtuReply(ok, text)), at)

    def _handle(self, token: str) -> None:
        cmd = token.upper()
        self.received.append(cmd)
        if self.echo:
            self._say(token + " ")
        m = _COMMAND.match(cmd)
        if not m:
            self._reply(False, "Illegal Command")
            return
        op, arg = m.group(1), m.group(2)
        now = self._clock()
        axis = {"P": self.pan, "T": self.tilt}.get(op[0])
        if op in ("PP", "TP"):
            if arg is None:
                pos = int(round(axis.position(now)))
                self._reply(True, str(pos) if self.terse
                            else f"Current {axis.name} position is {pos}")
                return
            target = int(arg)
            if target > axis.max_steps:
                self._reply(False, f"Maximum allowable {axis.name} position is {axis.max_steps}")
            elif target < axis.min_steps:
                self._reply(False, f"Minimum allowable {axis.name} position is {axis.min_steps}")
            else:
                axis.move(target, now)
                self._reply(True)
        elif op in ("PN", "PX", "TN", "TX") and arg is None:
            lo = op[1] == "N"
            pos = axis.min_steps if lo else axis.max_steps
            self._reply(True, str(pos) if self.terse else
                        f"{'Minimum' if lo else 'Maximum'} {axis.name} position is {pos}")
        elif op in ("PR", "TR") and arg is None:
            res = f"{axis.resolution_arcsec:.4f}"
            self._reply(True, res if self.terse
                        else f"{axis.name} resolution is {res} seconds arc per position")
        elif op == "A" and arg is None:
            self._reply(True, at=max(now, self.pan.arrival(), self.tilt.arrival()))
        elif op in ("ED", "EE") and arg is None:
            self.echo = op == "EE"
            self._reply(True)
        elif op in ("FT", "FV") and arg is None:
            self.terse = op == "FT"
            self._reply(True)
        elif op == "I" and arg is None:
            self._reply(True)
        else:
            self._reply(False, "Illegal Command")


@contextlib.contextmanager
def simulated_ptu_device(ptu: SimulatedPtu | None = None) -> Iterator[tuple[str, SimulatedPtu]]:
    """Run a :class:`SimulatedPtu` behind a pty; yields (device name, simulator)."""
    ptu = SimulatedPtu() if ptu is None else ptu
    with PtyDevice(ptu, name="ptu") as device:
        yield device.path, ptu


class ManualClock:
    """A clock that advances only when told: ``clock()`` reads it, ``clock.sleep(dt)`` and
    ``clock.advance(dt)`` move it forward (seconds)."""

    def __init__(self, start_s: float = 0.0) -> None:
        self.now_s = float(start_s)
        self.sleeps: list[float] = []

    def __call__(self) -> float:
        return self.now_s

    def sleep(self, dt_s: float) -> None:
        """Advance by ``dt_s`` seconds (records the request)."""
        self.sleeps.append(float(dt_s))
        self.advance(dt_s)

    def advance(self, dt_s: float) -> None:
        """Advance by ``dt_s`` seconds (negative values are ignored)."""
        self.now_s += max(0.0, float(dt_s))
