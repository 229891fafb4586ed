"""DJI radiometric JPEGs (Zenmuse H20T/H20N/H30T/XT S, Mavic 2 Enterprise Advanced, M30T,
Mavic 3T, Matrice 4T): recognised and refused.

DJI stores the raw thermal image in JPEG APP3 segments (exiftool ``DJI:ThermalData``) and its
conversion to temperature in a proprietary calibration block that only DJI's Thermal SDK
(closed-source binaries) decodes. No decoder installable from the package registries reproduces
the SDK's reference arrays (``docs/import.md`` lists the candidates and why each was not
used), so these files are refused with a message saying how to bring them in: export the
temperatures as a float32 TIFF with DJI's own software and import that TIFF with its unit.
Zenmuse XT/XT2 files are FLIR R-JPEGs (a FLIR core) and are read by
:mod:`clearfast_gis.cameras.flir`.
"""

from __future__ import annotations

from os import PathLike
from typing import Any

from clearfast_gis.errors import InvalidInput


def is_dji_rjpeg(tags: dict[str, Any]) -> bool:
    """True for a DJI radiometric JPEG (DJI thermal data, no FLIR raw image)."""
    return "DJI:ThermalData" in tags or "DJI:ThermalCalibration" in tags


def refuse(path: str | PathLike, tags: dict[str, Any]) -> InvalidInput:
    """The error for a DJI radiometric JPEG."""
    model = tags.get("IFD0:Model") or "unknown model"
    return InvalidInput(
        f"DJI radiometric JPEG ({model}): not supported, no open decoder reproduces DJI's "
        "Thermal SDK; export its temperatures as a float32 TIFF with DJI Thermal Analysis "
        "Tool and import that with --unit C (docs/import.md)", path)
