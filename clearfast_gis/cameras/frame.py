"""One radiometric frame as read from a camera's file, with what the file says about it.

A frame is the stored raw image (rows and columns as stored, no rotation) and the camera's own
way to turn it into object temperature: FLIR Planck constants plus object parameters
(:mod:`clearfast_gis.radiometry.flir`), or a linear scale (``T_K = scale * counts + offset``,
the TLinear cores and temperature TIFFs). Time, position and gimbal angles are what the file's
EXIF/XMP/FLIR tags give, ``None`` where it has none.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from datetime import datetime
from pathlib import Path

import numpy as np

from clearfast_gis.radiometry.flir import FlirObjectParams, FlirPlanck, object_temperature_c
from clearfast_gis.units import ZERO_CELSIUS_K


@dataclass(frozen=True)
class LinearScale:
    """Object temperature linear in the stored value: ``T_K = scale_k * value + offset_k``."""

    scale_k: float
    offset_k: float


@dataclass(frozen=True)
class Gimbal:
    """Gimbal angles from the file's tags, degrees: yaw (pan, clockwise from north as the camera
    states it), pitch (tilt, negative below the horizon), roll."""

    yaw_deg: float
    pitch_deg: float
    roll_deg: float


@dataclass(frozen=True)
class RadiometricFrame:
    """One frame of a radiometric camera file.

    Attributes
    ----------
    path : Path
        The file.
    index : int
        Frame number inside the file (0 for single-frame files).
    format : str
        ``flir-rjpeg``, ``flir-fff``, ``flir-seq``, ``flir-csq``, ``tlinear-tiff`` or
        ``temperature-tiff``.
    camera : str
        Make and model as the file states them ("" when absent).
    raw : ndarray, (H, W)
        The stored image: uint16 counts, or float32 temperatures (temperature TIFFs).
    planck, object_params : FlirPlanck, FlirObjectParams or None
        FLIR radiometry (FLIR formats only).
    linear : LinearScale or None
        Linear radiometry (TLinear and temperature TIFFs only).
    time : datetime or None
        Capture time; timezone-aware when the file states the zone, naive otherwise.
    gps : tuple (lat_deg, lon_deg, alt_m) or None
        WGS84 position from the file; altitude None when absent.
    gimbal : Gimbal or None
        Gimbal angles from the file's XMP tags.
    tags : dict
        The file's metadata as exiftool reports it (``GROUP:Tag`` keys).
    """

    path: Path
    index: int
    format: str
    camera: str
    raw: np.ndarray
    planck: FlirPlanck | None = None
    object_params: FlirObjectParams | None = None
    linear: LinearScale | None = None
    time: datetime | None = None
    gps: tuple[float, float, float | None] | None = None
    gimbal: Gimbal | None = None
    tags: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def shape(self) -> tuple[int, int]:
        """(rows, columns) of the stored image."""
        return tuple(self.raw.shape)  # type: ignore[return-value]

    def object_temperature_c(self) -> np.ndarray:
        """Object temperature, degrees C, float32 (H, W), with the camera's own parameters
        (what the camera's software shows); NaN where the raw value has no temperature."""
        if self.planck is not None and self.object_params is not None:
            return object_temperature_c(self.raw, self.planck, self.object_params).astype(
                np.float32)
        if self.linear is not None:
            t_k = self.linear.scale_k * self.raw.astype(np.float64) + self.linear.offset_k
            return (t_k - ZERO_CELSIUS_K).astype(np.float32)
        raise AssertionError("a frame has FLIR or linear radiometry")  # readers guarantee it
