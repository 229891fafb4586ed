"""RTK-DGPS receiver logging: raw NMEA 0183 lines to ``gnss.nmea``, checksums, latest fix.

Every complete line received is appended to the raw log exactly as it arrived (bytes and line
ending kept; bad lines too, since the log is the receiver's record and
:func:`clearfast_gis.survey.read_nmea` skips and counts them the same way). Each line is also
checked: checksum errors and non-NMEA lines are counted, GGA sentences update the latest fix
(dated by the last RMC sentence, else by the host clock's date).
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable
from dataclasses import dataclass

import pynmea2
import serial

from clearfast_gis.acquire.appendlog import AppendLog
from clearfast_gis.acquire.linelogger import LineLogger
from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey.nmea import parse_nmea

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


def classify_sentence(text: str) -> tuple[str, pynmea2.NMEASentence | None]:
    """Check one NMEA line: ``("ok", msg)``, ``("bad_checksum", None)`` or ``("junk", None)``.

    Lines without a checksum count as bad checksums, as in
    :func:`clearfast_gis.survey.parse_nmea`.
    """
    line = text.strip()
    if not line.startswith("$"):
        return "junk", None
    try:
        return "ok", pynmea2.parse(line, check=True)
    except pynmea2.ChecksumError:
        return "bad_checksum", None
    except (pynmea2.ParseError, pynmea2.SentenceTypeError, ValueError, TypeError,
            AttributeError, IndexError):
        return "junk", None


class GnssLogger(LineLogger):
    """Logs a GNSS receiver's NMEA stream to ``gnss.nmea`` (append-only, raw).

    Parameters
    ----------
    port : serial.SerialBase
        Open pyserial port (device, pty or URL such as ``loop://``).
    path : path
        The raw log, normally ``<survey>/gnss.nmea``; appended to if it exists.
    clock : callable
        Host UTC clock, epoch seconds (dates GGA epochs before any RMC, stamps arrivals).
    fsync_interval_s : float
        Seconds between fsyncs of the log.

    Attributes
    ----------
    fix : GnssFix or None
        The latest GGA epoch.
    n_sentences, n_bad_checksum, n_unparseable : int
        Valid NMEA sentences, lines with a wrong or missing checksum, non-NMEA lines.
    """

    kind = "gnss"

    def __init__(self, port: serial.SerialBase, path: str | os.PathLike,
                 clock: Callable[[], float] = time.time, fsync_interval_s: float = 5.0) -> None:
        super().__init__(port, AppendLog(path, fsync_interval_s=fsync_interval_s))
        self._clock = clock
        self.fix: GnssFix | None = None
        self.n_sentences = 0
        self.n_bad_checksum = 0
        self.n_unparseable = 0
        self._last_rmc = ""

    def handle_lines(self, lines: list[bytes]) -> list[bytes]:
        for raw in lines:
            text = raw.decode("ascii", "replace").strip()
            if text:
                self._check(text)
        return lines

    def _check(self, text: str) -> None:
        verdict, msg = classify_sentence(text)
        if verdict == "bad_checksum":
            self.n_bad_checksum += 1
            return
        if verdict == "junk":
            self.n_unparseable += 1
            return
        self.n_sentences += 1
        if isinstance(msg, pynmea2.RMC):
            self._last_rmc = text
        elif isinstance(msg, pynmea2.GGA):
            now = self._clock()
            try:
                log = parse_nmea(text + "\n" + self._last_rmc, "gnss", fallback_date_s=now)
            except InvalidInput:
                self.n_unparseable += 1
                return
            if len(log) == 0:
                self.n_unparseable += 1
                return
            self.fix = GnssFix(
                time_s=float(log.time_s[0]), lat_deg=float(log.lat_deg[0]),
                lon_deg=float(log.lon_deg[0]), alt_m=float(log.alt_m[0]),
                fix_quality=int(log.fix_quality[0]), n_sats=int(log.n_sats[0]),
                hdop=float(log.hdop[0]), received_s=now)

    def status(self) -> dict:
        out = super().status()
        out.update(sentences=self.n_sentences, bad_checksum=self.n_bad_checksum,
                   unparseable=self.n_unparseable)
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
