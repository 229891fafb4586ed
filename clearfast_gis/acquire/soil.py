"""Soil thermocouple logging: a generic multi-channel logger's lines in, ``soil.csv`` out.

Assumed input (a generic multi-channel thermocouple logger, e.g. a TC-08 or a small
microcontroller board, set to print one record per line, every 10 minutes in a survey)::

    T,2026-11-15T00:10:00Z,18.412,17.950,17.031,16.020,15.003

the literal ``T``, the logger's time in ISO 8601 UTC (``Z`` or no offset), then one
temperature in degrees C per channel, channels in the order of the configured depths.
``NAN`` or an empty field marks an open thermocouple. Other lines (banners, ``#`` comments)
are ignored; a ``T`` line with a bad time, a non-numeric value or the wrong number of
channels is counted as bad and not written.

The two calibration blackbodies' temperature sensors (paper §3.3) are wired to the same
logger, which reports them once a minute on lines of their own::

    B,2026-11-15T00:10:00Z,25.013,15.102

(``B``, time, heated blackbody, ambient blackbody, degrees C).

Output: ``soil.csv`` as :func:`clearfast_gis.survey.write_soil_log` writes it
(``time_utc,T_0.020m_C,...``) and ``blackbody/temperatures.csv``
(``time_utc,bb1_c,bb2_c``, as :func:`clearfast_gis.survey.write_blackbody_log`), headers
written once when a file is new.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable, Sequence

import serial

from clearfast_gis.acquire.appendlog import AppendLog
from clearfast_gis.acquire.linelogger import EventSink, LineLogger
from clearfast_gis.errors import InvalidInput
from clearfast_gis.timeutil import format_utc, parse_utc

#: thermocouple depths of the survey set-up, metres (docs/contracts.md §2)
DEFAULT_DEPTHS_M = (0.02, 0.05, 0.10, 0.20, 0.50)


def soil_header(depths_m: Sequence[float]) -> str:
    """The ``soil.csv`` header line for thermocouples at ``depths_m`` (metres)."""
    return "time_utc," + ",".join(f"T_{float(d):.3f}m_C" for d in depths_m) + "\n"


#: header of ``blackbody/temperatures.csv``
BLACKBODY_HEADER = "time_utc,bb1_c,bb2_c\n"


def soil_row(time_s: float, temps_c: Sequence[float]) -> str:
    """One ``soil.csv`` (or ``blackbody/temperatures.csv``) row: ISO UTC time to the second,
    temperatures (C) to 1e-4, NaN as ``NAN``."""
    vals = ",".join("NAN" if not math.isfinite(v) else f"{v:.4f}" for v in map(float, temps_c))
    return f"{format_utc(float(time_s), 'seconds')},{vals}\n"


def parse_thermocouple_line(text: str, n_channels: int, tag: str = "T"
                            ) -> tuple[float, list[float]] | None:
    """Parse ``T,<iso time>,<t1>,...`` (or the lines of another ``tag``, such as the
    blackbodies' ``B``); None for a line that is not such a record.

    Raises
    ------
    ValueError
        For a record with a bad time, a bad value or a channel count other than
        ``n_channels``.
    """
    fields = [f.strip() for f in text.strip().split(",")]
    if not fields or fields[0].upper() != tag:
        return None
    if len(fields) != n_channels + 2:
        raise ValueError(f"expected {n_channels} channels, got {len(fields) - 2}")
    t = parse_utc(fields[1])
    temps = []
    for f in fields[2:]:
        if f.upper() in ("NAN", "", "NA", "-NAN"):
            temps.append(math.nan)
            continue
        v = float(f)
        if not math.isfinite(v):
            raise ValueError("not finite")
        temps.append(v)
    return t, temps


class ThermocoupleLogger(LineLogger):
    """Logs a multi-channel thermocouple logger to ``soil.csv``.

    Parameters
    ----------
    port : serial.SerialBase
        Open pyserial port.
    path : path
        ``<survey>/soil.csv``; appended to if it exists (it must have the same header).
    depths_m : sequence of float
        Depth of each channel below the surface, metres, in channel order.
    clock : callable
        Host UTC clock, epoch seconds.
    fsync_interval_s : float
        Seconds between fsyncs.
    blackbody_path : path, optional
        ``<survey>/blackbody/temperatures.csv`` for the ``B`` lines (ignored without it).
    reopen, retry_s, on_event
        As for :class:`~clearfast_gis.acquire.linelogger.LineLogger` (reconnection, events).

    Attributes
    ----------
    n_records, n_bad : int
        Soil records written and bad ``T``/``B`` lines.
    n_blackbody : int
        Blackbody records written.
    last, last_blackbody : (time_s, temperatures) or None
        The latest soil and blackbody records.

    Raises
    ------
    InvalidInput
        For bad depths, or an existing ``path`` with another header.
    """

    kind = "soil"

    def __init__(self, port: serial.SerialBase, path: str | os.PathLike,
                 depths_m: Sequence[float] = DEFAULT_DEPTHS_M,
                 clock: Callable[[], float] = time.time, fsync_interval_s: float = 5.0,
                 blackbody_path: str | os.PathLike | None = None,
                 reopen: Callable[[], serial.SerialBase] | None = None, retry_s: float = 1.0,
                 on_event: EventSink | None = None) -> None:
        depths = [float(d) for d in depths_m]
        if not depths or any(not (math.isfinite(d) and d >= 0) for d in depths):
            raise InvalidInput("depths must be non-negative numbers (metres)", "soil depths")
        header = soil_header(depths)
        if len({f"{d:.3f}" for d in depths}) != len(depths):
            raise InvalidInput("two thermocouples at the same depth", "soil depths")
        _check_existing(path, header)
        if blackbody_path is not None:
            _check_existing(blackbody_path, BLACKBODY_HEADER)
        super().__init__(port, AppendLog(path, header.encode("ascii"), fsync_interval_s),
                         reopen=reopen, retry_s=retry_s, on_event=on_event)
        self.blackbody_log = None if blackbody_path is None else AppendLog(
            blackbody_path, BLACKBODY_HEADER.encode("ascii"), fsync_interval_s)
        self.depths_m = tuple(depths)
        self._clock = clock
        self.n_records = 0
        self.n_bad = 0
        self.n_blackbody = 0
        self.last: tuple[float, list[float]] | None = None
        self.last_blackbody: tuple[float, list[float]] | None = None

    def handle_lines(self, lines: list[bytes]) -> list[bytes]:
        out: list[bytes] = []
        bb: list[bytes] = []
        for raw in lines:
            text = raw.decode("utf-8", "replace")
            try:
                rec = parse_thermocouple_line(text, len(self.depths_m))
                bb_rec = None if rec is not None else parse_thermocouple_line(text, 2, "B")
            except (ValueError, OverflowError, OSError):
                self.n_bad += 1
                continue
            if rec is not None:
                self.n_records += 1
                self.last = rec
                out.append(soil_row(*rec).encode("ascii"))
            elif bb_rec is not None and self.blackbody_log is not None:
                self.n_blackbody += 1
                self.last_blackbody = bb_rec
                bb.append(soil_row(*bb_rec).encode("ascii"))
        if self.blackbody_log is not None:
            self.blackbody_log.append(bb)
        return out

    def close_logs(self) -> None:
        super().close_logs()
        if self.blackbody_log is not None:
            self.blackbody_log.close()

    def status(self) -> dict:
        out = super().status()
        out.update(records=self.n_records, bad=self.n_bad)
        for key, rec in (("last", self.last), ("last_blackbody", self.last_blackbody)):
            if rec is not None:
                out[key] = {"time_utc": format_utc(rec[0], "seconds"),
                            "temp_c": [None if math.isnan(v) else v for v in rec[1]]}
        if self.blackbody_log is not None:
            out["blackbody_records"] = self.n_blackbody
        return out

    def status_text(self) -> str:
        """Short status for a one-line display."""
        bad = f" ({self.n_bad} bad)" if self.n_bad else ""
        top = ""
        if self.last is not None and math.isfinite(self.last[1][0]):
            top = f" {self.depths_m[0]:g} m {self.last[1][0]:.1f} C"
        return f"soil {self.n_records} records{bad}{top}"


def _check_existing(path: str | os.PathLike, header: str) -> None:
    try:
        with open(path, "rb") as fh:
            first = fh.readline().decode("utf-8", "replace")
    except FileNotFoundError:
        return
    except OSError as exc:
        raise InvalidInput(f"cannot read: {exc.strerror or exc}", str(path)) from None
    if first.strip() and first.strip() != header.strip():
        raise InvalidInput(f"exists with another header; expected {header.strip()}", str(path),
                           "line 1")
