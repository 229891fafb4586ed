"""Camera pose from pan/tilt pointing, platform attitude and mount offsets.

Conventions (docs/contracts.md §1): world frame (E, N, z up); azimuth A clockwise from grid
north; elevation E above horizontal (negative looks down, -90 = nadir). For an optical axis
(A, E) the OpenCV camera axes in the pan/tilt base frame are

- forward ``f = (sinA cosE, cosA cosE, sinE)``
- right ``r = (cosA, -sinA, 0)``
- down ``d = f x r``

and ``R_world_from_cam = R_world_from_base @ [r | d | f]``. The platform attitude (roll, pitch,
yaw in degrees) rotates the pan/tilt base: ``R_world_from_base = Rz(-yaw) @ Ry(pitch) @
Rx(roll)`` with right-handed rotations about the world east (x), north (y) and up (z) axes, so a
positive yaw turns the base clockwise seen from above (like an azimuth).
"""

from __future__ import annotations

import functools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from clearfast_gis.errors import InvalidInput


def _rx(a_rad: float) -> np.ndarray:
    c, s = np.cos(a_rad), np.sin(a_rad)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def _ry(a_rad: float) -> np.ndarray:
    c, s = np.cos(a_rad), np.sin(a_rad)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def _rz(a_rad: float) -> np.ndarray:
    c, s = np.cos(a_rad), np.sin(a_rad)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def attitude_matrix(roll_deg: float, pitch_deg: float, yaw_deg: float) -> np.ndarray:
    """Rotation of the pan/tilt base in the world, ``Rz(-yaw) @ Ry(pitch) @ Rx(roll)``.

    Parameters
    ----------
    roll_deg, pitch_deg, yaw_deg : float
        Platform attitude in degrees (roll about east, pitch about north, yaw clockwise about up).

    Returns
    -------
    ndarray, shape (3, 3)
        ``R_world_from_base``.
    """
    angles = (float(roll_deg), float(pitch_deg), float(yaw_deg))
    return _attitude_matrix(tuple(a.hex() for a in angles), *angles).copy()


@functools.lru_cache(maxsize=4096)
def _attitude_matrix(key: tuple[str, ...], roll_deg: float, pitch_deg: float,
                     yaw_deg: float) -> np.ndarray:
    """:func:`attitude_matrix`, remembered: a scan's frames share one attitude, and every ray,
    footprint and re-posing asks for it again. ``key`` is the angles' exact bits (``-0.0``
    is not ``0.0`` here)."""
    return (_rz(-np.radians(yaw_deg)) @ _ry(np.radians(pitch_deg))
            @ _rx(np.radians(roll_deg)))


def direction_from_angles(azimuth_rad: np.ndarray, elevation_rad: np.ndarray) -> np.ndarray:
    """Unit vectors (E, N, up) for azimuths and elevations in radians; shape (..., 3)."""
    ce = np.cos(elevation_rad)
    return np.stack([np.sin(azimuth_rad) * ce, np.cos(azimuth_rad) * ce,
                     np.sin(elevation_rad) * np.ones_like(ce)], axis=-1)


