"""The read loop shared by the line-oriented instrument loggers (GNSS, weather, soil).

A logger reads whatever bytes the port has, splits them into lines, lets the subclass decide
what each line becomes in its log (:meth:`LineLogger.handle_lines`), and appends the result
in whole lines. :meth:`LineLogger.run` loops until a stop event is set, which it notices
within the port's read timeout; the log is then closed complete (an incomplete last input line
is dropped, never written).

When the logger is given a way to reopen its port (``reopen``), a lost device (cable pulled,
USB adapter reset, converter rebooted) does not end the run: the port is closed, the line in
progress is dropped, and the port is reopened every ``retry_s`` seconds until it answers again
(a USB adapter that comes back under the same name or ``/dev/serial/by-id`` link); each loss and
each return is reported as an event.
"""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Callable

import serial

from clearfast_gis.acquire.appendlog import AppendLog, LineSplitter
from clearfast_gis.acquire.ports import READ_TIMEOUT_S, SERIAL_ERRORS, PortError, _reason
from clearfast_gis.errors import ClearfastError

#: ``on_event(instrument, event, detail)``: a logger's report of something worth a log line
EventSink = Callable[[str, str, str], None]


def port_name(port: serial.SerialBase) -> str:
    """The device name or URL of an open pyserial port."""
    return str(getattr(port, "portstr", None) or getattr(port, "port", None) or "serial port")


class LineLogger:
    """Base class: reads ``port``, splits lines, appends to ``log``.

    Parameters
    ----------
    port : serial.SerialBase
        An open pyserial port (``serial.Serial`` or from ``serial.serial_for_url``). If it has
        no read timeout, one of :data:`~clearfast_gis.acquire.ports.READ_TIMEOUT_S` is set so
        that a stop request is noticed.
    log : AppendLog
        The output log.
    reopen : callable, optional
        ``reopen() -> port`` opens the instrument's port again (raising
        :class:`~clearfast_gis.acquire.ports.PortError` while it is missing); with it a lost
        port is reconnected instead of ending :meth:`run`.
    retry_s : float
        Seconds between attempts to reopen a lost port.
    on_event : callable, optional
        ``on_event(kind, event, detail)`` is called for losses, reconnections and what the
        subclass reports (fix changes, missing replies).

    Attributes
    ----------
    error : str or None
        One-line description of the error that ended :meth:`run`, if any.
    connected : bool
        False while a lost port is being reopened.
    n_disconnects : int
        Times the port was lost.
    """

    #: instrument name used in status displays
    kind = "instrument"

    def __init__(self, port: serial.SerialBase, log: AppendLog,
                 reopen: Callable[[], serial.SerialBase] | None = None, retry_s: float = 1.0,
                 on_event: EventSink | None = None) -> None:
        self.port = port
        self.log = log
        self.splitter = LineSplitter()
        self.error: str | None = None
        self.n_lines_in = 0
        self.reopen = reopen
        self.retry_s = float(retry_s)
        self.on_event = on_event
        self.connected = True
        self.n_disconnects = 0
        if port.timeout is None:
            port.timeout = READ_TIMEOUT_S
        self._thread: threading.Thread | None = None

    def event(self, event: str, detail: str = "") -> None:
        """Report an event to ``on_event`` (if any)."""
        if self.on_event is not None:
            self.on_event(self.kind, event, detail)

    @property
    def port_name(self) -> str:
        """The device name or URL of the port."""
        return port_name(self.port)

    def handle_lines(self, lines: list[bytes]) -> list[bytes]:
        """Process complete input lines; return the lines to append to the log."""
        return lines

    def feed(self, data: bytes) -> int:
        """Process received bytes (also usable without a port); return the lines completed."""
        lines = self.splitter.feed(data)
        if lines:
            self.n_lines_in += len(lines)
            self.log.append(self.handle_lines(lines))
        return len(lines)

    def poll(self) -> int:
        """Read what the port has (waiting at most its read timeout) and process it.

        Raises
        ------
        PortError
            When reading fails (device unplugged, socket closed).
        """
        try:
            waiting = self.port.in_waiting
            data = self.port.read(max(1, waiting))
        except SERIAL_ERRORS as exc:
            raise PortError(f"read failed ({_reason(exc)})", self.port_name) from None
        return self.feed(data) if data else 0

    def reconnect(self, lost: PortError, stop: threading.Event) -> bool:
        """Close the lost port and reopen it every :attr:`retry_s` seconds until it opens or
        ``stop`` is set; True when the port is back. The incomplete line is dropped."""
        self.connected = False
        self.n_disconnects += 1
        self.event("disconnected", lost.message)
        with contextlib.suppress(Exception):
            self.port.close()
        self.splitter = LineSplitter()
        while not stop.wait(self.retry_s):
            try:
                port = self.reopen()
            except PortError:
                continue
            if port.timeout is None:
                port.timeout = READ_TIMEOUT_S
            self.port = port
            self.connected = True
            self.event("reconnected", self.port_name)
            self.on_reconnect()
            return True
        return False

    def on_reconnect(self) -> None:
        """Called after the port was reopened (subclasses reset their protocol state)."""

    def run(self, stop: threading.Event) -> None:
        """Poll until ``stop`` is set or reading or writing fails (the error is kept in
        :attr:`error`; a lost port is reopened when :attr:`reopen` is set); always closes
        the log."""
        try:
            while not stop.is_set():
                try:
                    self.poll()
                except PortError as exc:
                    if self.reopen is None:
                        raise
                    if not self.reconnect(exc, stop):
                        break  # stopped while the port was away
        except ClearfastError as exc:  # port lost, disk full
            self.error = exc.one_line()
        finally:
            try:
                self.close_logs()
            except ClearfastError as exc:
                self.error = self.error or exc.one_line()

    def close_logs(self) -> None:
        """fsync and close the output log(s)."""
        self.log.close()

    def start(self, stop: threading.Event) -> threading.Thread:
        """Run :meth:`run` in a daemon thread and return it."""
        self._thread = threading.Thread(target=self.run, args=(stop,), daemon=True,
                                        name=f"clearfast-{self.kind}")
        self._thread.start()
        return self._thread

    def status(self) -> dict:
        """A JSON-ready snapshot for status displays."""
        return {"port": self.port_name, "lines": self.n_lines_in, "error": self.error,
                "connected": self.connected, "disconnects": self.n_disconnects}
