"""Ground projection of frames: cv2.remap maps, footprints and per-cell viewing geometry.

:func:`ground_maps` gives, for every cell of a :class:`GroundGrid`, the source pixel (u, v) of
a frame taken with a camera and pose, as float32 maps for ``cv2.remap``. The kernels
(:mod:`clearfast_gis.geometry._kernels`) are compiled with numba and compute every cell exactly
(no coarse-lattice interpolation), a 1000 x 1000 grid in a few milliseconds; they agree with
the cameras' ``project`` (:mod:`clearfast_gis.geometry._reference`) to float32 rounding
(tested).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import shapely
from shapely.geometry import Polygon

from clearfast_gis import kernels
from clearfast_gis.geometry.cameras import Camera
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.geometry.pose import CameraPose

#: map value of cells the frame does not see
NOT_SEEN = -1.0


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
    return frame_footprints(camera, [pose], z, samples_per_edge, max_range_m)[0]


def frame_footprints(camera: Camera, poses: Sequence[CameraPose], z: float = 0.0,
                     samples_per_edge: int = 32, max_range_m: float | None = None
                     ) -> list[Polygon]:
    """:func:`frame_footprint` of many frames, the outlines' rays in one vectorised
    computation (the same polygons, bit for bit, as one frame at a time)."""
    if not len(poses):
        return []
    heights = np.array([p.position_m[2] for p in poses]) - z
    out: list[Polygon] = [Polygon()] * len(poses)
    above = np.flatnonzero(heights > 0.0)
    if above.size == 0:
        return out
    placed = [poses[i] for i in above]
    height = heights[above][:, None]
    limit = 50.0 * height if max_range_m is None else float(max_range_m)
    edge = camera.edge_pixels(samples_per_edge)
    d = camera.rays_of_poses(edge[:, 0], edge[:, 1], placed)  # (F, N, 3)
    horiz = np.hypot(d[..., 0], d[..., 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = np.where(d[..., 2] < 0.0, height * horiz / -d[..., 2], np.inf)
        scale = np.where(reach <= limit, height / -d[..., 2], limit / horiz)
    origins = np.stack([p.position_m[:2] for p in placed])[:, None, :]
    pts = origins + scale[..., None] * d[..., :2]  # (F, N, 2)
    sees = np.any(d[..., 2] < 0.0, axis=1)
    finite = np.all(np.isfinite(pts), axis=2)
    whole = sees & np.all(finite, axis=1)
    polys = np.empty(len(placed), dtype=object)
    if whole.any():
        polys[whole] = shapely.polygons(pts[whole])
    for k in np.flatnonzero(sees & ~whole):
        kept = pts[k][finite[k]]
        polys[k] = Polygon(kept) if len(kept) >= 3 else Polygon()
    for k, i in enumerate(above):
        if sees[k]:
            out[i] = _valid_outline(polys[k], pts[k][finite[k]])
    return out


def _valid_outline(poly: Polygon, pts: np.ndarray) -> Polygon:
    """``poly`` itself when valid; an outline cut at the range limit can cross itself: then
    its polygonal parts, or the convex hull of the outline points ``pts`` (M, 2) when nothing
    polygonal survives the repair."""
    if poly.is_empty or poly.is_valid:
        return poly
    parts = [g for g in shapely.get_parts(shapely.make_valid(poly))
             if g.geom_type in ("Polygon", "MultiPolygon") and not g.is_empty]
    poly = shapely.unary_union(parts) if parts else shapely.MultiPoint(pts).convex_hull
    if poly.is_empty or poly.geom_type not in ("Polygon", "MultiPolygon"):
        poly = shapely.MultiPoint(pts).convex_hull
    return poly
