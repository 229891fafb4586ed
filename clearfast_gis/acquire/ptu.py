"""FLIR (Directed Perception) PTU-style pan/tilt unit driver over a serial ASCII protocol.

Protocol (PTU-D46/E46 command set, the subset a stop-and-go survey needs):

- Commands are ASCII, case-insensitive, ended by a space delimiter: ``PP1000 `` sets the
  absolute pan position in steps, ``TP-500 `` the tilt position, ``A `` awaits the completion of
  both motions, ``PP `` / ``TP `` query the current positions, ``PR `` / ``TR `` query the
  resolutions in arc seconds per step, ``PN `` / ``PX `` / ``TN `` / ``TX `` the minimum and
  maximum positions in steps, ``ED `` disables the echo, ``FT `` selects terse feedback,
  ``I `` immediate execution mode.
- Each command is answered by one line ending in CR LF: ``*`` (accepted) optionally followed by
  a value (``* 1000`` terse, ``* Current Pan position is 1000`` verbose) or ``!`` followed by an
  error message (``! Maximum allowable Pan position is 3090``). With echo on, the line starts
  with the echoed command text.

Angles are degrees (``pan_deg``, ``tilt_deg`` as in ``frames.csv``); steps are integers;
``resolution_deg`` is degrees per step (arc seconds / 3600).

With ``reopen`` the driver survives a lost connection (USB adapter reset, cable pulled and
plugged back): a move that fails on the port or gets no reply reopens the port every
``retry_s`` seconds for up to ``reconnect_s`` seconds, sets the unit up again and repeats the
whole move (the unit keeps its position while its serial link is down).
"""

from __future__ import annotations

import contextlib
import math
import re
import time
from collections.abc import Callable
from dataclasses import dataclass

import serial

from clearfast_gis.acquire.linelogger import port_name
from clearfast_gis.acquire.ports import SERIAL_ERRORS, PortError, _reason
from clearfast_gis.errors import ClearfastError

_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


class PtuError(ClearfastError):
    """The pan/tilt unit refused a command (``!`` reply); the port is the ``path``."""


class PtuTimeout(PtuError):
    """The pan/tilt unit did not answer in time."""


