"""NMEA 0183 GNSS logs: GGA (position, fix quality), RMC and ZDA (date and time) sentences.

Parsing uses pynmea2 with checksum verification; lines with a wrong checksum are counted and
skipped, as are lines that are not NMEA. Each GGA sentence gives one epoch; its date comes from
the RMC or ZDA sentence of the same epoch, else from the last known date (rolling over
midnight), else from a fallback date (the survey start).
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from datetime import UTC, datetime

import numpy as np
import pynmea2

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey._text import read_text

#: GGA fix quality codes
FIX_NONE, FIX_GPS, FIX_DGPS, FIX_RTK_FIXED, FIX_RTK_FLOAT = 0, 1, 2, 4, 5


def nmea_checksum(body: str) -> str:
    """The two hex digits of the NMEA checksum of ``body`` (text between ``$`` and ``*``)."""
    c = 0
    for ch in body.encode("ascii"):
        c ^= ch
    return f"{c:02X}"


def _sentence(body: str) -> str:
    return f"${body}*{nmea_checksum(body)}"


def _hhmmss(time_s: float) -> str:
    ms = int(round((float(time_s) % 86400.0) * 1000.0)) % 86_400_000
    h, rem = divmod(ms, 3_600_000)
    m, rem = divmod(rem, 60_000)
    s, frac = divmod(rem, 1000)
    return f"{h:02d}{m:02d}{s:02d}.{frac:03d}"


def _angle_field(value_deg: float, degree_digits: int, positive: str, negative: str
                 ) -> tuple[str, str]:
    """An angle as NMEA ``(d)ddmm.mmmmmmm`` and its hemisphere letter ("" when not finite)."""
    if not math.isfinite(value_deg):
        return "", ""
    a = abs(value_deg)
    d = int(a)
    minutes = (a - d) * 60.0
    if round(minutes, 7) >= 60.0:
        d, minutes = d + 1, 0.0
    return f"{d:0{degree_digits}d}{minutes:010.7f}", (positive if value_deg >= 0 else negative)


def _lat_field(lat_deg: float) -> tuple[str, str]:
    return _angle_field(lat_deg, 2, "N", "S")


def _lon_field(lon_deg: float) -> tuple[str, str]:
    return _angle_field(lon_deg, 3, "E", "W")


def gga_sentence(time_s: float, lat_deg: float, lon_deg: float, alt_m: float, quality: int,
                 n_sats: int, hdop: float, geoid_sep_m: float = 0.0, talker: str = "GP") -> str:
    """A ``$xxGGA`` sentence with a correct checksum (no line ending).

    Parameters
    ----------
    time_s : float
        UTC epoch seconds (only the time of day is written, to the millisecond).
    lat_deg, lon_deg : float
        WGS84 latitude and longitude in degrees (NaN writes empty fields, as for no fix).
    alt_m : float
        Antenna altitude above mean sea level, metres.
    quality : int
        Fix quality (0 none, 1 GPS, 2 DGPS, 4 RTK fixed, 5 RTK float).
    n_sats : int
        Satellites in use.
    hdop : float
        Horizontal dilution of precision.
    geoid_sep_m : float
        Geoid separation, metres.
    talker : str
        Talker identifier (``GP``, ``GN``...).
    """
    lat, ns = _lat_field(lat_deg)
    lon, ew = _lon_field(lon_deg)
    alt = f"{alt_m:.3f}" if math.isfinite(alt_m) else ""
    body = (f"{talker}GGA,{_hhmmss(time_s)},{lat},{ns},{lon},{ew},{int(quality)},"
            f"{int(n_sats):02d},{hdop:.2f},{alt},M,{geoid_sep_m:.3f},M,,")
    return _sentence(body)


def rmc_sentence(time_s: float, lat_deg: float, lon_deg: float, speed_kn: float = 0.0,
                 course_deg: float = 0.0, valid: bool = True, talker: str = "GP") -> str:
    """A ``$xxRMC`` sentence (time, date, position) with a correct checksum.

    Parameters
    ----------
    time_s : float
        UTC epoch seconds (time of day and date are written).
    lat_deg, lon_deg : float
        WGS84 degrees (NaN writes empty fields).
    speed_kn : float
        Speed over ground, knots.
    course_deg : float
        Course over ground, degrees true.
    valid : bool
        Status ``A`` (valid) or ``V`` (void).
    talker : str
        Talker identifier.
    """
    lat, ns = _lat_field(lat_deg)
    lon, ew = _lon_field(lon_deg)
    day = datetime.fromtimestamp(math.floor(round(float(time_s), 3)), tz=UTC)
    mode = "D" if valid else "N"
    body = (f"{talker}RMC,{_hhmmss(time_s)},{'A' if valid else 'V'},{lat},{ns},{lon},{ew},"
            f"{speed_kn:.2f},{course_deg:.1f},{day:%d%m%y},,,{mode}")
    return _sentence(body)


def zda_sentence(time_s: float, talker: str = "GP") -> str:
    """A ``$xxZDA`` sentence (UTC time of day, day, month, four-digit year, zone 00:00) with a
    correct checksum (no line ending).

    Parameters
    ----------
    time_s : float
        UTC epoch seconds (written to the millisecond).
    talker : str
        Talker identifier.
    """
    day = datetime.fromtimestamp(math.floor(round(float(time_s), 3)), tz=UTC)
    return _sentence(f"{talker}ZDA,{_hhmmss(time_s)},{day:%d},{day:%m},{day:%Y},00,00")


@dataclass(frozen=True)
class GnssLog:
    """GNSS epochs from GGA sentences (arrays of length N, in file order).

    Attributes
    ----------
    time_s : float64 (N,)
        UTC epoch seconds.
    lat_deg, lon_deg : float64 (N,)
        WGS84 degrees; NaN without a fix.
    alt_m : float64 (N,)
        GGA antenna altitude above mean sea level, metres (NaN without a fix).
    fix_quality : int8 (N,)
        GGA fix quality (4 = RTK fixed, 5 = RTK float, 1/2 = GPS/DGPS, 0 = none).
    n_sats : int16 (N,)
        Satellites in use.
    hdop : float64 (N,)
        Horizontal dilution of precision (NaN if absent).
    n_lines : int
        Non-blank lines in the file.
    bad_checksum_lines, unparseable_lines : tuple of int
        1-based line numbers skipped for a wrong checksum or for not being NMEA.
    """

    time_s: np.ndarray
    lat_deg: np.ndarray
    lon_deg: np.ndarray
    alt_m: np.ndarray
    fix_quality: np.ndarray
    n_sats: np.ndarray
    hdop: np.ndarray
    n_lines: int = 0
    bad_checksum_lines: tuple[int, ...] = field(default=())
    unparseable_lines: tuple[int, ...] = field(default=())

    def __len__(self) -> int:
        return int(self.time_s.shape[0])

    @property
    def n_bad_checksum(self) -> int:
        """Number of lines skipped for a wrong checksum."""
        return len(self.bad_checksum_lines)

    @property
    def n_unparseable(self) -> int:
        """Number of lines skipped for not being NMEA."""
        return len(self.unparseable_lines)

    def fix_counts(self) -> dict[int, int]:
        """Number of epochs per fix quality."""
        q, n = np.unique(self.fix_quality, return_counts=True)
        return {int(a): int(b) for a, b in zip(q, n, strict=True)}


_TIME = re.compile(r"^([01]\d|2[0-3])([0-5]\d)([0-5]\d|60)(\.\d{1,9})?$")
_DATE = re.compile(r"^(\d\d)(\d\d)(\d\d)$")


def _tod_field(text: str) -> float:
    """``hhmmss[.sss]`` to seconds of the day; ValueError if malformed."""
    m = _TIME.match(text)
    if not m:
        raise ValueError(f"bad time {text!r}")
    frac = float(m.group(4)) if m.group(4) else 0.0
    return int(m.group(1)) * 3600.0 + int(m.group(2)) * 60.0 + int(m.group(3)) + frac


def _date_field(text: str) -> float:
    """RMC ``ddmmyy`` to the epoch second of that day's midnight (years 2000-2099)."""
    m = _DATE.match(text)
    if not m:
        raise ValueError(f"bad date {text!r}")
    d, mo, y = (int(g) for g in m.groups())
    return datetime(2000 + y, mo, d, tzinfo=UTC).timestamp()


