"""NMEA 0183 GNSS logs: GGA (position, fix quality), RMC and ZDA (date and time) sentences.

Parsing uses pynmea2 with checksum verification (line handling of real receivers in
:mod:`clearfast_gis.survey.nmea_lines`); lines with a wrong or missing checksum are counted and
skipped, as are lines that are not NMEA. The GGA sentences of one time (one per constellation
on some receivers) give one epoch, the best fix; its date comes from the valid RMC or ZDA
sentence of the same epoch, else from the last known date (rolling over midnight), else from a
fallback date (the survey start).
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from datetime import UTC, datetime

import numpy as np
import pynmea2

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey._text import read_text
from clearfast_gis.survey.nmea_lines import (
    CHECKSUM_MODES,
    FIELD_ERRORS,
    USABLE_FIX_QUALITIES,
    classify_line,
    fix_rank,
    gga_fields,
    gga_has_time,
    is_void_rmc,
    sentence_time,
    split_lines,
)

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
        GGA fix quality (4 = RTK fixed, 5 = RTK float, 1/2/3 = GPS/DGPS/PPS, 0 = none;
        6/7/8 = dead reckoning/manual/simulator are kept as reported, with NaN position).
    n_sats : int16 (N,)
        Satellites in use.
    hdop : float64 (N,)
        Horizontal dilution of precision (NaN if absent).
    n_lines : int
        Non-blank lines in the file.
    bad_checksum_lines, unparseable_lines : tuple of int
        1-based line numbers skipped for a wrong checksum or for not being NMEA.
    no_checksum_lines : tuple of int
        Lines skipped for having no checksum (while checksums are required).
    untimed_gga_lines : tuple of int
        GGA sentences with an empty time field (a receiver before its first fix), skipped.
    void_rmc_lines : tuple of int
        RMC sentences with status V (void), not used for dating.
    implausible_date_lines : tuple of int
        RMC/ZDA sentences dated too far from the survey start, not used for dating.
    prefixed_lines : tuple of int
        Lines whose sentence was preceded by other bytes (skipped; the sentence was read).
    merged_epochs : int
        GGA sentences merged into an epoch of the same time (one per constellation).
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
    no_checksum_lines: tuple[int, ...] = field(default=())
    untimed_gga_lines: tuple[int, ...] = field(default=())
    void_rmc_lines: tuple[int, ...] = field(default=())
    implausible_date_lines: tuple[int, ...] = field(default=())
    prefixed_lines: tuple[int, ...] = field(default=())
    merged_epochs: int = 0

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

    @property
    def usable(self) -> np.ndarray:
        """True for epochs with a position fix (quality 1-5 and finite coordinates)."""
        return np.isin(self.fix_quality, USABLE_FIX_QUALITIES) & np.isfinite(self.lat_deg)

    def fix_counts(self) -> dict[int, int]:
        """Number of epochs per fix quality."""
        q, n = np.unique(self.fix_quality, return_counts=True)
        return {int(a): int(b) for a, b in zip(q, n, strict=True)}


#: an RMC or ZDA date farther than this from the survey's own start is refused (a receiver's
#: cold-start or week-rollover date), seconds
MAX_DATE_OFFSET_S = 7 * 86400.0

#: GGA sentences whose times differ by less than this are one epoch, seconds
SAME_EPOCH_S = 1e-3

_HALF_DAY_S = 43200.0


def parse_nmea(text: str, label: str = "gnss.nmea", fallback_date_s: float | None = None,
               checksums: str = "required") -> GnssLog:
    """Parse NMEA 0183 text into a :class:`GnssLog`.

    What real receivers write is accepted (:mod:`clearfast_gis.survey.nmea_lines`): junk
    before a sentence, ``$$`` starts, CR-only line ends, one GGA per constellation per epoch
    (merged into one epoch keeping the best fix), void RMC (never used for dating), leap
    seconds. Validating a survey parses its logs once; the chain takes them from the
    validation report (:attr:`clearfast_gis.survey.validate.ValidationReport.logs`).

    Parameters
    ----------
    text : str
        The log's content.
    label : str
        File name used in error messages.
    fallback_date_s : float, optional
        Any UTC epoch second of the first day of the log (the survey start); used for GGA
        epochs before the first RMC or ZDA sentence when none follows in the same epoch, as
        the pivot of two-digit RMC years, and to refuse dates more than
        :data:`MAX_DATE_OFFSET_S` away from it.
    checksums : {"required", "optional"}
        ``"optional"`` accepts sentences without a checksum (receivers that send none);
        present checksums are always verified.

    Raises
    ------
    InvalidInput
        When the text holds no timed GGA sentence (the message names the cause: missing or
        failing checksums, untimed GGA, no GGA at all), or epochs cannot be dated.
    """
    if checksums not in CHECKSUM_MODES:
        raise ValueError(f"checksums must be one of {CHECKSUM_MODES}, got {checksums!r}")
    return _parse_nmea(text, label, fallback_date_s, checksums)


def gnss_checksums(manifest: dict) -> str:
    """The checksum mode of a survey's NMEA log: survey.json ``gnss.checksums``
    (``"required"`` unless the survey states ``"optional"``)."""
    gnss = manifest.get("gnss") if isinstance(manifest, dict) else None
    mode = gnss.get("checksums") if isinstance(gnss, dict) else None
    return mode if mode in CHECKSUM_MODES else "required"


def _no_epoch_cause(n_lines: int, n_sentences: int, binary: int,
                    skipped: dict[str, list[int]]) -> str:
    """The real reason a log gave no GGA epoch, for the error message."""
    nocs, bad = skipped["no_checksum"], skipped["bad_checksum"]
    if nocs and n_sentences == 0 and not bad:
        return (f"no sentence has a checksum ({len(nocs)} line(s), first line {nocs[0]}); if "
                "the receiver sends none, accept them with survey.json "
                '"gnss": {"checksums": "optional"}')
    if bad and n_sentences == 0:
        return (f"every sentence fails its checksum ({len(bad)} line(s), first line "
                f"{bad[0]}): wrong baud rate, or a log altered after recording")
    if skipped["bad_gga"]:
        return (f"every GGA sentence fails its checksum ({len(skipped['bad_gga'])} line(s), "
                f"first line {skipped['bad_gga'][0]}; other sentences pass): the receiver "
                "computes GGA checksums wrongly, or the log was altered")
    if nocs and not skipped["gga"]:
        return (f"no GGA sentence has a checksum ({len(nocs)} line(s) without one, first "
                f"line {nocs[0]}); if the receiver sends none, accept them with survey.json "
                '"gnss": {"checksums": "optional"}')
    if skipped["rmc"] and not skipped["gga"]:
        return (f"no GGA sentence, only RMC ({len(skipped['rmc'])} line(s), first line "
                f"{skipped['rmc'][0]}): RMC has neither fix quality nor altitude; set the "
                "receiver to output GGA")
    if skipped["untimed"]:
        return (f"{len(skipped['untimed'])} GGA sentence(s) but none has a time, first line "
                f"{skipped['untimed'][0]} (the receiver never had a fix)")
    extra = ""
    if nocs or bad:
        extra = (f"; {len(bad)} line(s) with a wrong checksum, {len(nocs)} without one were "
                 "skipped")
    what = "binary data?" if binary > n_lines // 2 else "not a GNSS position log?"
    return (f"no GGA sentence with a time among {n_lines} line(s) ({n_sentences} NMEA "
            f"sentence(s)){extra}: {what}")


def _parse_nmea(text: str, label: str, fallback_date_s: float | None,
                checksums: str) -> GnssLog:
    """:func:`parse_nmea` once the checksum mode is checked."""
    known = fallback_date_s is not None and math.isfinite(fallback_date_s)
    pivot = datetime.fromtimestamp(fallback_date_s, tz=UTC).year if known else None
    records: list[tuple] = []  # (tod_s, kind, payload)
    skipped: dict[str, list[int]] = {k: [] for k in (
        "bad_checksum", "no_checksum", "junk", "untimed", "void", "implausible", "prefixed",
        "bad_gga", "gga", "rmc")}
    binary = 0
    n_lines = n_sentences = 0
    for lineno, raw in enumerate(split_lines(text), start=1):
        verdict = classify_line(raw, checksums)
        if not raw.strip() or verdict.kind == "comment":
            continue
        n_lines += 1
        if verdict.prefixed:
            skipped["prefixed"].append(lineno)
        if verdict.sentence_type in ("GGA", "RMC"):
            skipped[verdict.sentence_type.lower()].append(lineno)
        if verdict.kind != "ok":
            skipped[verdict.kind].append(lineno)
            if verdict.kind == "bad_checksum" and verdict.sentence_type == "GGA":
                skipped["bad_gga"].append(lineno)
            binary += "\ufffd" in raw
            continue
        msg = verdict.msg
        n_sentences += 1
        try:
            if isinstance(msg, pynmea2.GGA):
                if not gga_has_time(msg):
                    skipped["untimed"].append(lineno)
                    continue
                tod, payload = gga_fields(msg)
                records.append((tod, "GGA", payload))
            elif is_void_rmc(msg):
                skipped["void"].append(lineno)
            elif (when := sentence_time(msg, pivot)) is not None:
                if known and abs(sum(when) - fallback_date_s) > MAX_DATE_OFFSET_S:
                    skipped["implausible"].append(lineno)
                    continue
                records.append((when[0], "DATE", when[1]))
        except FIELD_ERRORS:
            skipped["junk"].append(lineno)
    if not any(r[1] == "GGA" for r in records):
        raise InvalidInput(_no_epoch_cause(n_lines, n_sentences, binary, skipped), label)

    first_dated = next((r for r in records if r[1] == "DATE"), None)
    cols: list[tuple] = []
    day_s: float | None = None
    last_tod = 0.0
    n_merged = 0
    k = 0
    while k < len(records):
        tod = records[k][0]
        end = k + 1
        while end < len(records) and abs(records[end][0] - tod) < SAME_EPOCH_S:
            end += 1
        block = records[k:end]
        k = end
        own = next((r[2] for r in block if r[1] == "DATE"), None)
        ggas = [r[2] for r in block if r[1] == "GGA"]
        if own is not None:
            day_s = own
        elif not ggas:
            continue
        elif day_s is not None:
            if tod < last_tod - _HALF_DAY_S:
                day_s += 86400.0
            elif tod > last_tod + _HALF_DAY_S:
                day_s -= 86400.0
        elif first_dated is not None:
            day_s = first_dated[2] - (86400.0 if tod > first_dated[0] + _HALF_DAY_S else 0.0)
        elif known:
            day_s = math.floor(fallback_date_s / 86400.0) * 86400.0
        else:
            raise InvalidInput(
                f"no valid RMC or ZDA sentence gives the date ({len(skipped['void'])} void "
                f"RMC, {len(skipped['implausible'])} implausible date(s)) and no survey start "
                "date is known", label)
        last_tod = tod
        if ggas:
            best = min(ggas, key=lambda p: fix_rank(p[3], p[4]))
            n_merged += len(ggas) - 1
            cols.append((day_s + tod, *best))
    arr = np.array(cols, dtype=np.float64).reshape(-1, 7)
    return GnssLog(
        time_s=arr[:, 0].copy(), lat_deg=arr[:, 1].copy(), lon_deg=arr[:, 2].copy(),
        alt_m=arr[:, 3].copy(), fix_quality=arr[:, 4].astype(np.int8),
        n_sats=arr[:, 5].astype(np.int16), hdop=arr[:, 6].copy(), n_lines=n_lines,
        bad_checksum_lines=tuple(skipped["bad_checksum"]),
        unparseable_lines=tuple(skipped["junk"]),
        no_checksum_lines=tuple(skipped["no_checksum"]),
        untimed_gga_lines=tuple(skipped["untimed"]), void_rmc_lines=tuple(skipped["void"]),
        implausible_date_lines=tuple(skipped["implausible"]),
        prefixed_lines=tuple(skipped["prefixed"]), merged_epochs=n_merged,
    )


def read_nmea(path: str | os.PathLike, fallback_date_s: float | None = None,
              label: str | None = None, checksums: str = "required") -> GnssLog:
    """Read an NMEA 0183 log file (see :func:`parse_nmea`); bytes that are not text (line
    noise, a binary protocol mixed with NMEA) become U+FFFD and are skipped with the junk."""
    label = str(path) if label is None else label
    return parse_nmea(read_text(path, label, errors="replace"), label, fallback_date_s,
                      checksums)

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