class PtuLimitError(PtuError):
    """A requested position lies outside the unit's limits."""


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
    reopen : callable, optional
        ``reopen() -> port`` opens the unit's port again; with it a lost connection is
        reconnected during :meth:`move_to`.
    reconnect_s, retry_s : float
        How long to try to reconnect and how often, seconds.
    on_event : callable, optional
        ``on_event("ptu", event, detail)`` for losses and reconnections.

    Attributes
    ----------
    limits_steps : (int, int, int, int) or None
        Pan minimum, pan maximum, tilt minimum, tilt maximum, steps (queried by
        :meth:`initialize`; None when the unit does not tell).
    n_reconnects : int
        Successful reconnections.
    """

    def __init__(self, port: serial.SerialBase, pan_resolution_deg: float | None = None,
                 tilt_resolution_deg: float | None = None, timeout_s: float = 2.0,
                 move_timeout_s: float = 60.0,
                 clock: Callable[[], float] = time.monotonic,
                 reopen: Callable[[], serial.SerialBase] | None = None,
                 reconnect_s: float = 60.0, retry_s: float = 1.0,
                 on_event: Callable[[str, str, str], None] | None = None) -> None:
        self.port = port
        self.pan_resolution_deg = pan_resolution_deg
        self.tilt_resolution_deg = tilt_resolution_deg
        self.timeout_s = float(timeout_s)
        self.move_timeout_s = float(move_timeout_s)
        self._clock = clock
        self._buf = bytearray()
        self.reopen = reopen
        self.reconnect_s = float(reconnect_s)
        self.retry_s = float(retry_s)
        self.on_event = on_event
        self.limits_steps: tuple[int, int, int, int] | None = None
        self.n_reconnects = 0
        self._set_timeout(port)

    @staticmethod
    def _set_timeout(port: serial.SerialBase) -> None:
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
        except SERIAL_ERRORS as exc:
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
            except SERIAL_ERRORS as exc:
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
        """Echo off, terse feedback, immediate mode; query resolutions not configured and the
        position limits (left unknown if the unit refuses the queries)."""
        self.command("ED")
        self.command("FT")
        self.command("I")
        if self.pan_resolution_deg is None or self.tilt_resolution_deg is None:
            pan, tilt = self.query_resolution()
            if self.pan_resolution_deg is None:
                self.pan_resolution_deg = pan
            if self.tilt_resolution_deg is None:
                self.tilt_resolution_deg = tilt
        if self.limits_steps is None:
            try:
                self.limits_steps = self.query_limits()
            except PtuTimeout:
                raise
            except PtuError:  # older firmware without PN/PX/TN/TX
                self.limits_steps = None

    def query_limits(self) -> tuple[int, int, int, int]:
        """Pan min, pan max, tilt min, tilt max positions, steps (``PN PX TN TX``)."""
        pn, px, tn, tx = (int(round(self._query_number(c))) for c in ("PN", "PX", "TN", "TX"))
        return pn, px, tn, tx

    def limits_deg(self) -> tuple[float, float, float, float] | None:
        """The limits in degrees (pan min, pan max, tilt min, tilt max), or None."""
        if self.limits_steps is None:
            return None
        rp, rt = self._resolutions()
        pn, px, tn, tx = self.limits_steps
        return pn * rp, px * rp, tn * rt, tx * rt

    def check_position(self, pan_deg: float, tilt_deg: float) -> None:
        """Raise :class:`PtuLimitError` when (pan_deg, tilt_deg) is outside the known limits
        (nothing when the limits are unknown)."""
        if self.limits_steps is None:
            return
        ps, ts = self.to_steps(pan_deg, tilt_deg)
        pn, px, tn, tx = self.limits_steps
        lim = self.limits_deg()
        for axis, steps, lo, hi, deg, lo_deg, hi_deg in (
                ("pan", ps, pn, px, pan_deg, lim[0], lim[1]),
                ("tilt", ts, tn, tx, tilt_deg, lim[2], lim[3])):
            if not lo <= steps <= hi:
                raise PtuLimitError(f"pan/tilt unit: {axis} {deg:.3f} deg is outside the "
                                    f"unit's range {lo_deg:.3f} to {hi_deg:.3f} deg", self.name)

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
        return the commanded steps.

        Raises
        ------
        PtuLimitError
            Before anything is sent, for a position outside the unit's known limits.
        """
        self.check_position(pan_deg, tilt_deg)
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
        """Move to (pan_deg, tilt_deg), wait for completion, return the read-back angles.

        With ``reopen``, a lost port or a missing reply reconnects (see :meth:`reconnect`) and
        repeats the move once.
        """
        try:
            return self._move(pan_deg, tilt_deg)
        except (PortError, PtuTimeout) as exc:
            if self.reopen is None:
                raise
            self.reconnect(exc)
            return self._move(pan_deg, tilt_deg)

    def _move(self, pan_deg: float, tilt_deg: float) -> tuple[float, float]:
        self.set_position(pan_deg, tilt_deg)
        self.await_completion()
        return self.position()

    def reconnect(self, lost: ClearfastError) -> None:
        """Reopen the port every ``retry_s`` seconds until the unit answers again (set up
        anew: echo, feedback, mode), for at most ``reconnect_s`` seconds.

        Raises
        ------
        ClearfastError
            ``lost`` again when the unit does not come back in time.
        """
        if self.on_event is not None:
            self.on_event("ptu", "disconnected", lost.message)
        deadline = self._clock() + self.reconnect_s
        while True:
            with contextlib.suppress(Exception):
                self.port.close()
            try:
                self.port = self.reopen()
                self._set_timeout(self.port)
                self._buf.clear()
                self.initialize()
            except (PortError, PtuError):
                if self._clock() + self.retry_s > deadline:
                    raise lost from None
                time.sleep(self.retry_s)
                continue
            self.n_reconnects += 1
            if self.on_event is not None:
                self.on_event("ptu", "reconnected", self.name)
            return
