"""Time, position and gimbal angles from a file's EXIF / XMP / FLIR tags (exiftool ``-G1``).

Preference order: FLIR's own record (its time carries the zone), then EXIF (with
``SubSecTimeOriginal`` and ``OffsetTimeOriginal`` where present), then XMP. GPS positions are
WGS84 degrees (exiftool's Composite tags apply the hemisphere references). Gimbal angles are
DJI's XMP ``drone-dji`` tags (also written by FLIR cores in DJI aircraft).
"""

from __future__ import annotations

import re
from datetime import UTC, datetime, timedelta, timezone
from os import PathLike
from typing import Any

from clearfast_gis.cameras.frame import Gimbal
from clearfast_gis.errors import InvalidInput

_TIME = re.compile(r"^(\d{4}):(\d\d):(\d\d) (\d\d):(\d\d):(\d\d)(\.\d+)?([+-]\d\d:\d\d|Z)?$")


def parse_time(text: str, source: str | PathLike, key: str, subsec: str | None = None,
               offset: str | None = None) -> datetime:
    """An EXIF-style time ``YYYY:MM:DD hh:mm:ss[.fff][+hh:mm]`` as a datetime (aware when a
    zone is given, in the text or as ``offset``)."""
    m = _TIME.match(str(text).strip())
    if not m:
        raise InvalidInput(f"not an EXIF time: {text!r}", source, key)
    y, mo, d, h, mi, s, frac, zone = m.groups()
    if frac is None and subsec:
        frac = "." + str(subsec).strip()
    micro = int(round(float(frac or "0") * 1e6))
    zone = zone or (offset.strip() if offset else None)
    tz = None
    if zone == "Z":
        tz = UTC
    elif zone:
        sign = -1 if zone[0] == "-" else 1
        hh, mm = zone[1:].split(":")
        tz = timezone(sign * timedelta(hours=int(hh), minutes=int(mm)))
    try:
        return datetime(int(y), int(mo), int(d), int(h), int(mi), int(s), tzinfo=tz) \
            + timedelta(microseconds=micro)
    except ValueError as exc:
        raise InvalidInput(f"not a valid time: {text!r} ({exc})", source, key) from None


def capture_time(tags: dict[str, Any], source: str | PathLike) -> datetime | None:
    """The capture time stated by the tags, or None."""
    if tags.get("FLIR:DateTimeOriginal"):
        return parse_time(tags["FLIR:DateTimeOriginal"], source, "FLIR:DateTimeOriginal")
    for key in ("ExifIFD:DateTimeOriginal", "ExifIFD:CreateDate", "XMP-xmp:CreateDate"):
        if tags.get(key):
            return parse_time(tags[key], source, key, tags.get("ExifIFD:SubSecTimeOriginal"),
                              tags.get("ExifIFD:OffsetTimeOriginal"))
    return None


def _float(tags: dict[str, Any], key: str, source: str | PathLike) -> float | None:
    if key not in tags or tags[key] in ("", None):
        return None
    try:
        return float(tags[key])
    except (TypeError, ValueError):
        raise InvalidInput(f"not a number: {tags[key]!r}", source, key) from None


def position(tags: dict[str, Any], source: str | PathLike) -> tuple[float, float,
                                                                      float | None] | None:
    """(lat, lon, alt) WGS84 degrees / metres from the tags, or None."""
    for grp in ("Composite", "FLIR"):
        lat = _float(tags, f"{grp}:GPSLatitude", source)
        lon = _float(tags, f"{grp}:GPSLongitude", source)
        if lat is not None and lon is not None:
            if grp == "FLIR" and not tags.get("FLIR:GPSValid", 1):
                continue
            if not (-90 <= lat <= 90 and -180 <= lon <= 180):
                raise InvalidInput(f"position out of range: {lat}, {lon}", source,
                                   f"{grp}:GPSLatitude")
            alts = [_float(tags, f"{g}:GPSAltitude", source) for g in ("Composite", grp, "GPS")]
            return lat, lon, next((a for a in alts if a is not None), None)
    return None


def gimbal(tags: dict[str, Any], source: str | PathLike) -> Gimbal | None:
    """Gimbal yaw, pitch, roll (degrees) from DJI XMP tags, or None."""
    vals = [_float(tags, f"XMP-drone-dji:Gimbal{n}Degree", source)
            for n in ("Yaw", "Pitch", "Roll")]
    if vals[0] is None or vals[1] is None:
        return None
    return Gimbal(vals[0], vals[1], vals[2] if vals[2] is not None else 0.0)
