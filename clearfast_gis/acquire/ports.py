"""Serial port specifications (``PORT[,baud]``) and opening ports with one-line errors.

A port is a device name (``/dev/ttyUSB0``, ``COM3``, a pty such as ``/dev/pts/5``) or any
pyserial URL (``loop://``, ``socket://host:port``, ``rfc2217://host:port``). The baud rate
follows a comma; each instrument has its own default.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import serial

from clearfast_gis.errors import ClearfastError

try:  # termios (POSIX) raises its own error, not an OSError, on a vanished terminal
    import termios
    _TERMIOS_ERRORS: tuple[type[BaseException], ...] = (termios.error,)
except ImportError:  # pragma: no cover - Windows
    _TERMIOS_ERRORS = ()

#: exceptions of reading, writing or flushing a serial port that has gone away
SERIAL_ERRORS = (serial.SerialException, OSError, *_TERMIOS_ERRORS)

#: default baud rates per instrument (typical factory settings)
DEFAULT_BAUD = {"gnss": 115200, "weather": 9600, "soil": 9600, "ptu": 9600}

#: read timeout of ports opened here, seconds (how quickly a logger notices a stop request)
READ_TIMEOUT_S = 0.1


class PortError(ClearfastError):
    """A serial port that cannot be opened, read or written (the port is the ``path``)."""


@dataclass(frozen=True)
class PortSpec:
    """A serial port name or pyserial URL and its baud rate."""

    port: str
    baud: int

    def __str__(self) -> str:
        return f"{self.port},{self.baud}"


def parse_port_spec(text: str, default_baud: int) -> PortSpec:
    """Parse ``PORT[,baud]``.

    Parameters
    ----------
    text : str
        Port name or pyserial URL, optionally followed by ``,`` and the baud rate.
    default_baud : int
        Baud rate when none is given.

    Raises
    ------
    ValueError
        For an empty port name or a baud rate that is not a positive integer.
    """
    port, sep, baud_text = text.strip().rpartition(",")
    if not sep:
        port, baud_text = text.strip(), ""
    port = port.strip()
    if not port:
        raise ValueError(f"expected PORT[,baud], got {text!r}")
    if not baud_text.strip():
        return PortSpec(port, int(default_baud))
    try:
        baud = int(baud_text)
    except ValueError:
        raise ValueError(f"baud rate must be an integer, got {baud_text.strip()!r}") from None
    if baud <= 0:
        raise ValueError(f"baud rate must be positive, got {baud}")
    return PortSpec(port, baud)


def open_port(spec: PortSpec, timeout_s: float = READ_TIMEOUT_S) -> serial.SerialBase:
    """Open ``spec`` (8N1, no flow control) with a read timeout.

    Raises
    ------
    PortError
        ``<port>: cannot open serial port (<reason>)`` when the port is missing, busy or
        refused.
    """
    try:
        return serial.serial_for_url(spec.port, baudrate=spec.baud, timeout=timeout_s,
                                     write_timeout=2.0)
    except (serial.SerialException, ValueError, OSError) as exc:
        raise PortError(f"cannot open serial port ({_reason(exc)})", spec.port) from None


def _reason(exc: BaseException) -> str:
    """The OS reason of a pyserial error without the repeated port name."""
    if _TERMIOS_ERRORS and isinstance(exc, _TERMIOS_ERRORS) and len(exc.args) == 2:
        return str(exc.args[1])
    text = " ".join(str(exc).split())
    found = re.findall(r"\[Errno -?\d+\] ([^:\]]+)", text)
    if found:
        return found[-1].strip()
    m = re.search(r"\(\d+, '([^']+)'\)", text)
    if m:
        return f"not a serial device: {m.group(1)}"
    return text or type(exc).__name__
