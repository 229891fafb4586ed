"""Camera models: the paper's equiangular model (Eq. 6) and a pinhole with OpenCV distortion.

Both map world points to pixels (:meth:`project`) and pixels to unit world rays
(:meth:`rays`) and ground points (:meth:`ground_points`), consistently: pixel -> ground ->
pixel returns the pixel. Pixels are (u, v) = (column, row) with centres at integers.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.geometry.pose import CameraPose, angles_from_direction, direction_from_angles


def _points(points_world: np.ndarray) -> np.ndarray:
    pts = np.asarray(points_world, dtype=float)
    if pts.ndim == 1:
        pts = pts[None, :]
    if pts.ndim != 2 or pts.shape[1] != 3:
        raise ValueError(f"points_world must have shape (N, 3), got {pts.shape}")
    return pts


def _pixels(u: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    u_arr = np.asarray(u, dtype=float).reshape(-1)
    v_arr = np.asarray(v, dtype=float).reshape(-1)
    u_arr, v_arr = np.broadcast_arrays(u_arr, v_arr)
    return u_arr, v_arr


def intersect_ground(origin_m: np.ndarray, directions: np.ndarray, z: float = 0.0) -> np.ndarray:
    """Points where rays from ``origin_m`` along ``directions`` meet the plane z.

    ``origin_m`` (3,) with ``directions`` (N, 3), or one origin per frame, (F, 3) with
    ``directions`` (F, N, 3). Returns the shape of ``directions``, metres, NaN where the ray
    is parallel to the plane or meets it behind the origin (or the origin is not above the
    plane).
    """
    d = np.asarray(directions, dtype=float)
    origin = np.asarray(origin_m, dtype=float)[..., None, :]
    dz = d[..., 2]
    height = origin[..., 2] - z
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -height / dz
    ok = (dz < 0.0) & (height > 0.0) & np.isfinite(t)
    out = origin + np.where(ok, t, np.nan)[..., None] * d
    out[..., 2] = np.where(ok, z, np.nan)
    return out


def _attitudes(poses: Sequence[CameraPose]) -> np.ndarray:
    """The poses' ``R_world_from_base``, (F, 3, 3)."""
    return np.stack([p.attitude() for p in poses])


class _Camera:
    """Shared behaviour of the camera models (each model defines ``project`` and
    ``rays_of_poses``)."""

    width: int
    height: int

    @property
    def shape(self) -> tuple[int, int]:
        """(height, width) of the frame in pixels."""
        return (self.height, self.width)

    def ground_points(self, u: np.ndarray, v: np.ndarray, pose: CameraPose,
                      z: float = 0.0) -> np.ndarray:
        """Ground points (N, 3) metres seen by pixels (u, v) on the plane ``z``.

        NaN where the pixel's ray does not meet the plane ahead of the camera.
        """
        return self.ground_points_of_poses(u, v, [pose], z)[0]

    def ground_points_of_poses(self, u: np.ndarray, v: np.ndarray,
                               poses: Sequence[CameraPose], z: float = 0.0) -> np.ndarray:
        """Ground points (F, N, 3) metres seen by pixels (u, v) (N,) from each of F poses,
        in one vectorised computation: ``[i]`` is ``ground_points(u, v, poses[i], z)``, bit
        for bit. NaN where the pixel's ray does not meet the plane ahead of the camera."""
        origins = np.stack([p.position_m for p in poses])
        return intersect_ground(origins, self.rays_of_poses(u, v, poses), z)

    def rays(self, u: np.ndarray, v: np.ndarray, pose: CameraPose) -> np.ndarray:
        """Unit world directions (N, 3) of pixels (u, v)."""
        return self.rays_of_poses(u, v, [pose])[0]

    def in_frame(self, uv: np.ndarray) -> np.ndarray:
        """True where pixel coordinates (N, 2) lie within the pixel-centre hull
        ``[0, W-1] x [0, H-1]``."""
        uv = np.asarray(uv, dtype=float)
        with np.errstate(invalid="ignore"):
            return ((uv[:, 0] >= 0.0) & (uv[:, 0] <= self.width - 1)
                    & (uv[:, 1] >= 0.0) & (uv[:, 1] <= self.height - 1))

    def edge_pixels(self, samples_per_edge: int = 32) -> np.ndarray:
        """The frame outline (pixel-centre hull), counter-clockwise in the image, (4n, 2)
        (read-only: computed once per frame size, every frame footprint uses it)."""
        return _edge_pixels(self.width, self.height, int(samples_per_edge))


