"""FLIR radiometric files: R-JPEG (FFF records in JPEG APP1), FFF, SEQ and CSQ.

exiftool (:mod:`clearfast_gis.cameras.exiftool`) decodes the metadata and extracts the embedded
raw thermal image; this module decodes that image by its ``RawThermalImageType``:

- ``TIFF``: a 16-bit TIFF (tifffile; byte order as the TIFF states it);
- ``PNG``: a 16-bit PNG written little-endian by FLIR against the PNG standard, so the decoded
  values are byte-swapped back (as exiftool's documentation and every FLIR decoder note);
- ``JPEG-LS`` (CSQ files): lossless JPEG-LS, decoded by ``imagecodecs`` (CharLS).

SEQ and CSQ files are FFF records one after the other, each starting with the magic
``FFF\\0``; each record is one frame, read by exiftool from standard input.
"""

from __future__ import annotations

import io
from os import PathLike
from pathlib import Path
from typing import Any

import numpy as np

from clearfast_gis.cameras import exiftool
from clearfast_gis.cameras import tags as tagmod
from clearfast_gis.cameras.frame import RadiometricFrame
from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry.flir import FlirObjectParams, FlirPlanck

FFF_MAGIC = b"FFF\0"
FFF_VERSION = 100
"""Header version of an FFF record (bytes 20-23 after a 16-byte creator name): a magic
followed by it starts a record; the same four bytes inside image data do not."""


def is_flir(tags: dict[str, Any]) -> bool:
    """True when the tags hold a FLIR raw thermal image."""
    return "FLIR:RawThermalImage" in tags or "FLIR:RawThermalImageType" in tags


def planck_of(tags: dict[str, Any], source: str | PathLike) -> FlirPlanck:
    """The Planck constants of a FLIR record."""
    g = {k: exiftool.number(tags, f"FLIR:Planck{k}", source) for k in ("R1", "R2", "B", "F", "O")}
    if not (g["R1"] > 0 and g["R2"] > 0 and g["B"] > 0):
        raise InvalidInput(f"Planck constants not physical: R1={g['R1']} R2={g['R2']} "
                           f"B={g['B']}", source, "FLIR:PlanckR1")
    return FlirPlanck(r1=g["R1"], r2=g["R2"], b=g["B"], f=g["F"], o=g["O"])


def object_params_of(tags: dict[str, Any], source: str | PathLike) -> FlirObjectParams:
    """The object parameters of a FLIR record (ObjectDistance, never EXIF SubjectDistance).

    FLIR stores relative humidity as a fraction (exiftool ``-n``); older records store percent
    (values above 1), both are accepted.
    """
    def n(key: str) -> float:
        return exiftool.number(tags, f"FLIR:{key}", source)

    rh = n("RelativeHumidity")
    return FlirObjectParams(
        emissivity=n("Emissivity"), reflected_c=n("ReflectedApparentTemperature"),
        atmosphere_c=n("AtmosphericTemperature"), distance_m=n("ObjectDistance"),
        rh_pct=rh * 100.0 if rh <= 1.0 else rh, window_c=n("IRWindowTemperature"),
        window_transmission=n("IRWindowTransmission"), x=n("AtmosphericTransX"),
        alpha1=n("AtmosphericTransAlpha1"), alpha2=n("AtmosphericTransAlpha2"),
        beta1=n("AtmosphericTransBeta1"), beta2=n("AtmosphericTransBeta2"))


