"""One NMEA 0183 line as real receivers write it: sentence start, checksum verdict, time fields.

A receiver's raw log is not always one clean ``$...*hh`` sentence per CR LF line:

- binary bytes may precede the sentence on the same line (receivers that mix a binary
  protocol with NMEA, e.g. the Quectel L76K), or two sentences run together when a line end
  was lost: the *last* sentence start on the line is taken;
- some receivers start every line with ``$$`` (ST Teseo): the sentence starts at the last
  ``$`` followed by an address field;
- some loggers end lines with CR alone;
- some receivers send no checksum at all (accepted only on request, ``checksums="optional"``);
- capture tools (gpsd's regression logs, many loggers) write ``#`` comment lines, which may
  quote a sentence as an example: a line that starts with ``#`` followed by white space (or
  nothing) is a comment, never a sentence (a ``#`` byte glued to a sentence is binary junk).

Time fields: ``hhmmss[.s]`` with the leap second ``23:59:60`` (placed in the last
millisecond of the day, so that UTC epoch seconds stay increasing); RMC dates ``ddmmyy``
with the century chosen around a pivot year; void RMC (status ``V``) never dates anything.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from datetime import UTC, datetime

import pynmea2

#: GGA fix qualities that are position fixes: GPS, DGPS, PPS, RTK fixed, RTK float. Dead
#: reckoning (6), manual input (7) and simulator (8) are not measurements of the antenna.
USABLE_FIX_QUALITIES = (1, 2, 3, 4, 5)

#: accepted values of the ``checksums`` option of the NMEA readers
CHECKSUM_MODES = ("required", "optional")

#: the last sentence start of a line: ``$`` then an address field (talker + type, or a
#: proprietary ``P...``) and a comma, with no further ``$`` after it
_SENTENCE = re.compile(r"\$([A-Z][A-Z0-9]{2,19},[^$]*)$")
_TIME = re.compile(r"^([01]\d|2[0-3])([0-5]\d)([0-5]\d|60)(\.\d{1,9})?$")
_DATE = re.compile(r"^(\d\d)(\d\d)(\d\d)$")

#: a receiver's own 23:59:60 is placed in the last millisecond of 23:59:59
_LEAP_START_S = 86399.999
_LEAP_SPAN_S = 0.000999

#: parse errors of a sentence pynmea2 accepted but whose fields are malformed
FIELD_ERRORS = (ValueError, TypeError, AttributeError, IndexError, OverflowError)


def split_lines(text: str) -> list[str]:
    """Lines of a raw log: split at LF (CR LF on the wire), or at CR when the log has no LF
    at all (loggers that end lines with CR alone). With LF line ends, a stray CR of line
    noise stays inside its line, so line numbers are those of a text editor."""
    return text.split("\n") if "\n" in text else text.split("\r")


_COMMENT = re.compile(r"#(\s|$)")


@dataclass(frozen=True)
class LineVerdict:
    """What one raw line holds.

    Attributes
    ----------
    kind : str
        ``"ok"`` (a sentence pynmea2 parsed), ``"bad_checksum"`` (checksum present and
        wrong), ``"no_checksum"`` (no ``*hh`` while checksums are required), ``"junk"``
        (no sentence, or one pynmea2 cannot parse), ``"comment"`` (a ``#`` line).
    msg : pynmea2.NMEASentence or None
        The parsed sentence when ``kind == "ok"``.
    prefixed : bool
        Bytes other than ``$`` preceded the sentence on the line (skipped).
    sentence_type : str
        The sentence's type (``GGA``, ``RMC``...; last three letters of the address field)
        when a sentence start was found, else ``""``.
    """

    kind: str
    msg: pynmea2.NMEASentence | None = None
    prefixed: bool = False
    sentence_type: str = ""


def classify_line(line: str, checksums: str = "required") -> LineVerdict:
    """Find and check the NMEA sentence of one raw line (see module docstring).

    Parameters
    ----------
    line : str
        One line without its line ending (surrounding white space is ignored).
    checksums : {"required", "optional"}
        Whether a sentence without ``*hh`` is refused (``"no_checksum"``) or parsed. A
        checksum that is present is always verified.
    """
    text = line.strip()
    if _COMMENT.match(text):
        return LineVerdict("comment")
    m = _SENTENCE.search(text)
    if m is None:
        return LineVerdict("junk")
    prefixed = bool(text[:m.start()].strip("$"))
    sentence = "$" + m.group(1)
    kind = m.group(1).split(",", 1)[0][-3:]
    has_checksum = re.search(r"\*[0-9A-Fa-f]{2}$", sentence) is not None
    if not has_checksum and checksums == "required":
        return LineVerdict("no_checksum", None, prefixed, kind)
    try:
        msg = pynmea2.parse(sentence, check=False)
    except pynmea2.ChecksumError:
        return LineVerdict("bad_checksum", None, prefixed, kind)
    except (pynmea2.ParseError, pynmea2.SentenceTypeError, ValueError, TypeError,
            AttributeError, IndexError):
        return LineVerdict("junk", None, prefixed, kind)
    return LineVerdict("ok", msg, prefixed, kind)


def tod_field(text: str) -> float:
    """``hhmmss[.sss]`` to seconds of the day; the leap second ``235960[.s]`` lies in the
    last millisecond of the day (UTC epoch seconds have no 61st second). ValueError if
    malformed (also for a second 60 at any other minute)."""
    m = _TIME.match(text)
    if not m:
        raise ValueError(f"bad time {text!r}")
    frac = float(m.group(4)) if m.group(4) else 0.0
    h, mi, s = int(m.group(1)), int(m.group(2)), int(m.group(3))
    if s == 60:
        if (h, mi) != (23, 59):
            raise ValueError(f"bad time {text!r} (a leap second is 23:59:60)")
        return _LEAP_START_S + frac * _LEAP_SPAN_S
    return h * 3600.0 + mi * 60.0 + s + frac


def century_year(yy: int, pivot_year: int | None) -> int:
    """The four-digit year of a two-digit RMC year: the one within 50 years of
    ``pivot_year`` (the survey's own year), or 2000-2099 without a pivot."""
    if pivot_year is None:
        return 2000 + yy
    base = pivot_year - pivot_year % 100
    candidates = (base - 100 + yy, base + yy, base + 100 + yy)
    return min(candidates, key=lambda y: (abs(y - pivot_year), y))


def date_field(text: str, pivot_year: int | None = None) -> float:
    """RMC ``ddmmyy`` to the epoch second of that day's midnight (century: see
    :func:`century_year`)."""
    m = _DATE.match(text)
    if not m:
        raise ValueError(f"bad date {text!r}")
    d, mo, y = (int(g) for g in m.groups())
    return datetime(century_year(y, pivot_year), mo, d, tzinfo=UTC).timestamp()


def zda_date(day: str, month: str, year: str) -> float:
    """ZDA day, month and four-digit year fields to the epoch second of that day's midnight."""
    if not (day.isdigit() and month.isdigit() and len(year) == 4 and year.isdigit()):
        raise ValueError(f"bad date {day!r} {month!r} {year!r}")
    return datetime(int(year), int(month), int(day), tzinfo=UTC).timestamp()


def is_void_rmc(msg: pynmea2.NMEASentence) -> bool:
    """True for an RMC sentence whose status is not ``A`` (void: the receiver has no valid
    fix, and its date may be a cold start's default such as 1980-01-05)."""
    return isinstance(msg, pynmea2.RMC) and msg.data[1].strip().upper() != "A"


def sentence_time(msg: pynmea2.NMEASentence, pivot_year: int | None = None
                  ) -> tuple[float, float] | None:
    """Time of day and date of a valid RMC or a ZDA sentence: ``(tod_s, midnight_s)``.

    ``tod_s`` is seconds since midnight UTC, ``midnight_s`` the epoch second of that day's
    midnight (so the UTC epoch is their sum). None for other sentences and for a void RMC.

    Parameters
    ----------
    msg : pynmea2.NMEASentence
    pivot_year : int, optional
        Year the two-digit RMC years are placed around (the survey's year).

    Raises
    ------
    ValueError
        For an RMC or ZDA sentence with a malformed time or date.
    """
    d = msg.data
    if isinstance(msg, pynmea2.RMC):
        if is_void_rmc(msg):
            return None
        return tod_field(d[0]), date_field(d[8], pivot_year)
    if isinstance(msg, pynmea2.ZDA):
        return tod_field(d[0]), zda_date(d[1], d[2], d[3])
    return None


def gga_has_time(msg: pynmea2.GGA) -> bool:
    """False for a GGA with an empty time field (a receiver before its first fix)."""
    return bool(msg.data[0].strip())


def gga_fields(msg: pynmea2.GGA) -> tuple[float, tuple]:
    """The epoch of a GGA sentence: ``(tod_s, (lat_deg, lon_deg, alt_m, quality, n_sats,
    hdop))``. Position NaN when the epoch has no usable fix: quality 0, or a quality that is
    not a measurement (6 dead reckoning, 7 manual, 8 simulator: kept as reported, position
    NaN), or missing coordinates (quality then 0).

    Raises
    ------
    ValueError
        For a malformed time, fix quality or satellite count.
    """
    d = msg.data
    tod = tod_field(d[0])
    q = int(d[5]) if d[5] else 0
    if not 0 <= q <= 9:
        raise ValueError("fix quality")
    lat = _coord(d[1], d[2], 2, 90.0)
    lon = _coord(d[3], d[4], 3, 180.0)
    alt = _num(d[8])
    if q not in USABLE_FIX_QUALITIES or math.isnan(lat) or math.isnan(lon):
        lat = lon = alt = math.nan  # no usable fix in this epoch
        if q in USABLE_FIX_QUALITIES:
            q = 0
    ns = int(d[6]) if d[6] else 0
    if not 0 <= ns <= 999:
        raise ValueError("satellites")
    return tod, (lat, lon, alt, q, ns, _num(d[7]))


#: precision rank of the fix qualities, best first, for choosing among the GGA sentences of
#: one epoch (one per constellation on some receivers)
_FIX_RANK = {4: 0, 5: 1, 2: 2, 3: 3, 1: 4}


def fix_rank(quality: int, n_sats: int) -> tuple[int, int]:
    """Sort key of a GGA epoch, smaller is better: fix precision, then more satellites."""
    return _FIX_RANK.get(int(quality), 9), -int(n_sats)


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