@functools.lru_cache(maxsize=16)
def _edge_pixels(width: int, height: int, n: int) -> np.ndarray:
    w, h = width - 1.0, height - 1.0
    t = np.linspace(0.0, 1.0, n, endpoint=False)
    top = np.column_stack([t * w, np.zeros(n)])
    right = np.column_stack([np.full(n, w), t * h])
    bottom = np.column_stack([w - t * w, np.full(n, h)])
    left = np.column_stack([np.zeros(n), h - t * h])
    out = np.vstack([top, right, bottom, left])
    out.flags.writeable = False
    return out


def _check_size(width: int, height: int) -> tuple[int, int]:
    w, h = int(width), int(height)
    if w != width or h != height or w < 2 or h < 2:
        raise ValueError(f"resolution must be 2 integers >= 2, got {width}x{height}")
    return w, h


@dataclass(frozen=True, eq=True)
class EquiangularCamera(_Camera):
    """The paper's Eq. 6 camera: pixel column and row linear in the ray's azimuth and elevation.

    ``A_ray = A + (u - (W-1)/2) ifov``, ``E_ray = E - (v - (H-1)/2) ifov`` in the pan/tilt base
    frame, with ``ifov = radians(aperture_deg) / (W - 1)``.

    Parameters
    ----------
    width, height : int
        Frame size in pixels.
    aperture_deg : float
        Horizontal aperture 2 alpha, degrees, in (0, 180).
    """

    width: int
    height: int
    aperture_deg: float

    def __post_init__(self) -> None:
        w, h = _check_size(self.width, self.height)
        if not 0.0 < float(self.aperture_deg) < 180.0:
            raise ValueError(f"aperture_deg must be in (0, 180), got {self.aperture_deg}")
        object.__setattr__(self, "width", w)
        object.__setattr__(self, "height", h)
        object.__setattr__(self, "aperture_deg", float(self.aperture_deg))

    @property
    def ifov_rad(self) -> float:
        """Angle between neighbouring pixel centres, radians."""
        return float(np.radians(self.aperture_deg) / (self.width - 1))

    def angle_offsets(self, u: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Azimuth and elevation offsets (radians) of pixels from the optical axis."""
        u_arr, v_arr = _pixels(u, v)
        return ((u_arr - (self.width - 1) / 2.0) * self.ifov_rad,
                -(v_arr - (self.height - 1) / 2.0) * self.ifov_rad)

    def project(self, points_world: np.ndarray, pose: CameraPose) -> np.ndarray:
        """Pixel coordinates (N, 2) of world points (N, 3); NaN for the camera centre itself.

        The azimuth difference to the optical axis is wrapped to (-pi, pi], so points behind
        the camera land far outside the frame.
        """
        pts = _points(points_world)
        d_base = (pts - pose.position_m) @ pose.attitude()  # rows: R^T d
        az, el = angles_from_direction(d_base)
        d_az = np.angle(np.exp(1j * (az - np.radians(pose.azimuth_deg))))
        d_el = el - np.radians(pose.elevation_deg)
        u = d_az / self.ifov_rad + (self.width - 1) / 2.0
        v = -d_el / self.ifov_rad + (self.height - 1) / 2.0
        at_centre = ~np.any(d_base != 0.0, axis=1)
        uv = np.column_stack([u, v])
        uv[at_centre] = np.nan
        return uv

    def rays_of_poses(self, u: np.ndarray, v: np.ndarray, poses: Sequence[CameraPose]
                      ) -> np.ndarray:
        """Unit world directions (F, N, 3) of pixels (u, v) (N,) from each of F poses."""
        d_az, d_el = self.angle_offsets(u, v)
        az = np.radians([p.azimuth_deg for p in poses])[:, None]
        el = np.radians([p.elevation_deg for p in poses])[:, None]
        d_base = direction_from_angles(az + d_az, el + d_el)
        return d_base @ _attitudes(poses).transpose(0, 2, 1)


def distort_normalized(x: np.ndarray, y: np.ndarray,
                       distortion: Sequence[float]) -> tuple[np.ndarray, np.ndarray]:
    """OpenCV's (k1, k2, p1, p2, k3) distortion of normalized image coordinates."""
    k1, k2, p1, p2, k3 = distortion
    r2 = x * x + y * y
    radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3))
    xd = x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x)
    yd = y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y
    return xd, yd


