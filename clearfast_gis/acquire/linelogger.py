"""The read loop shared by the line-oriented instrument loggers (GNSS, weather, soil).

A logger reads whatever bytes the port has, splits them into lines, lets the subclass decide
what each line becomes in its log (:meth:`LineLogger.handle_lines`), and appends the result
in whole lines. :meth:`LineLogger.run` loops until a stop event is set, which it notices
within the port's read timeout; the log is then closed complete (an incomplete last input line
is dropped, never written).
"""

from __future__ import annotations

import threading

import serial

from clearfast_gis.acquire.appendlog import AppendLog, LineSplitter
from clearfast_gis.acquire.ports import READ_TIMEOUT_S, PortError, _reason
from clearfast_gis.errors import ClearfastError


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

    Attributes
    ----------
    error : str or None
        One-line description of the error that ended :meth:`run`, if any.
    """

    #: instrument name used in status displays
    kind = "instrument"

    def __init__(self, port: serial.SerialBase, log: AppendLog) -> None:
        self.port = port
        self.log = log
        self.splitter = LineSplitter()
        self.error: str | None = None
        self.n_lines_in = 0
        if port.timeout is None:
            port.timeout = READ_TIMEOUT_S
        self._thread: threading.Thread | None = None

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
        except (serial.SerialException, OSError) as exc:
            raise PortError(f"read failed ({_reason(exc)})", self.port_name) from None
        return self.feed(data) if data else 0

    def run(self, stop: threading.Event) -> None:
        """Poll until ``stop`` is set or reading or writing fails (the error is kept in
        :attr:`error`); always closes the log."""
        try:
            while not stop.is_set():
                self.poll()
        except ClearfastError as exc:  # port lost, disk full
            self.error = exc.one_line()
        finally:
            try:
                self.log.close()
            except ClearfastError as exc:
                self.error = self.error or exc.one_line()

    def start(self, stop: threading.Event) -> threading.Thread:
        """Run :meth:`run` in a daemon thread and return it."""
        self._thread = threading.Thread(target=self.run, args=(stop,), daemon=True,
                                        name=f"clearfast-{self.kind}")
        self._thread.start()
        return self._thread

    def status(self) -> dict:
        """A JSON-ready snapshot for status displays."""
        return {"port": self.port_name, "lines": self.n_lines_in, "error": self.error}