def _zda_date(day: str, month: str, year: str) -> float:
    """ZDA day, month and four-digit year fields to the epoch second of that day's midnight."""
    if not (day.isdigit() and month.isdigit() and len(year) == 4 and year.isdigit()):
        raise ValueError(f"bad date {day!r} {month!r} {year!r}")
    return datetime(int(year), int(month), int(day), tzinfo=UTC).timestamp()


def sentence_time(msg: pynmea2.NMEASentence) -> tuple[float, float] | None:
    """Time of day and date of an RMC or ZDA sentence: ``(tod_s, midnight_s)``.

    ``tod_s`` is seconds since midnight UTC, ``midnight_s`` the epoch second of that day's
    midnight (so the UTC epoch is their sum). None for other sentences.

    Raises
    ------
    ValueError
        For an RMC or ZDA sentence with a malformed time or date.
    """
    d = msg.data
    if isinstance(msg, pynmea2.RMC):
        return _tod_field(d[0]), _date_field(d[8])
    if isinstance(msg, pynmea2.ZDA):
        return _tod_field(d[0]), _zda_date(d[1], d[2], d[3])
    return None


def gga_fields(msg: pynmea2.GGA) -> tuple[float, tuple]:
    """The epoch of a GGA sentence: ``(tod_s, (lat_deg, lon_deg, alt_m, quality, n_sats,
    hdop))``; position NaN and quality 0 when the epoch has no usable fix.

    Raises
    ------
    ValueError
        For a malformed time, fix quality or satellite count.
    """
    d = msg.data
    tod = _tod_field(d[0])
    q = int(d[5]) if d[5] else 0
    if not 0 <= q <= 9:
        raise ValueError("fix quality")
    lat = _coord(d[1], d[2], 2, 90.0)
    lon = _coord(d[3], d[4], 3, 180.0)
    alt = _num(d[8])
    if q == 0 or math.isnan(lat) or math.isnan(lon):
        lat = lon = alt = math.nan  # no usable fix in this epoch
        q = 0
    ns = int(d[6]) if d[6] else 0
    if not 0 <= ns <= 999:
        raise ValueError("satellites")
    return tod, (lat, lon, alt, q, ns, _num(d[7]))