def undistort_normalized(xd: np.ndarray, yd: np.ndarray, distortion: Sequence[float],
                         tol: float = 1e-15, max_iter: int = 60) -> tuple[np.ndarray, np.ndarray]:
    """Invert :func:`distort_normalized` by vectorised Newton iterations (to ~1e-15).

    Starts from a few fixed-point steps (OpenCV's scheme) and refines with the analytic 2x2
    Jacobian until every point moves less than ``tol``. Points that do not converge (outside
    the region where the distortion polynomial is invertible) come back as NaN.
    """
    k1, k2, p1, p2, k3 = distortion
    xd = np.asarray(xd, dtype=float)
    yd = np.asarray(yd, dtype=float)
    if not any(distortion):
        return xd.copy(), yd.copy()
    x, y = xd.copy(), yd.copy()
    for _ in range(5):  # fixed-point start, as cv2.undistortPoints
        r2 = x * x + y * y
        radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3))
        dx = 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x)
        dy = p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y
        x, y = (xd - dx) / radial, (yd - dy) / radial
    step = np.full(x.shape, np.inf)
    for _ in range(max_iter):
        r2 = x * x + y * y
        radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3))
        g = k1 + r2 * (2.0 * k2 + 3.0 * k3 * r2)
        fx = x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x) - xd
        fy = y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y - yd
        j11 = radial + 2.0 * g * x * x + 2.0 * p1 * y + 6.0 * p2 * x
        j12 = 2.0 * g * x * y + 2.0 * p1 * x + 2.0 * p2 * y
        j22 = radial + 2.0 * g * y * y + 6.0 * p1 * y + 2.0 * p2 * x
        det = j11 * j22 - j12 * j12
        with np.errstate(divide="ignore", invalid="ignore"):
            sx = (j22 * fx - j12 * fy) / det
            sy = (j11 * fy - j12 * fx) / det
        x, y = x - sx, y - sy
        step = np.hypot(sx, sy)
        if not np.any(step > tol * (1.0 + np.hypot(x, y))):
            break
    rx, ry = distort_normalized(x, y, distortion)
    bad = ~(np.hypot(rx - xd, ry - yd) < 1e-10 * (1.0 + np.hypot(xd, yd)))
    x[bad] = np.nan
    y[bad] = np.nan
    return x, y


@dataclass(frozen=True, eq=True)
class PinholeCamera(_Camera):
    """Pinhole camera with OpenCV intrinsics and (k1, k2, p1, p2, k3) distortion.

    Parameters
    ----------
    width, height : int
        Frame size in pixels.
    fx, fy : float
        Focal lengths in pixels.
    cx, cy : float
        Principal point in pixels (pixel centres at integers).
    distortion : sequence of 5 floats
        (k1, k2, p1, p2, k3) as in ``cv2.projectPoints``.
    """

    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    distortion: tuple[float, float, float, float, float] = (0.0, 0.0, 0.0, 0.0, 0.0)

    def __post_init__(self) -> None:
        w, h = _check_size(self.width, self.height)
        dist = tuple(float(k) for k in self.distortion)
        if len(dist) != 5:
            raise ValueError("distortion must be 5 numbers (k1, k2, p1, p2, k3)")
        if not (self.fx > 0 and self.fy > 0):
            raise ValueError("fx and fy must be positive")
        object.__setattr__(self, "width", w)
        object.__setattr__(self, "height", h)
        for name in ("fx", "fy", "cx", "cy"):
            object.__setattr__(self, name, float(getattr(self, name)))
        object.__setattr__(self, "distortion", dist)

    @classmethod
    def from_aperture(cls, width: int, height: int, aperture_deg: float) -> PinholeCamera:
        """Distortion-free pinhole whose pixel-centre hull spans ``aperture_deg`` horizontally."""
        f = ((width - 1) / 2.0) / np.tan(np.radians(aperture_deg) / 2.0)
        return cls(width, height, f, f, (width - 1) / 2.0, (height - 1) / 2.0)

    @property
    def matrix(self) -> np.ndarray:
        """The 3x3 intrinsic matrix K."""
        return np.array([[self.fx, 0.0, self.cx], [0.0, self.fy, self.cy], [0.0, 0.0, 1.0]])

    def project(self, points_world: np.ndarray, pose: CameraPose) -> np.ndarray:
        """Pixel coordinates (N, 2) of world points (N, 3); NaN for points not in front."""
        pts = _points(points_world)
        pc = (pts - pose.position_m) @ pose.rotation()  # rows: R^T d
        with np.errstate(divide="ignore", invalid="ignore"):
            x = pc[:, 0] / pc[:, 2]
            y = pc[:, 1] / pc[:, 2]
        xd, yd = distort_normalized(x, y, self.distortion)
        uv = np.column_stack([self.fx * xd + self.cx, self.fy * yd + self.cy])
        uv[~(pc[:, 2] > 0.0)] = np.nan
        return uv

    def rays_of_poses(self, u: np.ndarray, v: np.ndarray, poses: Sequence[CameraPose]
                      ) -> np.ndarray:
        """Unit world directions (F, N, 3) of pixels (u, v) (N,) from each of F poses (exact
        undistortion)."""
        u_arr, v_arr = _pixels(u, v)
        x, y = undistort_normalized((u_arr - self.cx) / self.fx, (v_arr - self.cy) / self.fy,
                                    self.distortion)
        d_cam = np.column_stack([x, y, np.ones_like(x)])
        d_cam /= np.linalg.norm(d_cam, axis=1, keepdims=True)
        rotations = np.stack([p.rotation() for p in poses])
        return d_cam @ rotations.transpose(0, 2, 1)


