"""Writing FLIR FFF records and radiometric JPEGs (for the digital twin's camera files).

The layout is the one exiftool reads (``Image::ExifTool::FLIR``, P. Harvey): a 64-byte FFF
header (``FFF\\0``, creator, version 100, offset and count of the record directory), a
directory of 32-byte entries, and two records, little-endian:

- ``RawData`` (type 1, subtype 2 = little-endian): a 32-byte header of int16 (byte-order
  mark 2, width, height, width - 1 at word 6, height - 1 at word 8) and the raw uint16 image;
- ``CameraInfo`` (type 0x20): emissivity, ObjectDistance, reflected / atmospheric / IR-window
  temperatures (kelvin), window transmission, relative humidity (fraction), Planck R1, B, F,
  the atmospheric constants, FieldOfView, camera model, PlanckO (int32), PlanckR2 and the
  capture time (UTC seconds, milliseconds, zone offset) at exiftool's offsets.

A radiometric JPEG is an 8-bit preview JPEG with the FFF record split over APP1 segments
``FLIR\\0 0x01 <chunk> <chunks - 1>``. Files written here read back through
:func:`clearfast_gis.cameras.read_frames` (exiftool) to the same raw image and parameters
(tested).
"""

from __future__ import annotations

import io
import struct
from datetime import datetime
from os import PathLike

import numpy as np

from clearfast_gis.atomic import atomic_path
from clearfast_gis.radiometry.flir import FlirObjectParams, FlirPlanck
from clearfast_gis.units import ZERO_CELSIUS_K

CAMERA_INFO_SIZE = 0x480
"""Bytes of the CameraInfo record (past its last field, FrameRate at 0x464)."""
APP1_CHUNK = 65000
"""FFF bytes per JPEG APP1 segment (a segment holds at most 65533)."""


def _entry(rec_type: int, subtype: int, offset: int, length: int) -> bytes:
    return struct.pack("<HHIIIIIII", rec_type, subtype, 0x64, 1, offset, length, 0, 0, 0)


def fff_bytes(raw: np.ndarray, planck: FlirPlanck, params: FlirObjectParams,
              time_utc: datetime, fov_deg: float = 0.0, model: str = "clearfast twin"
              ) -> bytes:
    """One FFF record holding ``raw`` (uint16 (H, W)) and the camera's parameters.

    ``planck.o`` is stored as an integer (FLIR's int32 field); ``time_utc`` must be aware.
    """
    raw = np.ascontiguousarray(raw, dtype="<u2")
    h, w = raw.shape
    raw_hdr = np.zeros(16, "<u2")
    raw_hdr[[0, 1, 2, 6, 8]] = (2, w, h, w - 1, h - 1)
    raw_rec = raw_hdr.tobytes() + raw.tobytes()
    info = bytearray(CAMERA_INFO_SIZE)
    struct.pack_into("<HHH", info, 0, 2, w, h)
    floats = {0x20: params.emissivity, 0x24: params.distance_m,
              0x28: params.reflected_c + ZERO_CELSIUS_K,
              0x2c: params.atmosphere_c + ZERO_CELSIUS_K,
              0x30: params.window_c + ZERO_CELSIUS_K, 0x34: params.window_transmission,
              0x3c: params.rh_pct / 100.0, 0x58: planck.r1, 0x5c: planck.b, 0x60: planck.f,
              0x70: params.alpha1, 0x74: params.alpha2, 0x78: params.beta1,
              0x7c: params.beta2, 0x80: params.x, 0x1b4: fov_deg, 0x30c: planck.r2}
    for off, val in floats.items():
        struct.pack_into("<f", info, off, float(val))
    struct.pack_into("<i", info, 0x308, int(round(planck.o)))
    info[0xd4:0xd4 + 32] = model.encode("ascii", "replace")[:31].ljust(32, b"\0")
    stamp = time_utc.timestamp()
    secs = int(np.floor(stamp))
    struct.pack_into("<IIh", info, 0x384, secs, int(round((stamp - secs) * 1000)) % 1000, 0)
    header_len, dir_len = 0x40, 2 * 0x20
    raw_off = header_len + dir_len
    info_off = raw_off + len(raw_rec)
    header = bytearray(header_len)
    header[0:4] = b"FFF\0"
    header[4:20] = b"clearfast".ljust(16, b"\0")
    struct.pack_into("<IIII", header, 0x14, 100, header_len, 2, 2)
    directory = _entry(1, 2, raw_off, len(raw_rec)) + _entry(0x20, 1, info_off, len(info))
    return bytes(header) + directory + raw_rec + bytes(info)


def write_fff(path: str | PathLike, record: bytes) -> None:
    """Write one FFF record as a ``.fff`` file (atomically)."""
    with atomic_path(path) as tmp:
        tmp.write_bytes(record)


def write_rjpeg(path: str | PathLike, record: bytes, preview: np.ndarray) -> None:
    """Write a FLIR radiometric JPEG: an 8-bit preview (H, W) with the FFF record in APP1.

    Parameters
    ----------
    record : bytes
        From :func:`fff_bytes`.
    preview : uint8 (H, W)
        The visible image (e.g. the raw image stretched).
    """
    from PIL import Image

    buf = io.BytesIO()
    Image.fromarray(np.asarray(preview, np.uint8)).save(buf, format="JPEG", quality=90)
    jpeg = buf.getvalue()
    chunks = [record[i:i + APP1_CHUNK] for i in range(0, len(record), APP1_CHUNK)]
    segments = b"".join(
        b"\xff\xe1" + struct.pack(">H", 2 + 8 + len(c)) + b"FLIR\0\x01"
        + bytes([k, len(chunks) - 1]) + c for k, c in enumerate(chunks))
    with atomic_path(path) as tmp:
        tmp.write_bytes(jpeg[:2] + segments + jpeg[2:])
