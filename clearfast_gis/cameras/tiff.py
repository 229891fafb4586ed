"""Radiometric TIFFs: 16-bit linear counts (FLIR TLinear cores) and float temperatures.

- ``tlinear-tiff``: one band of uint16 counts, object temperature ``T_K = scale * counts +
  offset``. FLIR Boson/Tau/Lepton cores in TLinear mode write 0.01 K (high resolution off:
  0.04 K on Tau/Duo) per count with offset 0 K. The scale is given by the user or read from
  the TIFF's GDAL scale/offset tags (with a GDAL unit type ``K`` or ``degC`` stating what the
  scaled value is); without either the file is refused.
- ``temperature-tiff``: one band of float32/float64 temperatures in degrees C or kelvin, stated
  by the user or by the GDAL unit type tag; without a stated unit the file is refused.

Values that cannot be physical (outside :data:`PHYSICAL_RANGE_C`) are a
problem of the file or of the stated unit/scale, never data. Files are read with rasterio
(GDAL), which also reads the scale, offset and unit tags that :func:`write_tiff` writes.
"""

from __future__ import annotations

import warnings
from os import PathLike
from pathlib import Path
from typing import Any

import numpy as np

from clearfast_gis.cameras import tags as tagmod
from clearfast_gis.cameras.frame import LinearScale, RadiometricFrame
from clearfast_gis.errors import InvalidInput
from clearfast_gis.units import ZERO_CELSIUS_K

PHYSICAL_RANGE_C = (-90.0, 200.0)
"""Temperatures a temperature TIFF may hold, degrees C: kelvin read as degrees C (above
200) or degrees C read as kelvin (below -90) fall outside and are refused."""
KELVIN_UNITS = ("k", "kelvin")
CELSIUS_UNITS = ("c", "degc", "deg c", "celsius", "\u00b0c")
"""Accepted unit names (case-insensitive), GDAL's ``degC`` and ``K`` among them."""


def unit_is_kelvin(unit: str, source: str | PathLike, field: str) -> bool:
    """True for kelvin, False for degrees C; an error for anything else."""
    key = str(unit).strip().lower()
    if key not in KELVIN_UNITS + CELSIUS_UNITS:
        raise InvalidInput(f"unit {unit!r} is neither degrees C ('C') nor kelvin ('K')",
                           source, field)
    return key in KELVIN_UNITS


def read_tiff(path: str | PathLike, tags: dict[str, Any], unit: str | None = None,
              scale_k: float | None = None, offset_k: float | None = None
              ) -> RadiometricFrame:
    """A radiometric TIFF as one frame.

    Parameters
    ----------
    path : path
        The TIFF.
    tags : dict
        Its exiftool tags (time, GPS).
    unit : {"C", "K"}, optional
        Unit of a float TIFF (overrides the file's tag).
    scale_k, offset_k : float, optional
        Kelvin per count and kelvin offset of a 16-bit TIFF (override the file's tags;
        offset default 0 K when only a scale is given).
    """
    import rasterio
    from rasterio.errors import NotGeoreferencedWarning

    path = Path(path)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", NotGeoreferencedWarning)
            src = rasterio.open(path)
        with src:
            if src.count != 1:
                raise InvalidInput(f"{src.count} bands; a radiometric TIFF has one band", path)
            data = src.read(1)
            file_unit = (src.units[0] or "").strip()
            file_scale, file_offset = src.scales[0], src.offsets[0]
    except InvalidInput:
        raise
    except Exception as exc:  # rasterio/GDAL errors on unreadable files
        raise InvalidInput(f"not a readable TIFF: {' '.join(str(exc).split())}", path) from None
    common = dict(time=tagmod.capture_time(tags, path), gps=tagmod.position(tags, path),
                  gimbal=tagmod.gimbal(tags, path), tags=tags,
                  camera=" ".join(str(tags.get(k, "")) for k in ("IFD0:Make", "IFD0:Model")
                                  ).strip() or str(tags.get("XMP-xmpDM:CameraModel", "")))
    if data.dtype == np.uint16:
        if scale_k is None:
            if not file_unit:
                raise InvalidInput("16-bit TIFF without a stated scale: give the kelvin per "
                                   "count (--scale-k 0.04 or 0.01 for FLIR TLinear)", path)
            k = unit_is_kelvin(file_unit, path, "unit")
            scale_k, offset_k = file_scale, file_offset + (0.0 if k else ZERO_CELSIUS_K)
        if not scale_k > 0:
            raise InvalidInput(f"scale must be positive kelvin per count, got {scale_k}", path)
        lin = LinearScale(float(scale_k), float(offset_k or 0.0))
        frame = RadiometricFrame(path=path, index=0, format="tlinear-tiff", raw=data,
                                 linear=lin, **common)
    elif data.dtype.kind == "f":
        unit = unit or file_unit
        if not unit:
            raise InvalidInput("float TIFF without a stated unit: give --unit C or --unit K",
                               path)
        k = unit_is_kelvin(unit, path, "unit")
        lin = LinearScale(1.0, 0.0 if k else ZERO_CELSIUS_K)
        frame = RadiometricFrame(path=path, index=0, format="temperature-tiff",
                                 raw=data.astype(np.float32, copy=False), linear=lin, **common)
    else:
        raise InvalidInput(f"sample type {data.dtype} is neither 16-bit counts nor float "
                           "temperatures", path)
    check_physical(frame.object_temperature_c(), path)
    return frame


def check_physical(t_c: np.ndarray, source: str | PathLike) -> None:
    """Refuse temperatures (degrees C) outside :data:`PHYSICAL_RANGE_C` (NaN allowed)."""
    lo, hi = PHYSICAL_RANGE_C
    finite = t_c[np.isfinite(t_c)]
    if finite.size == 0:
        raise InvalidInput("no finite temperature in the image", source)
    tmin, tmax = float(finite.min()), float(finite.max())
    if tmin < lo or tmax > hi:
        raise InvalidInput(f"temperatures {tmin:.1f} to {tmax:.1f} degrees C are not physical "
                           f"(wrong unit or scale?)", source)


def write_tiff(path: str | PathLike, values: np.ndarray, unit: str,
               scale: float = 1.0, offset: float = 0.0) -> None:
    """Write one radiometric band with its GDAL unit, scale and offset tags (atomically).

    Parameters
    ----------
    values : ndarray, (H, W)
        uint16 counts (with ``scale``/``offset`` giving ``unit``) or float32 temperatures.
    unit : {"K", "degC"}
        GDAL unit type of the scaled value.
    """
    import rasterio
    from rasterio.errors import NotGeoreferencedWarning

    from clearfast_gis.atomic import atomic_path

    profile = dict(driver="GTiff", width=values.shape[1], height=values.shape[0], count=1,
                   dtype=values.dtype.name, compress="deflate")
    with atomic_path(path) as tmp, warnings.catch_warnings():
        warnings.simplefilter("ignore", NotGeoreferencedWarning)
        dst = rasterio.open(tmp, "w", **profile)
        with dst:
            dst.write(values, 1)
            dst.units = (unit,)
            dst.scales = (scale,)
            dst.offsets = (offset,)