Camera = EquiangularCamera | PinholeCamera


def _resolution(camera: Mapping, path: str) -> tuple[int, int]:
    res = camera.get("resolution")
    if (not isinstance(res, (list, tuple)) or len(res) != 2
            or not all(isinstance(x, int) and not isinstance(x, bool) for x in res)):
        raise InvalidInput("expected 2 integers", path, "camera.resolution")
    if res[0] < 2 or res[1] < 2:
        raise InvalidInput("expected 2 integers of at least 2", path, "camera.resolution")
    return int(res[0]), int(res[1])


def _finite(value: object, path: str, field: str, what: str = "a number") -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not np.isfinite(value):
        raise InvalidInput(f"expected {what}", path, field)
    return float(value)


def camera_from_manifest(camera: Mapping, path: str = "survey.json") -> Camera:
    """The camera model described by a survey.json ``camera`` object.

    Parameters
    ----------
    camera : mapping
        ``{"model": "equiangular"|"pinhole", "resolution": [W, H], "aperture_deg": ...,
        "intrinsics": {"fx", "fy", "cx", "cy", "distortion": [k1, k2, p1, p2, k3]}}``.
    path : str
        File named in error messages.

    Raises
    ------
    InvalidInput
        Naming the file and the field, e.g. ``survey.json: camera.resolution: expected 2
        integers``.
    """
    if not isinstance(camera, Mapping):
        raise InvalidInput("expected an object", path, "camera")
    model = camera.get("model", "equiangular")
    width, height = _resolution(camera, path)
    if model == "equiangular":
        aperture = _finite(camera.get("aperture_deg"), path, "camera.aperture_deg",
                           "an aperture in degrees, 0 to 180")
        if not 0.0 < aperture < 180.0:
            raise InvalidInput("expected an aperture in degrees, 0 to 180", path,
                               "camera.aperture_deg")
        return EquiangularCamera(width, height, aperture)
    if model == "pinhole":
        intr = camera.get("intrinsics")
        if not isinstance(intr, Mapping):
            raise InvalidInput("expected an object with fx, fy, cx, cy", path,
                               "camera.intrinsics")
        vals = {k: _finite(intr.get(k), path, f"camera.intrinsics.{k}") for k in
                ("fx", "fy", "cx", "cy")}
        for k in ("fx", "fy"):
            if vals[k] <= 0:
                raise InvalidInput("expected a positive focal length in pixels", path,
                                   f"camera.intrinsics.{k}")
        dist = intr.get("distortion", [0.0] * 5)
        if not isinstance(dist, (list, tuple)) or len(dist) != 5:
            raise InvalidInput("expected 5 numbers (k1, k2, p1, p2, k3)", path,
                               "camera.intrinsics.distortion")
        coeffs = tuple(_finite(d, path, f"camera.intrinsics.distortion.{i}")
                       for i, d in enumerate(dist))
        return PinholeCamera(width, height, vals["fx"], vals["fy"], vals["cx"], vals["cy"],
                             coeffs)
    raise InvalidInput("expected \"equiangular\" or \"pinhole\"", path, "camera.model")
