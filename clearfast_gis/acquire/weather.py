"""Weather station logging: Campbell Scientific TOA5 data lines in, ``weather.dat`` (TOA5) out.

Assumed input: the station's datalogger (CR1000X or alike, clock on UTC) sends each 1-minute
record of its table as one TOA5 data line on its serial port, the way ``TOA5`` files hold
them: ``"2026-11-15 00:01:00",42,15.21,60.3,1005.2,2.10,0,301.5,0``. Columns are found by
name, never by position: the station's TOA5 field-name line (``"TIMESTAMP","RECORD",...``)
sets the column order and its units line (``"TS","RN",...``) the units; the names are mapped
to quantities by the station profile and Campbell's standard names
(:func:`clearfast_gis.survey.station_profiles.map_columns`), and the values converted to the
toolkit's units. A station that sends no header needs its field names in the station
profile (``header``); data lines that cannot be mapped by name are refused and counted
(``n_unmapped``), with one event saying why. ``NAN`` marks a missing value.

Output: ``weather.dat`` in TOA5 exactly as :func:`clearfast_gis.survey.write_toa5` writes it,
header written once when the file is new; the station's record number is kept (or counted
on from the file's last record when the station sends none). Lines that are not a valid
record are counted, not written.

Polled stations (``poll_interval_s``): the datalogger's program answers a one-line request
for the records it holds from a record number on::

    host:    GET 42<CR><LF>
    station: "2026-11-15 00:42:00",42,15.21,60.3,1005.2,2.10,0,301.5,0<CR><LF>
             "2026-11-15 00:43:00",43,15.19,60.4,1005.2,2.04,0,301.2,0<CR><LF>
             END<CR><LF>

oldest first, at most a page of records (then ``MORE`` instead of ``END``: the logger asks
again at once); a reply may start with the table's TOA5 field-name and units lines, as the
digital twin's station's replies do. The logger asks for the record after the last one in
``weather.dat``, so a restarted acquisition or a reconnected station fills the gap from the
station's memory and never writes a record twice. Requests go out every ``poll_interval_s``
seconds of the survey clock; a request without ``END`` or ``MORE`` within ``reply_timeout_s``
(wall seconds) counts as a missing reply and is repeated at the next interval.
"""

from __future__ import annotations

import csv
import math
import os
import time
from collections.abc import Callable

import numpy as np
import serial

from clearfast_gis.acquire.appendlog import AppendLog
from clearfast_gis.acquire.linelogger import EventSink, LineLogger
from clearfast_gis.acquire.ports import SERIAL_ERRORS, PortError, _reason
from clearfast_gis.errors import ClearfastError, InvalidInput
from clearfast_gis.survey.station_profiles import ColumnMap, StationProfile, map_columns
from clearfast_gis.survey.toa5 import COLUMNS, WeatherLog, toa5_text
from clearfast_gis.timeutil import format_utc, parse_utc


def _empty_log() -> WeatherLog:
    e = np.empty(0)
    return WeatherLog(e, e, e, e, e, e, e, e)


def toa5_header(station: str = "clearfast") -> str:
    """The four TOA5 header lines ``weather.dat`` starts with (CR LF line endings)."""
    return toa5_text(_empty_log(), station)


def toa5_record_line(time_s: float, record: int, values: dict[str, float]) -> str:
    """One TOA5 data line (CR LF ended) in the format of :func:`clearfast_gis.survey.write_toa5`.

    Parameters
    ----------
    time_s : float
        UTC epoch seconds of the record.
    record : int
        Record number.
    values : dict
        TOA5 column name -> value in the contract's units (NaN or absent = ``"NAN"``).
    """
    one = np.array([float(time_s)])
    attrs = {attr: np.array([values.get(col, math.nan)]) for col, (attr, _) in COLUMNS.items()}
    line = toa5_text(WeatherLog(time_s=one, **attrs)).split("\r\n")[4]
    ts, _, rest = line.split(",", 2)
    return f"{ts},{int(record)},{rest}\r\n"


def _float(text: str) -> float:
    t = text.strip().strip('"')
    if t.upper() in ("NAN", "", "-NAN", "NA"):
        return math.nan
    v = float(t)
    if math.isinf(v):
        raise ValueError("infinite")
    return v


