"""Ground projection of frames: cv2.remap maps, footprints and per-cell viewing geometry.

:func:`ground_maps` gives, for every cell of a :class:`GroundGrid`, the source pixel (u, v) of
a frame taken with a camera and pose, as float32 maps for ``cv2.remap``. The kernels are
compiled with numba and compute every cell exactly (no coarse-lattice interpolation), a
1000 x 1000 grid in a few milliseconds; they agree with the cameras' ``project`` to float32
rounding (tested).
"""

from __future__ import annotations

import math

import numba
import numpy as np
import shapely
from shapely.geometry import Polygon

from clearfast_gis import kernels
from clearfast_gis.geometry.cameras import Camera, EquiangularCamera, PinholeCamera
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.geometry.pose import CameraPose

#: map value of cells the frame does not see
NOT_SEEN = -1.0


@numba.njit(cache=True, nogil=True)
def _equiangular_maps(xs, ys, z, c, r_att, az0, el0, ifov, width, height,
                      map_x, map_y):  # pragma: no cover - compiled
    cu = (width - 1) / 2.0
    cv = (height - 1) / 2.0
    dz = z - c[2]
    two_pi = 2.0 * math.pi
    for i in range(ys.size):
        dy = ys[i] - c[1]
        for j in range(xs.size):
            dx = xs[j] - c[0]
            bx = r_att[0, 0] * dx + r_att[1, 0] * dy + r_att[2, 0] * dz
            by = r_att[0, 1] * dx + r_att[1, 1] * dy + r_att[2, 1] * dz
            bz = r_att[0, 2] * dx + r_att[1, 2] * dy + r_att[2, 2] * dz
            d_az = math.atan2(bx, by) - az0
            d_az -= two_pi * math.floor((d_az + math.pi) / two_pi)
            el = math.atan2(bz, math.sqrt(bx * bx + by * by))
            u = d_az / ifov + cu
            v = (el0 - el) / ifov + cv
            if dz < 0.0 and 0.0 <= u <= width - 1.0 and 0.0 <= v <= height - 1.0:
                map_x[i, j] = u
                map_y[i, j] = v
            else:
                map_x[i, j] = -1.0
                map_y[i, j] = -1.0


@numba.njit(cache=True, nogil=True)
def _pinhole_maps(xs, ys, z, c, rot, fx, fy, cx, cy, dist, width, height,
                  map_x, map_y):  # pragma: no cover - compiled
    k1, k2, p1, p2, k3 = dist[0], dist[1], dist[2], dist[3], dist[4]
    dz = z - c[2]
    for i in range(ys.size):
        dy = ys[i] - c[1]
        for j in range(xs.size):
            dx = xs[j] - c[0]
            pz = rot[0, 2] * dx + rot[1, 2] * dy + rot[2, 2] * dz
            map_x[i, j] = -1.0
            map_y[i, j] = -1.0
            if pz <= 0.0 or dz >= 0.0:
                continue
            x = (rot[0, 0] * dx + rot[1, 0] * dy + rot[2, 0] * dz) / pz
            y = (rot[0, 1] * dx + rot[1, 1] * dy + rot[2, 1] * dz) / pz
            r2 = x * x + y * y
            radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3))
            xd = x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x)
            yd = y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y
            u = fx * xd + cx
            v = fy * yd + cy
            if 0.0 <= u <= width - 1.0 and 0.0 <= v <= height - 1.0:
                map_x[i, j] = u
                map_y[i, j] = v


