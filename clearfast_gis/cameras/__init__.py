"""Real radiometric thermal cameras: their files read into :class:`RadiometricFrame` objects.

One module per format family: :mod:`~clearfast_gis.cameras.flir` (R-JPEG, FFF, SEQ, CSQ),
:mod:`~clearfast_gis.cameras.tiff` (TLinear counts and temperature TIFFs),
:mod:`~clearfast_gis.cameras.dji` (DJI R-JPEG, recognised and refused). Metadata comes from
exiftool (:mod:`~clearfast_gis.cameras.exiftool`); the camera's radiometry is in
:mod:`clearfast_gis.radiometry.flir`. Formats and what is assumed: ``docs/import.md``.
"""

from __future__ import annotations

from os import PathLike
from pathlib import Path

from clearfast_gis.cameras import dji, exiftool, flir, tiff
from clearfast_gis.cameras.frame import Gimbal, LinearScale, RadiometricFrame
from clearfast_gis.errors import InvalidInput

__all__ = ["Gimbal", "LinearScale", "RadiometricFrame", "read_frames"]


def read_frames(path: str | PathLike, frame: int | None = None, unit: str | None = None,
                scale_k: float | None = None, offset_k: float | None = None,
                tags: dict | None = None) -> list[RadiometricFrame]:
    """The radiometric frames of one camera file (all, or only number ``frame``).

    Parameters
    ----------
    path : path
        A FLIR R-JPEG/FFF/SEQ/CSQ file or a radiometric TIFF.
    frame : int, optional
        Frame number inside a multi-frame file (0-based).
    unit, scale_k, offset_k
        For TIFFs without the tags stating them (:func:`clearfast_gis.cameras.tiff.read_tiff`).
    tags : dict, optional
        The file's exiftool tags when already read (:func:`exiftool.read_tags_many`).

    Raises
    ------
    InvalidInput
        One line naming the file: not a file, no radiometric data, unsupported camera,
        missing tags, values that are not physical.
    """
    path = Path(path)
    if not path.is_file():
        raise InvalidInput("no such file", path)
    tags = exiftool.read_tags(path) if tags is None else tags
    if flir.is_flir(tags) or str(tags.get("File:FileType", "")).upper() in ("SEQ", "CSQ"):
        return flir.read_flir(path, tags, frame)
    if dji.is_dji_rjpeg(tags):
        raise dji.refuse(path, tags)
    if str(tags.get("File:FileType", "")).upper() in ("TIFF", "BIGTIFF"):
        if frame not in (None, 0):
            raise InvalidInput(f"frame {frame} does not exist (the file holds 1 frame)", path)
        return [tiff.read_tiff(path, tags, unit, scale_k, offset_k)]
    kind = tags.get("File:FileType") or "unknown type"
    raise InvalidInput(f"no radiometric data ({kind} without a FLIR raw thermal image)", path)