#: parse errors of a sentence pynmea2 accepted but whose fields are malformed
FIELD_ERRORS = (ValueError, TypeError, AttributeError, IndexError, OverflowError)


def _num(text: str) -> float:
    try:
        v = float(text)
    except (TypeError, ValueError):
        return math.nan
    return v if math.isfinite(v) else math.nan


def _coord(value: str, hemi: str, deg_digits: int, limit: float) -> float:
    if not value or hemi not in ("N", "S", "E", "W"):
        return math.nan
    try:
        d = int(value[:deg_digits])
        m = float(value[deg_digits:])
    except ValueError:
        return math.nan
    if not (0.0 <= m < 60.0) or value[:deg_digits].strip() != value[:deg_digits]:
        return math.nan
    v = d + m / 60.0
    if v > limit:
        return math.nan
    return -v if hemi in ("S", "W") else v


"""The last logs parsed (a survey's log is parsed by the validation, then by the chain)."""


def parse_nmea(text: str, label: str = "gnss.nmea", fallback_date_s: float | None = None
               ) -> GnssLog:
    """Parse NMEA 0183 text into a :class:`GnssLog`.

    Validating a survey parses its logs once; the chain takes them from the validation
    report (:attr:`clearfast_gis.survey.validate.ValidationReport.logs`).

    Parameters
    ----------
    text : str
        The log's content.
    label : str
        File name used in error messages.
    fallback_date_s : float, optional
        Any UTC epoch second of the first day of the log (the survey start); used for GGA
        epochs before the first RMC or ZDA sentence when none follows in the same epoch.

    Raises
    ------
    InvalidInput
        When the text holds no GGA sentence, or epochs cannot be dated.
    """
    records: list[tuple] = []  # (kind, tod_s, payload)
    bad_cs: list[int] = []
    junk: list[int] = []
    n_lines = 0
    # lines end at LF (CR LF on the wire), as the logger splits them: control characters of
    # line noise (CR, FF, VT, ...) stay inside their line
    for lineno, raw in enumerate(text.split("\n"), start=1):
        line = raw.strip()
        if not line:
            continue
        n_lines += 1
        if not line.startswith("$"):
            junk.append(lineno)
            continue
        try:
            msg = pynmea2.parse(line, check=True)
        except pynmea2.ChecksumError:
            bad_cs.append(lineno)
            continue
        except (pynmea2.ParseError, pynmea2.SentenceTypeError, ValueError, TypeError,
                AttributeError, IndexError):
            junk.append(lineno)
            continue
        try:
            if isinstance(msg, pynmea2.GGA):
                tod, payload = gga_fields(msg)
                records.append(("GGA", tod, payload))
            elif (when := sentence_time(msg)) is not None:
                records.append(("DATE", *when))
        except FIELD_ERRORS:
            junk.append(lineno)
            continue
    ggas = [i for i, r in enumerate(records) if r[0] == "GGA"]
    if not ggas:
        raise InvalidInput("no GGA sentence with a time (not an NMEA GNSS log?)", label)

    first_dated = next((r for r in records if r[0] == "DATE"), None)
    cols: list[tuple] = []
    day_s: float | None = None
    last_tod = None
    for i in ggas:
        kind, tod, payload = records[i]
        own = None
        for j in (i + 1, i - 1, i + 2, i - 2):
            if 0 <= j < len(records) and records[j][0] == "DATE" and \
                    abs(records[j][1] - tod) < 1e-3:
                own = records[j][2]
                break
        if own is not None:
            day_s = own
        elif day_s is not None:
            if last_tod is not None and tod < last_tod - 43200.0:
                day_s += 86400.0
        elif first_dated is not None:
            day_s = first_dated[2] - (86400.0 if tod > first_dated[1] + 43200.0 else 0.0)
        elif fallback_date_s is not None and math.isfinite(fallback_date_s):
            day_s = math.floor(fallback_date_s / 86400.0) * 86400.0
        else:
            raise InvalidInput("no RMC or ZDA sentence gives the date and no survey start date "
                               "is known", label)
        last_tod = tod
        cols.append((day_s + tod, *payload))
    arr = np.array(cols, dtype=np.float64).reshape(-1, 7)
    return GnssLog(
        time_s=arr[:, 0].copy(), lat_deg=arr[:, 1].copy(), lon_deg=arr[:, 2].copy(),
        alt_m=arr[:, 3].copy(), fix_quality=arr[:, 4].astype(np.int8),
        n_sats=arr[:, 5].astype(np.int16), hdop=arr[:, 6].copy(), n_lines=n_lines,
        bad_checksum_lines=tuple(bad_cs), unparseable_lines=tuple(junk),
    )


