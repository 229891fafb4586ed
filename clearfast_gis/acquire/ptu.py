"""FLIR (Directed Perception) PTU-style pan/tilt unit driver over a serial ASCII protocol.

Protocol (PTU-D46/E46 command set, the subset a stop-and-go survey needs):

- Commands are ASCII, case-insensitive, ended by a space delimiter: ``PP1000 `` sets the
  absolute pan position in steps, ``TP-500 `` the tilt position, ``A `` awaits the completion of
  both motions, ``PP `` / ``TP `` query the current positions, ``PR `` / ``TR `` query the
  resolutions in arc seconds per step, ``ED `` disables the echo, ``FT `` selects terse
  feedback, ``I `` immediate execution mode.
- Each command is answered by one line ending in CR LF: ``*`` (accepted) optionally followed by
  a value (``* 1000`` terse, ``* Current Pan position is 1000`` verbose) or ``!`` followed by an
  error message (``! Maximum allowable Pan position is 3090``). With echo on, the line starts
  with the echoed command text.

Angles are degrees (``pan_deg``, ``tilt_deg`` as in ``frames.csv``); steps are integers;
``resolution_deg`` is degrees per step (arc seconds / 3600).
"""

from __future__ import annotations

import math
import re
import time
from collections.abc import Callable
from dataclasses import dataclass

import serial

from clearfast_gis.acquire.linelogger import port_name
from clearfast_gis.acquire.ports import PortError, _reason
from clearfast_gis.errors import ClearfastError

_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


class PtuError(ClearfastError):
    """The pan/tilt unit refused a command (``!`` reply); the port is the ``path``."""


class PtuTimeout(PtuError):
    """The pan/tilt unit did not answer in time."""


class PtuProtocolError(PtuError):
    """A reply that is neither ``*`` nor ``!`` (wrong baud rate, wrong device)."""


@dataclass(frozen=True)
class PtuReply:
    """One parsed reply line.

    Attributes
    ----------
    ok : bool
        True for ``*`` (accepted), False for ``!`` (error).
    text : str
        What follows the ``*`` or ``!``, stripped (the value or the error message).
    """

    ok: bool
    text: str

    def number(self) -> float:
        """The first number in :attr:`text` (terse ``* 1000`` or verbose replies).

        Raises
        ------
        PtuProtocolError
            When the reply holds no number.
        """
        m = _NUMBER.search(self.text)
        value = float(m.group(0)) if m else math.nan
        if not math.isfinite(value):
            raise PtuProtocolError(f"expected a number in the reply, got {self.text[:60]!r}")
        return value


def parse_reply(line: str, echo: str | None = None) -> PtuReply:
    """Parse one reply line of the unit.

    Parameters
    ----------
    line : str
        The line, with or without its CR LF.
    echo : str, optional
        The command sent; an echoed copy at the start of the line is removed.

    Raises
    ------
    PtuProtocolError
        When the line (after the echo) does not start with ``*`` or ``!``.
    """
    text = line.strip()
    if echo:
        cmd = echo.strip()
        if cmd and text.upper().startswith(cmd.upper()):
            text = text[len(cmd):].strip()
    if text.startswith("*"):
        return PtuReply(True, text[1:].strip())
    if text.startswith("!"):
        return PtuReply(False, text[1:].strip())
    raise PtuProtocolError(f"unexpected reply {text[:60]!r} (expected '*' or '!')")


def format_reply(reply: PtuReply) -> str:
    """The line a unit sends for ``reply`` (CR LF included); inverse of :func:`parse_reply`."""
    mark = "*" if reply.ok else "!"
    return f"{mark} {reply.text}\r\n" if reply.text else f"{mark}\r\n"


def deg_to_steps(angle_deg: float, resolution_deg: float) -> int:
    """Nearest step count of ``angle_deg`` for a unit of ``resolution_deg`` degrees per step."""
    if not resolution_deg > 0:
        raise ValueError(f"resolution must be positive, got {resolution_deg}")
    return int(round(float(angle_deg) / float(resolution_deg)))


def steps_to_deg(steps: int, resolution_deg: float) -> float:
    """Angle in degrees of ``steps`` for a unit of ``resolution_deg`` degrees per step."""
    return float(steps) * float(resolution_deg)