class WeatherStationLogger(LineLogger):
    """Logs TOA5 records from a weather station to ``weather.dat``.

    Parameters
    ----------
    port : serial.SerialBase
        Open pyserial port.
    path : path
        ``<survey>/weather.dat``; appended to if it exists (it must then be a TOA5 file with
        the same columns).
    station : str
        Station name written in the TOA5 environment line of a new file.
    clock : callable
        UTC clock, epoch seconds: the survey clock (times the polls; no poll goes out while it
        raises :class:`~clearfast_gis.errors.ClearfastError`, i.e. before it has a time).
    fsync_interval_s : float
        Seconds between fsyncs.
    poll_interval_s : float, optional
        Poll the station (``GET <record>``) every so many seconds of ``clock``; None for a
        station that sends its records by itself.
    reply_timeout_s : float
        Wall seconds a poll waits for its ``END`` or ``MORE``.
    mono : callable
        Host monotonic clock, seconds (reply timeouts).
    reopen, retry_s, on_event
        As for :class:`~clearfast_gis.acquire.linelogger.LineLogger` (reconnection, events).
    profile : StationProfile, optional
        The station's profile: its column names and units, and the field names of a station
        that sends no header.

    Attributes
    ----------
    n_records, n_bad, n_duplicates : int
        Records written, lines that are not records, records received again (polling).
    n_unmapped : int
        Data lines refused because their columns could not be mapped by name (no header
        yet, or a header whose quantities or units are not known).
    n_polls, n_timeouts : int
        Requests sent and requests left without a complete reply.

    Raises
    ------
    InvalidInput
        When an existing ``path`` is not a TOA5 file with the expected columns.
    """

    kind = "weather"

    def __init__(self, port: serial.SerialBase, path: str | os.PathLike,
                 station: str = "clearfast", clock: Callable[[], float] = time.time,
                 fsync_interval_s: float = 5.0, poll_interval_s: float | None = None,
                 reply_timeout_s: float = 5.0, mono: Callable[[], float] = time.monotonic,
                 reopen: Callable[[], serial.SerialBase] | None = None, retry_s: float = 1.0,
                 on_event: EventSink | None = None,
                 profile: StationProfile | None = None) -> None:
        header = toa5_header(station)
        _check_existing(path, header)
        super().__init__(port, AppendLog(path, header.encode("ascii"), fsync_interval_s),
                         reopen=reopen, retry_s=retry_s, on_event=on_event)
        self._next_record = _next_record(self.log.read_existing())
        self.profile = profile
        self._columns: list[str] | None = list(profile.header) if profile and profile.header \
            else None
        self._units: list[str] = []
        self._map: dict[str, ColumnMap] | None = None
        self._why_unmapped = "no TOA5 field-name line from the station yet"
        self.n_unmapped = 0
        self._clock = clock
        self._mono = mono
        self.poll_interval_s = poll_interval_s
        self.reply_timeout_s = float(reply_timeout_s)
        self.n_records = 0
        self.n_bad = 0
        self.n_duplicates = 0
        self.n_polls = 0
        self.n_timeouts = 0
        self.last: dict[str, float] | None = None
        self._asked_at: float | None = None  # monotonic time of the unanswered request
        self._next_poll_s = -math.inf

    # -- polling ----------------------------------------------------------------------------

    def poll(self) -> int:
        """Send a due request (polled stations), then read and process what arrived."""
        if self.poll_interval_s is not None:
            self._request_if_due()
        return super().poll()

    def _request_if_due(self) -> None:
        if self._asked_at is not None:
            if self._mono() - self._asked_at <= self.reply_timeout_s:
                return
            self.n_timeouts += 1
            self._asked_at = None
            self.event("no reply", f"GET {self._next_record}: no END within "
                       f"{self.reply_timeout_s:g} s")
        try:
            now = self._clock()
        except ClearfastError:  # the survey clock has no time yet
            return
        interval = float(self.poll_interval_s)
        if now < self._next_poll_s - 2.0 * interval:  # the clock was set back
            self._next_poll_s = now
        if now < self._next_poll_s:
            return
        try:
            self.port.write(f"GET {self._next_record}\r\n".encode("ascii"))
        except SERIAL_ERRORS as exc:
            raise PortError(f"write failed ({_reason(exc)})", self.port_name) from None
        self.n_polls += 1
        self._asked_at = self._mono()
        self._next_poll_s = now + interval

    def on_reconnect(self) -> None:
        self._asked_at = None
        self._next_poll_s = -math.inf  # ask at once for what was missed

    def handle_lines(self, lines: list[bytes]) -> list[bytes]:
        out: list[bytes] = []
        for raw in lines:
            text = raw.decode("utf-8", "replace").strip()
            if not text:
                continue
            line = self._record(text)
            if line is not None:
                out.append(line.encode("ascii"))
        return out

    def _record(self, text: str) -> str | None:
        try:
            fields = next(csv.reader([text]))
        except (csv.Error, StopIteration):
            self.n_bad += 1
            return None
        first = fields[0].strip() if fields else ""
        if self.poll_interval_s is not None and first in ("END", "MORE") and len(fields) == 1:
            self._asked_at = None
            if first == "MORE":
                self._next_poll_s = -math.inf
            return None
        if first == "TIMESTAMP":
            if [f.strip() for f in fields] != self._columns:
                self._columns = [f.strip() for f in fields]
                self._units = []
                self._map = None
            return None
        if first == "TS":
            if [f.strip() for f in fields] != self._units:
                self._units = [f.strip() for f in fields]
                self._map = None
            return None
        if first in ("TOA5", ""):
            return None  # environment and processing lines of a TOA5 header
        try:
            parse_utc(first)
        except (ValueError, TypeError, OverflowError, OSError):
            self.n_bad += 1  # not a record (line noise, a reply of another kind)
            return None
        mapping = self._mapping()
        if mapping is None:
            self.n_unmapped += 1
            if self.n_unmapped == 1:
                self.event("unmapped", f"data line refused: {self._why_unmapped}; columns "
                           "are mapped by name only (a station without a header needs "
                           "\"header\" in its station profile)")
            return None
        pos = {name: i for i, name in enumerate(self._columns)}
        try:
            time_s = parse_utc(fields[pos["TIMESTAMP"]])
            values = {}
            for col, (attr, _) in COLUMNS.items():
                cm = mapping.get(attr)
                if cm is None:
                    continue
                values[col] = cm.scale * _float(fields[cm.index]) + cm.offset
            record = self._next_record
            if "RECORD" in pos and pos["RECORD"] < len(fields) and fields[pos["RECORD"]].strip():
                record = int(fields[pos["RECORD"]].strip().strip('"'))
        except (ValueError, KeyError, IndexError, OverflowError, OSError):
            self.n_bad += 1
            return None
        if self.poll_interval_s is not None and record < self._next_record:
            self.n_duplicates += 1
            return None
        self._next_record = record + 1
        self.n_records += 1
        self.last = {"time_s": time_s, **values}
        return toa5_record_line(time_s, record, values)

    def _mapping(self) -> dict[str, ColumnMap] | None:
        """Quantity -> column of the current header (None while it cannot be mapped)."""
        if self._map is None and self._columns is not None:
            try:
                self._map = map_columns(self._columns, self._units, self.port_name,
                                        self.profile)
            except InvalidInput as exc:
                self._why_unmapped = exc.message
        return self._map

    def status(self) -> dict:
        out = super().status()
        out.update(records=self.n_records, bad=self.n_bad, unmapped=self.n_unmapped)
        if self.poll_interval_s is not None:
            out.update(polls=self.n_polls, timeouts=self.n_timeouts,
                       duplicates=self.n_duplicates)
        if self.last is not None:
            out["last"] = {"time_utc": format_utc(self.last["time_s"], "seconds"),
                           **{k: (None if math.isnan(v) else v)
                              for k, v in self.last.items() if k != "time_s"}}
        return out

    def status_text(self) -> str:
        """Short status for a one-line display."""
        air = ""
        if self.last is not None and math.isfinite(self.last.get("AirTC_Avg", math.nan)):
            air = f" air {self.last['AirTC_Avg']:.1f} C"
        bad = f" ({self.n_bad} bad)" if self.n_bad else ""
        return f"weather {self.n_records} records{bad}{air}"


def _check_existing(path: str | os.PathLike, header: str) -> None:
    """Refuse to append to a non-empty file that is not our TOA5 table."""
    try:
        with open(path, "rb") as fh:
            head = fh.read(4096).decode("utf-8", "replace").splitlines()
    except FileNotFoundError:
        return
    except OSError as exc:
        raise InvalidInput(f"cannot read: {exc.strerror or exc}", str(path)) from None
    if not head:
        return
    names = header.splitlines()[1]
    if not head[0].startswith('"TOA5"'):
        raise InvalidInput("exists and is not a TOA5 file; not appending to it", str(path),
                           "line 1")
    if len(head) < 2 or head[1].strip() != names:
        raise InvalidInput(f"exists with other columns; expected {names}", str(path), "line 2")


def _next_record(content: bytes) -> int:
    """The record number after the last data line of a TOA5 file's content (0 if none)."""
    lines = [x for x in content.decode("utf-8", "replace").splitlines() if x.strip()][4:]
    for line in reversed(lines):
        fields = line.split(",")
        if len(fields) > 1 and fields[1].strip().lstrip("-").isdigit():
            return int(fields[1]) + 1
    return 0