def read_nmea(path: str | os.PathLike, fallback_date_s: float | None = None,
              label: str | None = None) -> GnssLog:
    """Read an NMEA 0183 log file (see :func:`parse_nmea`); bytes that are not text (line
    noise recorded by the logger) make their line unparseable, not the file unreadable."""
    label = str(path) if label is None else label
    return parse_nmea(read_text(path, label, errors="replace"), label, fallback_date_s)


def gnss_sentences(log: GnssLog, talker: str = "GP") -> list[str]:
    """GGA and RMC sentences (in that order) for every epoch of ``log``."""
    out: list[str] = []
    for k in range(len(log)):
        t = float(log.time_s[k])
        lat, lon = float(log.lat_deg[k]), float(log.lon_deg[k])
        q = int(log.fix_quality[k])
        out.append(gga_sentence(t, lat, lon, float(log.alt_m[k]), q, int(log.n_sats[k]),
                                float(log.hdop[k]) if math.isfinite(log.hdop[k]) else 99.99,
                                talker=talker))
        out.append(rmc_sentence(t, lat, lon, valid=q > 0, talker=talker))
    return out


def write_nmea(path: str | os.PathLike, sentences: Iterable[str] | GnssLog) -> os.PathLike:
    """Write NMEA sentences (or a whole :class:`GnssLog` as GGA+RMC) atomically, CRLF lines."""
    lines = gnss_sentences(sentences) if isinstance(sentences, GnssLog) else list(sentences)
    return write_text(path, "".join(s + "\r\n" for s in lines))
