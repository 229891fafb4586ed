"""The ground projection's fast kernel (``--kernels fast``, :mod:`clearfast_gis.kernels`).

:func:`ground_maps` is the registry's ``ground_maps``: the cell-centre source-pixel maps of
:func:`clearfast_gis.geometry.projection.ground_maps`, compiled with numba and computed only
over the window of the grid the frame can see. Its reference is
:mod:`clearfast_gis.geometry._reference`.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from clearfast_gis.geometry.cameras import Camera, EquiangularCamera, PinholeCamera
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.geometry.pose import CameraPose
from clearfast_gis.geometry.projection import NOT_SEEN, frame_footprint

PRETEST_MARGIN = 1e-9
"""Margin of the equiangular maps' pretest, in cosine and tangent units (the angles' own
rounding is ~1e-16): a cell is skipped only when it is this far outside the frame's
angular bounds, so every cell that may be seen gets the exact computation."""


@numba.njit(cache=True, nogil=True)
def _equiangular_maps(xs, ys, z, c, r_att, az0, el0, ifov, width, height,
                      map_x, map_y, skip_outside=True):  # pragma: no cover - compiled
    cu = (width - 1) / 2.0
    cv = (height - 1) / 2.0
    dz = z - c[2]
    two_pi = 2.0 * math.pi
    # pretest without the two arctangents: a cell is outside the frame when its direction
    # is farther than the half-width cu * ifov from the axis azimuth az0, or its elevation
    # outside el0 -+ cv * ifov (monotone in bz / rho); cells near the bounds (the margin)
    # and every cell when a bound reaches the vertical are computed exactly
    half_w = cu * ifov
    el_lo = el0 - cv * ifov
    el_hi = el0 + cv * ifov
    pretest = skip_outside and half_w < 0.5 * math.pi and -0.5 * math.pi < el_lo \
        and el_hi < 0.5 * math.pi
    cos_w = math.cos(half_w) - PRETEST_MARGIN
    sin_a = math.sin(az0)
    cos_a = math.cos(az0)
    tan_lo = math.tan(el_lo) - PRETEST_MARGIN * (1.0 + abs(math.tan(el_lo)))
    tan_hi = math.tan(el_hi) + PRETEST_MARGIN * (1.0 + abs(math.tan(el_hi)))
    for i in range(ys.size):
        dy = ys[i] - c[1]
        for j in range(xs.size):
            dx = xs[j] - c[0]
            bx = r_att[0, 0] * dx + r_att[1, 0] * dy + r_att[2, 0] * dz
            by = r_att[0, 1] * dx + r_att[1, 1] * dy + r_att[2, 1] * dz
            bz = r_att[0, 2] * dx + r_att[1, 2] * dy + r_att[2, 2] * dz
            rho = math.sqrt(bx * bx + by * by)
            if pretest and rho > 0.0 and (bx * sin_a + by * cos_a < rho * cos_w
                                          or bz < rho * tan_lo or bz > rho * tan_hi):
                map_x[i, j] = -1.0
                map_y[i, j] = -1.0
                continue
            d_az = math.atan2(bx, by) - az0
            d_az -= two_pi * math.floor((d_az + math.pi) / two_pi)
            el = math.atan2(bz, rho)
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


def ground_maps(camera: Camera, pose: CameraPose, grid: GroundGrid, z: float,
                bound: bool) -> tuple[np.ndarray, np.ndarray]:
    """:func:`clearfast_gis.geometry.projection.ground_maps` on the fast kernels (numba, over
    the seen window)."""
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