def angles_from_direction(d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Azimuth and elevation (radians) of direction vectors ``d`` (..., 3) (not necessarily unit).

    The azimuth is in (-pi, pi], clockwise from north; the elevation in [-pi/2, pi/2].
    """
    d = np.asarray(d, dtype=float)
    az = np.arctan2(d[..., 0], d[..., 1])
    el = np.arctan2(d[..., 2], np.hypot(d[..., 0], d[..., 1]))
    return az, el


def base_rotation(azimuth_deg: float, elevation_deg: float) -> np.ndarray:
    """``[r | d | f]`` for the optical axis (A, E) in the pan/tilt base frame, shape (3, 3)."""
    a, e = np.radians(azimuth_deg), np.radians(elevation_deg)
    f = np.array([np.sin(a) * np.cos(e), np.cos(a) * np.cos(e), np.sin(e)])
    r = np.array([np.cos(a), -np.sin(a), 0.0])
    d = np.cross(f, r)
    return np.column_stack([r, d, f])


@dataclass(frozen=True)
class CameraPose:
    """Position and pointing of the camera.

    Parameters
    ----------
    position_m : array_like, shape (3,)
        Camera centre (E, N, z above ground), metres.
    azimuth_deg : float
        Optical-axis azimuth in the pan/tilt base frame, degrees clockwise from grid north.
    elevation_deg : float
        Optical-axis elevation in the base frame, degrees (negative looks down), in [-90, 90].
    attitude_rpy_deg : tuple of 3 floats
        Platform roll, pitch, yaw in degrees (see :func:`attitude_matrix`).
    lever_m : tuple of 3 floats
        Antenna-to-camera offset in the pan/tilt base frame, metres (``position_m`` is the
        antenna plus this offset turned by the attitude); zero when the pose does not come
        from an antenna position.
    """

    position_m: np.ndarray
    azimuth_deg: float
    elevation_deg: float
    attitude_rpy_deg: tuple[float, float, float] = field(default=(0.0, 0.0, 0.0))
    lever_m: tuple[float, float, float] = field(default=(0.0, 0.0, 0.0))

    def __post_init__(self) -> None:
        pos = np.asarray(self.position_m, dtype=float).reshape(-1)
        if pos.shape != (3,) or not np.all(np.isfinite(pos)):
            raise ValueError(f"position_m must be 3 finite numbers, got {self.position_m!r}")
        if not -90.0 <= float(self.elevation_deg) <= 90.0:
            raise ValueError(f"elevation_deg must be in [-90, 90], got {self.elevation_deg}")
        att = tuple(float(x) for x in self.attitude_rpy_deg)
        if len(att) != 3:
            raise ValueError("attitude_rpy_deg must have 3 values (roll, pitch, yaw)")
        object.__setattr__(self, "position_m", pos)
        object.__setattr__(self, "azimuth_deg", float(self.azimuth_deg))
        object.__setattr__(self, "elevation_deg", float(self.elevation_deg))
        lever = tuple(float(x) for x in self.lever_m)
        if len(lever) != 3:
            raise ValueError("lever_m must have 3 values")
        object.__setattr__(self, "attitude_rpy_deg", att)
        object.__setattr__(self, "lever_m", lever)

    def with_attitude(self, attitude_rpy_deg) -> CameraPose:
        """The same camera on the same antenna with another platform attitude (degrees): the
        antenna-to-camera offset ``lever_m`` turns with the platform, so the camera centre
        moves by ``(R(new) - R(old)) @ lever_m`` (0.4 m below the antenna and 4.5 deg of roll:
        3 cm)."""
        att = tuple(float(a) for a in attitude_rpy_deg)
        lever = np.asarray(self.lever_m, dtype=float)
        position = self.position_m + (attitude_matrix(*att) - self.attitude()) @ lever
        return CameraPose(position, self.azimuth_deg, self.elevation_deg, att, self.lever_m)

    def attitude(self) -> np.ndarray:
        """``R_world_from_base`` (3, 3) from the platform attitude."""
        return attitude_matrix(*self.attitude_rpy_deg)

    def rotation(self) -> np.ndarray:
        """``R_world_from_cam`` (3, 3): columns are the camera's right, down, forward axes."""
        return self.attitude() @ base_rotation(self.azimuth_deg, self.elevation_deg)

    def forward(self) -> np.ndarray:
        """Unit optical axis in the world, shape (3,)."""
        return self.rotation()[:, 2]


def _vector(value: object, n: int, name: str, path: str | None) -> np.ndarray:
    try:
        arr = np.asarray(value, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise InvalidInput(f"expected {n} numbers", path, name) from None
    if arr.shape != (n,) or not np.all(np.isfinite(arr)):
        raise InvalidInput(f"expected {n} numbers", path, name)
    return arr


def _number(mapping: Mapping, key: str, field_name: str, path: str | None) -> float:
    value = mapping.get(key, 0.0)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not np.isfinite(value):
        raise InvalidInput("expected a number (degrees)", path, field_name)
    return float(value)


def pose_from_ptu(
    antenna_world_m: Sequence[float] | np.ndarray,
    pan_deg: float,
    tilt_deg: float,
    platform: Mapping,
    attitude_rpy_deg: Sequence[float] = (0.0, 0.0, 0.0),
    path: str | None = None,
) -> CameraPose:
    """Camera pose from the GNSS antenna position and the pan/tilt unit's angles.

    ``A = platform.pan_zero_azimuth_deg + pan_deg``, ``E = platform.tilt_zero_deg + tilt_deg``;
    the camera centre is ``antenna + R_world_from_base @ platform.antenna_to_camera_m``.

    Parameters
    ----------
    antenna_world_m : array_like, shape (3,)
        Antenna phase centre in the world frame (E, N, z above ground), metres.
    pan_deg, tilt_deg : float
        Pan/tilt unit readings, degrees.
    platform : mapping
        The survey.json ``platform`` object (``pan_zero_azimuth_deg``, ``tilt_zero_deg``,
        ``antenna_to_camera_m``; missing keys count as zero).
    attitude_rpy_deg : sequence of 3 floats
        Platform roll, pitch, yaw, degrees.
    path : str, optional
        File named in error messages (default ``survey.json``).

    Returns
    -------
    CameraPose
    """
    where = path or "survey.json"
    if not isinstance(platform, Mapping):
        raise InvalidInput("expected an object", where, "platform")
    antenna = _vector(antenna_world_m, 3, "antenna position", where)
    offset = _vector(platform.get("antenna_to_camera_m", (0.0, 0.0, 0.0)), 3,
                     "platform.antenna_to_camera_m", where)
    pan0 = _number(platform, "pan_zero_azimuth_deg", "platform.pan_zero_azimuth_deg", where)
    tilt0 = _number(platform, "tilt_zero_deg", "platform.tilt_zero_deg", where)
    att = tuple(_vector(attitude_rpy_deg, 3, "attitude_rpy_deg", where))
    elevation = tilt0 + float(tilt_deg)
    if not -90.0 <= elevation <= 90.0:
        raise InvalidInput(f"elevation {elevation:g} deg is outside [-90, 90]", where,
                           "tilt_deg")
    position = antenna + attitude_matrix(*att) @ offset
    return CameraPose(position, pan0 + float(pan_deg), elevation, att, tuple(offset))
