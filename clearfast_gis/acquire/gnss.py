"""RTK-DGPS receiver logging: raw NMEA 0183 lines to ``gnss.nmea``, checksums, fix, UTC time.

Every complete line received is appended to the raw log exactly as it arrived (bytes and line
ending kept; bad lines too, since the log is the receiver's record and
:func:`clearfast_gis.survey.read_nmea` skips and counts them the same way). Each line is also
checked the way :func:`clearfast_gis.survey.parse_nmea` reads the log
(:mod:`clearfast_gis.survey.nmea_lines`: junk before ``$``, ``$$``, missing checksums):
checksum errors and non-NMEA lines are counted; valid RMC (status ``A``, two-digit years placed
around the host clock's year, not more than a year from it) and ZDA sentences give the
receiver's UTC time (passed on to
``on_time``, which disciplines the survey clock and may refuse a jump,
:class:`~clearfast_gis.acquire.clock.GnssClock`); GGA sentences update the latest fix (dated by
the last RMC or ZDA sentence, else by the host clock's date), and a change of fix quality
(RTK fixed to float, loss of the fix) is reported as an event.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable
from dataclasses import dataclass
from datetime import UTC, datetime

import pynmea2
import serial

from clearfast_gis.acquire.appendlog import AppendLog
from clearfast_gis.acquire.linelogger import EventSink, LineLogger
from clearfast_gis.survey.nmea_lines import (
    FIELD_ERRORS,
    classify_line,
    gga_fields,
    gga_has_time,
    sentence_time,
)
from clearfast_gis.timeutil import format_utc

#: half a day, seconds: a GGA time of day this far from the last dated one crossed midnight
_HALF_DAY_S = 43200.0

#: a receiver time farther than this from the host clock is implausible (a cold start's 1980
#: date, a GPS week rollover's 19.6 years), seconds; a laptop clock is minutes off, not a year
MAX_HOST_DISAGREEMENT_S = 366 * 86400.0

#: GGA fix quality -> short name for displays
FIX_NAMES = {0: "no fix", 1: "GPS", 2: "DGPS", 3: "PPS", 4: "RTK fixed", 5: "RTK float",
             6: "estimated", 7: "manual", 8: "simulation"}


@dataclass(frozen=True)
class GnssFix:
    """The latest GGA epoch.

    Attributes
    ----------
    time_s : float
        UTC epoch seconds of the fix (receiver time).
    lat_deg, lon_deg : float
        WGS84 degrees (NaN without a fix).
    alt_m : float
        Antenna altitude above mean sea level, metres (NaN without a fix).
    fix_quality : int
        GGA fix quality (4 RTK fixed, 5 RTK float, 1/2 GPS/DGPS, 0 none).
    n_sats : int
        Satellites in use.
    hdop : float
        Horizontal dilution of precision (NaN if absent).
    received_s : float
        Host clock (UTC epoch seconds) when the sentence arrived.
    """

    time_s: float
    lat_deg: float
    lon_deg: float
    alt_m: float
    fix_quality: int
    n_sats: int
    hdop: float
    received_s: float

    @property
    def fix_name(self) -> str:
        """Human name of the fix quality."""
        return FIX_NAMES.get(self.fix_quality, f"quality {self.fix_quality}")


def classify_sentence(text: str, checksums: str = "required"
                      ) -> tuple[str, pynmea2.NMEASentence | None]:
    """Check one NMEA line: ``("ok", msg)``, ``("bad_checksum", None)`` or ``("junk", None)``.

    Lines without a checksum count as bad checksums unless ``checksums="optional"``; the
    sentence is found as in :func:`clearfast_gis.survey.parse_nmea`.
    """
    verdict = classify_line(text, checksums)
    kind = {"no_checksum": "bad_checksum", "comment": "junk"}.get(verdict.kind, verdict.kind)
    return kind, verdict.msg


class GnssLogger(LineLogger):
    """Logs a GNSS receiver's NMEA stream to ``gnss.nmea`` (append-only, raw).

    Parameters
    ----------
    port : serial.SerialBase
        Open pyserial port (device, pty or URL such as ``loop://``).
    path : path
        The raw log, normally ``<survey>/gnss.nmea``; appended to if it exists.
    clock : callable
        Host UTC clock, epoch seconds (dates GGA epochs before any RMC or ZDA, stamps
        arrivals).
    fsync_interval_s : float
        Seconds between fsyncs of the log.
    on_time : callable, optional
        ``on_time(utc_s, mono_s)`` for every RMC or ZDA sentence: the receiver's UTC epoch
        seconds and the host's monotonic clock (``mono``) when its line arrived.
    mono : callable
        Host monotonic clock, seconds.
    reopen, retry_s, on_event
        As for :class:`~clearfast_gis.acquire.linelogger.LineLogger` (reconnection, events).

    Attributes
    ----------
    fix : GnssFix or None
        The latest GGA epoch.
    time_s : float or None
        UTC epoch seconds of the latest RMC or ZDA sentence.
    n_sentences, n_bad_checksum, n_unparseable : int
        Valid NMEA sentences, lines with a wrong or missing checksum, non-NMEA lines.
    n_fix_changes : int
        Changes of the fix quality (the first fix included).
    n_refused_times : int
        Time sentences not used: more than :data:`MAX_HOST_DISAGREEMENT_S` from the host
        clock, or refused by ``on_time`` (it returned False: a jump of the survey clock).
    """

    kind = "gnss"

    def __init__(self, port: serial.SerialBase, path: str | os.PathLike,
                 clock: Callable[[], float] = time.time, fsync_interval_s: float = 5.0,
                 on_time: Callable[[float, float], bool | None] | None = None,
                 mono: Callable[[], float] = time.monotonic,
                 reopen: Callable[[], serial.SerialBase] | None = None, retry_s: float = 1.0,
                 on_event: EventSink | None = None) -> None:
        super().__init__(port, AppendLog(path, fsync_interval_s=fsync_interval_s),
                         reopen=reopen, retry_s=retry_s, on_event=on_event)
        self._clock = clock
        self._mono = mono
        self.on_time = on_time
        self.fix: GnssFix | None = None
        self.time_s: float | None = None
        self.n_sentences = 0
        self.n_bad_checksum = 0
        self.n_unparseable = 0
        self.n_fix_changes = 0
        self.n_refused_times = 0
        self._dated: tuple[float, float] | None = None  # (tod_s, midnight_s) of the last date

    def handle_lines(self, lines: list[bytes]) -> list[bytes]:
        arrived = self._mono()
        for raw in lines:
            text = raw.decode("ascii", "replace").strip()
            if text:
                self._check(text, arrived)
        return lines

    def _check(self, text: str, arrived: float) -> None:
        verdict, msg = classify_sentence(text)
        if verdict == "bad_checksum":
            self.n_bad_checksum += 1
            return
        if verdict == "junk":
            self.n_unparseable += 1
            return
        try:
            pivot = datetime.fromtimestamp(self._clock(), tz=UTC).year
            when = sentence_time(msg, pivot)
            gga = gga_fields(msg) if isinstance(msg, pynmea2.GGA) and gga_has_time(msg) \
                else None
        except FIELD_ERRORS:
            self.n_unparseable += 1
            return
        self.n_sentences += 1
        if when is not None:
            if abs(when[0] + when[1] - self._clock()) > MAX_HOST_DISAGREEMENT_S:
                self.n_refused_times += 1  # a cold-start or week-rollover date
                if self.n_refused_times == 1:
                    self.event("time refused", f"receiver date "
                               f"{format_utc(when[0] + when[1], 'seconds')} is more than a year "
                               "from the host clock")
                return
            if self.on_time is not None and self.on_time(when[0] + when[1], arrived) is False:
                self.n_refused_times += 1  # the survey clock refused a jump
                return
            self._dated = when
            self.time_s = when[0] + when[1]
        elif gga is not None:
            self._update_fix(*gga)

    def _midnight_of(self, tod_s: float, now_s: float) -> float:
        """Epoch second of the midnight of a GGA time of day: the last RMC/ZDA date, rolled
        over midnight, else the host clock's date."""
        if self._dated is None:
            return math.floor(now_s / 86400.0) * 86400.0
        last_tod, midnight = self._dated
        if tod_s < last_tod - _HALF_DAY_S:
            return midnight + 86400.0
        if tod_s > last_tod + _HALF_DAY_S:
            return midnight - 86400.0
        return midnight

    def _update_fix(self, tod_s: float, payload: tuple) -> None:
        now = self._clock()
        lat, lon, alt, quality, n_sats, hdop = payload
        old = self.fix
        self.fix = GnssFix(time_s=self._midnight_of(tod_s, now) + tod_s, lat_deg=lat,
                           lon_deg=lon, alt_m=alt, fix_quality=int(quality), n_sats=int(n_sats),
                           hdop=hdop, received_s=now)
        if old is None or old.fix_quality != self.fix.fix_quality:
            self.n_fix_changes += 1
            before = "" if old is None else f"{old.fix_name} -> "
            self.event("fix", f"{before}{self.fix.fix_name} at "
                       f"{format_utc(self.fix.time_s, 'seconds')[11:19]} UTC")

    def status(self) -> dict:
        out = super().status()
        out.update(sentences=self.n_sentences, bad_checksum=self.n_bad_checksum,
                   unparseable=self.n_unparseable, fix_changes=self.n_fix_changes,
                   refused_times=self.n_refused_times,
                   time_utc=None if self.time_s is None else format_utc(self.time_s))
        f = self.fix
        if f is not None:
            out["fix"] = {"quality": f.fix_quality, "name": f.fix_name, "n_sats": f.n_sats,
                          "lat_deg": _finite(f.lat_deg), "lon_deg": _finite(f.lon_deg),
                          "alt_m": _finite(f.alt_m), "hdop": _finite(f.hdop),
                          "age_s": round(self._clock() - f.received_s, 1)}
        return out

    def status_text(self) -> str:
        """Short status for a one-line display."""
        f = self.fix
        fix = "no data" if f is None else f"{f.fix_name} {f.n_sats} sats"
        bad = f" ({self.n_bad_checksum} bad)" if self.n_bad_checksum else ""
        return f"gnss {self.n_lines_in} lines{bad} {fix}"


def _finite(v: float) -> float | None:
    return None if not math.isfinite(v) else round(v, 9)