def decode_raw(blob: bytes, kind: str, width: int, height: int,
               source: str | PathLike) -> np.ndarray:
    """The raw thermal image (uint16, (height, width) as stored) from its embedded bytes."""
    if not blob:
        raise InvalidInput("no raw thermal image in the file", source, "FLIR:RawThermalImage")
    kind = str(kind).upper()
    try:
        if kind == "TIFF":
            import tifffile

            arr = tifffile.imread(io.BytesIO(blob))
        elif kind == "PNG":
            from PIL import Image

            with Image.open(io.BytesIO(blob)) as im:
                arr = np.asarray(im, dtype=np.uint16).byteswap()
        elif kind in ("JPEG-LS", "JPEGLS"):
            import imagecodecs

            arr = imagecodecs.jpegls_decode(blob)
        elif kind == "DAT" or len(blob) == 2 * width * height:
            arr = np.frombuffer(blob, dtype="<u2", count=width * height).reshape(height, width)
        else:
            raise InvalidInput(f"raw thermal image type {kind!r} is not supported", source,
                               "FLIR:RawThermalImageType")
    except InvalidInput:
        raise
    except Exception as exc:  # a decoder's own error on corrupt bytes
        raise InvalidInput(f"raw thermal image ({kind}) cannot be decoded: {exc}", source,
                           "FLIR:RawThermalImage") from None
    arr = np.asarray(arr)
    if arr.ndim != 2 or arr.dtype != np.uint16 or (width and arr.shape != (height, width)):
        raise InvalidInput(f"raw thermal image is {arr.dtype} {arr.shape}, expected uint16 "
                           f"({height}, {width})", source, "FLIR:RawThermalImage")
    return np.ascontiguousarray(arr, dtype=np.uint16)


def frame_from_record(source: Path, index: int, fmt: str, tags: dict[str, Any],
                      data: bytes | None = None) -> RadiometricFrame:
    """A :class:`RadiometricFrame` from one FLIR record's tags (raw read from ``source`` or
    from ``data``, the record's bytes)."""
    if not is_flir(tags):
        raise InvalidInput("no FLIR radiometric data (RawThermalImage) in the file", source)
    width = int(exiftool.number(tags, "FLIR:RawThermalImageWidth", source))
    height = int(exiftool.number(tags, "FLIR:RawThermalImageHeight", source))
    blob = exiftool.binary_tag(tags, "FLIR:RawThermalImage")
    if blob is None:
        blob = exiftool.read_binary(source, "RawThermalImage", data)
    raw = decode_raw(blob, tags.get("FLIR:RawThermalImageType", ""), width, height, source)
    make = tags.get("IFD0:Make") or "FLIR"
    model = tags.get("FLIR:CameraModel") or tags.get("IFD0:Model") or ""
    return RadiometricFrame(
        path=source, index=index, format=fmt, camera=f"{make} {model}".strip(), raw=raw,
        planck=planck_of(tags, source), object_params=object_params_of(tags, source),
        time=tagmod.capture_time(tags, source), gps=tagmod.position(tags, source),
        gimbal=tagmod.gimbal(tags, source), tags=tags)


def split_records(data: bytes) -> list[bytes]:
    """The FFF records of a SEQ/CSQ file, in file order (split at each ``FFF\\0`` magic that
    is followed by the header version)."""
    starts = []
    pos = data.find(FFF_MAGIC)
    while pos >= 0:
        version = data[pos + 20:pos + 24]
        if version in (FFF_VERSION.to_bytes(4, "big"), FFF_VERSION.to_bytes(4, "little")):
            starts.append(pos)
        pos = data.find(FFF_MAGIC, pos + 1)
    return [data[a:b] for a, b in zip(starts, [*starts[1:], len(data)], strict=True)]


def read_flir(path: str | PathLike, tags: dict[str, Any], frame: int | None = None
              ) -> list[RadiometricFrame]:
    """The frames of a FLIR file (all, or only number ``frame``).

    ``tags`` are the file's exiftool tags (already read to detect the format).
    """
    path = Path(path)
    ftype = str(tags.get("File:FileType", "")).upper()
    if ftype in ("SEQ", "CSQ"):
        records = split_records(path.read_bytes())
        if not records:
            raise InvalidInput("no FFF records in the file", path)
        wanted = range(len(records)) if frame is None else [frame]
        out = []
        for i in wanted:
            if not 0 <= i < len(records):
                raise InvalidInput(f"frame {i} does not exist (the file holds "
                                   f"{len(records)} frames, 0-{len(records) - 1})", path)
            rec_tags = exiftool.read_tags(path, records[i])
            out.append(frame_from_record(path, i, f"flir-{ftype.lower()}", rec_tags,
                                         records[i]))
        return out
    if frame not in (None, 0):
        raise InvalidInput(f"frame {frame} does not exist (the file holds 1 frame)", path)
    fmt = "flir-fff" if ftype == "FLIR" else "flir-rjpeg"
    return [frame_from_record(path, 0, fmt, tags)]