class PanTiltUnit:
    """Driver of a FLIR PTU-style pan/tilt unit.

    Parameters
    ----------
    port : serial.SerialBase
        Open pyserial port connected to the unit.
    pan_resolution_deg, tilt_resolution_deg : float, optional
        Degrees per step; queried from the unit (``PR``/``TR``) by :meth:`initialize` when not
        given.
    timeout_s : float
        Reply timeout of ordinary commands, seconds.
    move_timeout_s : float
        Timeout of ``A`` (await completion), seconds.
    clock : callable
        Monotonic clock, seconds (for timeouts).
    """

    def __init__(self, port: serial.SerialBase, pan_resolution_deg: float | None = None,
                 tilt_resolution_deg: float | None = None, timeout_s: float = 2.0,
                 move_timeout_s: float = 60.0,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.port = port
        self.pan_resolution_deg = pan_resolution_deg
        self.tilt_resolution_deg = tilt_resolution_deg
        self.timeout_s = float(timeout_s)
        self.move_timeout_s = float(move_timeout_s)
        self._clock = clock
        self._buf = bytearray()
        if port.timeout is None or port.timeout > 0.1:
            port.timeout = 0.05

    @property
    def name(self) -> str:
        """Port name or URL of the unit."""
        return port_name(self.port)

    # -- protocol ---------------------------------------------------------------------------

    def command(self, cmd: str, timeout_s: float | None = None) -> PtuReply:
        """Send ``cmd`` and return its ``*`` reply.

        Raises
        ------
        PtuError
            ``<port>: pan/tilt unit refused 'PP99999': <message>`` for a ``!`` reply.
        PtuTimeout
            When no complete reply line arrives within the timeout.
        PtuProtocolError
            For a reply that is neither ``*`` nor ``!``.
        """
        cmd = cmd.strip()
        timeout = self.timeout_s if timeout_s is None else float(timeout_s)
        try:
            self.port.reset_input_buffer()
            self._buf.clear()
            self.port.write((cmd + " ").encode("ascii"))
            self.port.flush()
        except (serial.SerialException, OSError) as exc:
            raise PortError(f"write failed ({_reason(exc)})", self.name) from None
        deadline = self._clock() + timeout
        while True:
            line = self._read_line(deadline)
            if line is None:
                raise PtuTimeout(f"pan/tilt unit: no reply to {cmd!r} within {timeout:g} s",
                                 self.name)
            text = line.decode("ascii", "replace").strip()
            if not text or text.upper() == cmd.upper():  # blank line or a bare echo
                continue
            try:
                reply = parse_reply(text, echo=cmd)
            except PtuProtocolError as exc:
                raise PtuProtocolError(f"pan/tilt unit: {exc.message} to {cmd!r}",
                                       self.name) from None
            if not reply.ok:
                raise PtuError(f"pan/tilt unit refused {cmd!r}: {reply.text or 'error'}",
                               self.name)
            return reply

    def _read_line(self, deadline: float) -> bytes | None:
        while True:
            end = self._buf.find(b"\n")
            if end >= 0:
                line = bytes(self._buf[:end + 1])
                del self._buf[:end + 1]
                return line
            if self._clock() >= deadline:
                return None
            try:
                data = self.port.read(max(1, self.port.in_waiting))
            except (serial.SerialException, OSError) as exc:
                raise PortError(f"read failed ({_reason(exc)})", self.name) from None
            self._buf += data

    def _query_number(self, cmd: str) -> float:
        reply = self.command(cmd)
        try:
            return reply.number()
        except PtuProtocolError as exc:
            raise PtuProtocolError(f"pan/tilt unit: {exc.message} to {cmd!r}",
                                   self.name) from None

    # -- set-up -----------------------------------------------------------------------------

    def initialize(self) -> None:
        """Echo off, terse feedback, immediate mode; query resolutions not configured."""
        self.command("ED")
        self.command("FT")
        self.command("I")
        if self.pan_resolution_deg is None or self.tilt_resolution_deg is None:
            pan, tilt = self.query_resolution()
            if self.pan_resolution_deg is None:
                self.pan_resolution_deg = pan
            if self.tilt_resolution_deg is None:
                self.tilt_resolution_deg = tilt

    def query_resolution(self) -> tuple[float, float]:
        """Pan and tilt resolution from ``PR``/``TR``, degrees per step."""
        pan = self._query_number("PR") / 3600.0
        tilt = self._query_number("TR") / 3600.0
        for axis, res in (("pan", pan), ("tilt", tilt)):
            if not res > 0:
                raise PtuProtocolError(f"pan/tilt unit: {axis} resolution {res * 3600:g} "
                                       "arc seconds per step is not positive", self.name)
        return pan, tilt

    def _resolutions(self) -> tuple[float, float]:
        if self.pan_resolution_deg is None or self.tilt_resolution_deg is None:
            raise PtuError("pan/tilt unit: resolution unknown (call initialize() or give "
                           "pan_resolution_deg and tilt_resolution_deg)", self.name)
        return self.pan_resolution_deg, self.tilt_resolution_deg

    # -- angles -----------------------------------------------------------------------------

    def to_steps(self, pan_deg: float, tilt_deg: float) -> tuple[int, int]:
        """Nearest (pan, tilt) step counts of angles in degrees."""
        rp, rt = self._resolutions()
        return deg_to_steps(pan_deg, rp), deg_to_steps(tilt_deg, rt)

    def to_degrees(self, pan_steps: int, tilt_steps: int) -> tuple[float, float]:
        """(pan_deg, tilt_deg) of step counts."""
        rp, rt = self._resolutions()
        return steps_to_deg(pan_steps, rp), steps_to_deg(tilt_steps, rt)

    def set_position(self, pan_deg: float, tilt_deg: float) -> tuple[int, int]:
        """Command absolute positions (``PP<steps>``, ``TP<steps>``) without waiting;
        return the commanded steps."""
        pan_steps, tilt_steps = self.to_steps(pan_deg, tilt_deg)
        self.command(f"PP{pan_steps}")
        self.command(f"TP{tilt_steps}")
        return pan_steps, tilt_steps

    def await_completion(self) -> None:
        """``A``: wait until both axes have reached their commanded positions."""
        self.command("A", timeout_s=self.move_timeout_s)

    def position_steps(self) -> tuple[int, int]:
        """Current (pan, tilt) positions in steps (``PP``/``TP`` queries)."""
        return int(round(self._query_number("PP"))), int(round(self._query_number("TP")))

    def position(self) -> tuple[float, float]:
        """Current (pan_deg, tilt_deg) read back from the unit."""
        return self.to_degrees(*self.position_steps())

    def move_to(self, pan_deg: float, tilt_deg: float) -> tuple[float, float]:
        """Move to (pan_deg, tilt_deg), wait for completion, return the read-back angles."""
        self.set_position(pan_deg, tilt_deg)
        self.await_completion()
        return self.position()
