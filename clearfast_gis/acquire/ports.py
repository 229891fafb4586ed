"""Serial port specifications (``PORT[,baud]``), ports files, and opening ports with one-line
errors.

A port is a device name (``/dev/ttyUSB0``, ``COM3``, a pty such as ``/dev/pts/5``, a
``/dev/serial/by-id`` link) or any pyserial URL (``loop://``, ``socket://host:port``,
``rfc2217://host:port``). The baud rate follows a comma; each instrument has its own default.
A ports file (:func:`read_ports_file`) names the ports of a station in one place.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path

import serial

from clearfast_gis.errors import ClearfastError, InvalidInput

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


#: instruments a ports file or the command line names, with the camera
INSTRUMENTS = ("gnss", "ptu", "weather", "soil")
PORTS_FORMAT = "clearfast-ports"


@dataclass(frozen=True)
class PortsFile:
    """A ports file (``ports.json``), as ``clearfast simulate-devices`` writes it or an operator
    keeps it for a station::

        {"format": "clearfast-ports", "format_version": 1,
         "gnss": "/dev/serial/by-id/usb-u-blox_GNSS-if00,115200", "ptu": "/dev/ttyUSB1",
         "weather": "/dev/ttyUSB2", "soil": "/dev/ttyUSB3", "camera": "drop:/data/camera",
         "mission": "mission.json", "setup": "setup.json", "time_scale": 1}

    Ports are ``PORT[,BAUD]`` as on the command line; ``mission`` and ``setup`` are relative
    to the ports file; ``time_scale`` is the scene time's speed of a device simulator (1 for
    real instruments).

    Attributes
    ----------
    ports : dict
        Instrument -> :class:`PortSpec`.
    camera : str or None
        Camera specification (``drop:DIR``).
    mission, setup : Path or None
        Resolved paths.
    time_scale : float
        Survey seconds per wall second.
    """

    ports: dict
    camera: str | None
    mission: Path | None
    setup: Path | None
    time_scale: float


def read_ports_file(path: str | os.PathLike) -> PortsFile:
    """Read and check a ports file.

    Raises
    ------
    InvalidInput
        ``ports.json: <key>: <problem>``.
    """
    from clearfast_gis.survey._text import read_text
    from clearfast_gis.survey.manifest import parse_json

    path = Path(path)
    label = str(path)
    doc = parse_json(read_text(path, label), label)
    if not isinstance(doc, dict) or doc.get("format") != PORTS_FORMAT:
        raise InvalidInput(f'expected an object with "format": "{PORTS_FORMAT}"', label,
                           "format")
    known = {"format", "format_version", "description", "camera", "mission", "setup",
             "time_scale", *INSTRUMENTS}
    extra = sorted(set(doc) - known)
    if extra:
        raise InvalidInput(f"unknown key (expected {', '.join(sorted(known))})", label, extra[0])
    ports = {}
    for kind in INSTRUMENTS:
        if kind in doc:
            if not isinstance(doc[kind], str):
                raise InvalidInput("expected PORT[,BAUD] as a text", label, kind)
            try:
                ports[kind] = parse_port_spec(doc[kind], DEFAULT_BAUD[kind])
            except ValueError as exc:
                raise InvalidInput(str(exc), label, kind) from None
    for key in ("camera", "mission", "setup"):
        if key in doc and not (isinstance(doc[key], str) and doc[key].strip()):
            raise InvalidInput("expected a non-empty text", label, key)
    scale = doc.get("time_scale", 1)
    if isinstance(scale, bool) or not isinstance(scale, int | float) or not 0 < scale < 1e7:
        raise InvalidInput("expected a positive number (scene seconds per second)", label,
                           "time_scale")
    return PortsFile(ports, doc.get("camera"),
                     path.parent / doc["mission"] if "mission" in doc else None,
                     path.parent / doc["setup"] if "setup" in doc else None, float(scale))