def ground_maps(camera: Camera, pose: CameraPose, grid: GroundGrid,
                z: float = 0.0, bound: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Source-pixel maps of a frame over a ground grid, for ``cv2.remap``.

    Parameters
    ----------
    camera : EquiangularCamera or PinholeCamera
    pose : CameraPose
    grid : GroundGrid
        Cells are sampled at their centres on the plane ``z``.
    z : float
        Height of the ground plane in the world frame, metres.
    bound : bool
        Compute only the cells inside the bounding box of the frame's ground outline (the
        others are not seen). False computes every cell of ``grid``: for a grid that is
        already such a window (:func:`clearfast_gis.mosaic.project.footprint_window`), where
        tracing the outline again would cost more than the few cells it skips. The maps are
        the same either way.

    Returns
    -------
    map_x, map_y : float32 (H_grid, W_grid)
        Pixel column and row of each cell centre, -1 where the frame does not see the cell
        (behind the camera, beyond the horizon or outside the pixel-centre hull
        ``[0, W-1] x [0, H-1]``, so bilinear interpolation never reads outside the frame).
    """
    return kernels.kernel("ground_maps")(camera, pose, grid, z, bound)


def _ground_maps_reference(camera: Camera, pose: CameraPose, grid: GroundGrid, z: float,
                           bound: bool) -> tuple[np.ndarray, np.ndarray]:
    """:func:`ground_maps` on the reference kernels (every cell; ``bound`` changes nothing
    in the maps)."""
    return reference_maps(camera, pose, grid, z)


def _ground_maps_fast(camera: Camera, pose: CameraPose, grid: GroundGrid, z: float,
                      bound: bool) -> tuple[np.ndarray, np.ndarray]:
    """:func:`ground_maps` on the fast kernels (numba, over the seen window)."""
    map_x = np.full(grid.shape, NOT_SEEN, dtype=np.float32)
    map_y = np.full(grid.shape, NOT_SEEN, dtype=np.float32)
    window = _seen_window(camera, pose, grid, z) if bound else (0, grid.height, 0, grid.width)
    if window is None:
        return map_x, map_y
    r0, r1, c0, c1 = window
    xs = grid.x_centres()[c0:c1].astype(np.float64)
    ys = grid.y_centres()[r0:r1].astype(np.float64)
    c = np.ascontiguousarray(pose.position_m, dtype=np.float64)
    out_x = map_x[r0:r1, c0:c1]
    out_y = map_y[r0:r1, c0:c1]
    if isinstance(camera, EquiangularCamera):
        _equiangular_maps(xs, ys, float(z), c, np.ascontiguousarray(pose.attitude()),
                          math.radians(pose.azimuth_deg), math.radians(pose.elevation_deg),
                          camera.ifov_rad, camera.width, camera.height, out_x, out_y)
    elif isinstance(camera, PinholeCamera):
        _pinhole_maps(xs, ys, float(z), c, np.ascontiguousarray(pose.rotation()),
                      camera.fx, camera.fy, camera.cx, camera.cy,
                      np.asarray(camera.distortion, dtype=np.float64),
                      camera.width, camera.height, out_x, out_y)
    else:
        raise TypeError(f"unknown camera model {type(camera).__name__}")
    return map_x, map_y


def reference_maps(camera: Camera, pose: CameraPose, grid: GroundGrid,
                   z: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """:func:`ground_maps` computed with the camera's numpy ``project`` for every cell (the
    reference of ``--kernels reference``); same shapes and conventions."""
    x, y = grid.cell_centres()
    uv = camera.project(np.column_stack([x.ravel(), y.ravel(), np.full(x.size, float(z))]),
                        pose)
    uv[~camera.in_frame(uv)] = NOT_SEEN
    return (uv[:, 0].reshape(grid.shape).astype(np.float32),
            uv[:, 1].reshape(grid.shape).astype(np.float32))


def _seen_window(camera: Camera, pose: CameraPose, grid: GroundGrid,
                 z: float) -> tuple[int, int, int, int] | None:
    """Row and column ranges (r0, r1, c0, c1) of the grid that can hold seen cells.

    The bounding box of the frame outline on the ground (rays cut beyond the farthest grid
    corner), widened by two cells; the whole grid when the frame may contain the nadir (where
    the outline does not bound the seen region). None when nothing can be seen.
    """
    height = pose.position_m[2] - z
    if height <= 0.0:
        return None
    full = (0, grid.height, 0, grid.width)
    if isinstance(camera, EquiangularCamera):
        bottom = pose.elevation_deg - math.degrees((camera.height - 1) / 2.0 * camera.ifov_rad)
        tilt = math.degrees(math.acos(min(1.0, pose.attitude()[2, 2])))
        if bottom - tilt <= -89.0:
            return full
    else:
        nadir = camera.project(pose.position_m - np.array([0.0, 0.0, 1.0]), pose)[0]
        margin = 0.05 * max(camera.width, camera.height)
        if np.all(np.isfinite(nadir)) and -margin <= nadir[0] <= camera.width - 1 + margin \
                and -margin <= nadir[1] <= camera.height - 1 + margin:
            return full
    xmin, ymin, xmax, ymax = grid.bounds
    corners = np.array([[xmin, ymin], [xmin, ymax], [xmax, ymin], [xmax, ymax]])
    reach = float(np.max(np.hypot(*(corners - pose.position_m[:2]).T))) + 2 * grid.pixel_size
    outline = frame_footprint(camera, pose, z, samples_per_edge=128, max_range_m=reach)
    if outline.is_empty:
        return None
    bx0, by0, bx1, by1 = outline.bounds
    pad = 2.0 * grid.pixel_size + 1e-4 * reach
    c0 = max(0, int(math.floor((bx0 - pad - grid.x0) / grid.pixel_size)))
    c1 = min(grid.width, int(math.ceil((bx1 + pad - grid.x0) / grid.pixel_size)))
    r0 = max(0, int(math.floor((grid.y0 - by1 - pad) / grid.pixel_size)))
    r1 = min(grid.height, int(math.ceil((grid.y0 - by0 + pad) / grid.pixel_size)))
    if c1 <= c0 or r1 <= r0:
        return None
    return r0, r1, c0, c1


def _offsets(pose: CameraPose, grid: GroundGrid, z: float) -> tuple[np.ndarray, ...]:
    xs = grid.x_centres() - pose.position_m[0]
    ys = grid.y_centres() - pose.position_m[1]
    return xs[None, :], ys[:, None], float(z) - pose.position_m[2]


def slant_range_map(pose: CameraPose, grid: GroundGrid, z: float = 0.0) -> np.ndarray:
    """Distance (m) from the camera centre to each cell centre (atmospheric path), (H, W)
    float32."""
    dx, dy, dz = _offsets(pose, grid, z)
    return np.sqrt(dx * dx + dy * dy + dz * dz).astype(np.float32)


def incidence_angle_map(pose: CameraPose, grid: GroundGrid, z: float = 0.0) -> np.ndarray:
    """Angle (deg) between the line of sight to each cell and the vertical (0 = seen from
    straight above, 90 = grazing), (H, W) float32."""
    dx, dy, dz = _offsets(pose, grid, z)
    return np.degrees(np.arctan2(np.hypot(dx, dy), -dz)).astype(np.float32)


def off_axis_angle_map(pose: CameraPose, grid: GroundGrid, z: float = 0.0) -> np.ndarray:
    """Angle (deg) between the optical axis and the line of sight to each cell, (H, W)
    float32 (small = near the frame centre)."""
    dx, dy, dz = _offsets(pose, grid, z)
    f = pose.forward()
    dot = dx * f[0] + dy * f[1] + dz * f[2]
    norm = np.sqrt(dx * dx + dy * dy + dz * dz)
    with np.errstate(invalid="ignore", divide="ignore"):
        cosang = np.clip(dot / norm, -1.0, 1.0)
    return np.degrees(np.arccos(cosang)).astype(np.float32)


def frame_footprint(camera: Camera, pose: CameraPose, z: float = 0.0,
                    samples_per_edge: int = 32, max_range_m: float | None = None) -> Polygon:
    """Ground outline of a frame on the plane ``z`` as a shapely Polygon.

    The outline of the pixel-centre hull is sampled ``samples_per_edge`` times per side and
    intersected with the ground. Rays that do not meet the ground within ``max_range_m``
    (horizontal distance, default 50 times the camera height) are cut there, so a frame that
    shows the horizon gets a bounded outline. Returns an empty polygon when the frame sees no
    ground.
    """
    height = pose.position_m[2] - z
    if height <= 0.0:
        return Polygon()
    limit = 50.0 * height if max_range_m is None else float(max_range_m)
    edge = camera.edge_pixels(samples_per_edge)
    d = camera.rays(edge[:, 0], edge[:, 1], pose)
    horiz = np.hypot(d[:, 0], d[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = np.where(d[:, 2] < 0.0, height * horiz / -d[:, 2], np.inf)
        scale = np.where(reach <= limit, height / -d[:, 2], limit / horiz)
    if not np.any(d[:, 2] < 0.0):
        return Polygon()
    pts = pose.position_m[None, :2] + scale[:, None] * d[:, :2]
    pts = pts[np.all(np.isfinite(pts), axis=1)]
    if len(pts) < 3:
        return Polygon()
    poly = Polygon(pts)
    if not poly.is_valid:
        # an outline cut at the range limit can cross itself: keep its polygonal parts, or the
        # convex hull of the outline points when nothing polygonal survives the repair
        parts = [g for g in shapely.get_parts(shapely.make_valid(poly))
                 if g.geom_type in ("Polygon", "MultiPolygon") and not g.is_empty]
        poly = shapely.unary_union(parts) if parts else shapely.MultiPoint(pts).convex_hull
        if poly.is_empty or poly.geom_type not in ("Polygon", "MultiPolygon"):
            poly = shapely.MultiPoint(pts).convex_hull
    return poly
