"""Ground projection of one frame onto a window of the mosaic grid (paper §5.1)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon

from clearfast_gis import kernels
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.geometry.pose import CameraPose
from clearfast_gis.geometry.projection import (
    frame_footprint,
    frame_footprints,
    ground_maps,
    incidence_angle_map,
)


@dataclass(frozen=True)
class Window:
    """A rectangular block of a grid: rows ``row0:row0+height``, cols ``col0:col0+width``."""

    row0: int
    col0: int
    height: int
    width: int

    @property
    def slices(self) -> tuple[slice, slice]:
        """(row slice, column slice) into the full grid."""
        return (slice(self.row0, self.row0 + self.height),
                slice(self.col0, self.col0 + self.width))


@dataclass
class ProjectedFrame:
    """A frame resampled onto a window of the mosaic grid.

    Attributes
    ----------
    values : float32 (B, h, w)
        Apparent temperature per band, degrees C; NaN where the frame does not see the cell.
    incidence_deg : float32 (h, w)
        Angle between the line of sight and the vertical (0 = nadir), degrees; NaN where
        unseen. The mosaic keeps, per cell, the frame that saw it closest to nadir.
    window : Window
        Where the block lies in the mosaic grid.
    """

    values: np.ndarray
    incidence_deg: np.ndarray
    window: Window

    @property
    def valid(self) -> np.ndarray:
        """Cells seen by the frame, bool (h, w)."""
        return np.isfinite(self.incidence_deg)


def footprint_window(footprint: Polygon, grid: GroundGrid, pad_px: int = 2) -> Window | None:
    """The smallest window of ``grid`` that contains ``footprint`` (None if disjoint)."""
    if footprint.is_empty:
        return None
    xmin, ymin, xmax, ymax = footprint.bounds
    ps = grid.pixel_size
    c0 = max(0, math.floor((xmin - grid.x0) / ps) - pad_px)
    c1 = min(grid.width, math.ceil((xmax - grid.x0) / ps) + pad_px)
    r0 = max(0, math.floor((grid.y0 - ymax) / ps) - pad_px)
    r1 = min(grid.height, math.ceil((grid.y0 - ymin) / ps) + pad_px)
    if c1 <= c0 or r1 <= r0:
        return None
    return Window(r0, c0, r1 - r0, c1 - c0)


def subgrid(grid: GroundGrid, window: Window) -> GroundGrid:
    """The grid of a window (same cell size and CRS)."""
    ps = grid.pixel_size
    return GroundGrid(grid.x0 + window.col0 * ps, grid.y0 - window.row0 * ps, ps,
                      window.width, window.height, grid.epsg)


def pixel_angle_rad(camera) -> float:
    """Angular size of one pixel at the frame centre, radians."""
    ifov = getattr(camera, "ifov_rad", None)
    return float(ifov) if ifov is not None else 1.0 / float(camera.fx)


def antialias_sigma_px(camera, pose: CameraPose, cell_m: float) -> float:
    """Gaussian sigma (frame pixels) that low-passes a frame to the mosaic cell size.

    Zero when the frame's ground pixel at its centre is already as large as a cell;
    otherwise half the ratio of the cell to the ground pixel, so resampling onto coarser
    cells averages instead of aliasing (the mosaic keeps the mean temperature of a cell).
    """
    return antialias_sigmas_px(camera, [pose], cell_m)[0]


def antialias_sigmas_px(camera, poses: Sequence[CameraPose], cell_m: float) -> list[float]:
    """:func:`antialias_sigma_px` of many frames (their centre rays in one computation)."""
    if not len(poses):
        return []
    centres = camera.ground_points_of_poses(np.array([(camera.width - 1) / 2.0]),
                                            np.array([(camera.height - 1) / 2.0]), poses)
    out = []
    for g, pose in zip(centres[:, 0], poses, strict=True):
        if not np.all(np.isfinite(g)):
            out.append(0.0)
            continue
        ground_px = float(np.linalg.norm(g - pose.position_m)) * pixel_angle_rad(camera)
        ratio = cell_m / ground_px
        out.append(0.5 * ratio if ratio > 1.2 else 0.0)
    return out


def resample(band: np.ndarray, map_x: np.ndarray, map_y: np.ndarray, sigma_px: float
             ) -> np.ndarray:
    """Bilinear samples of a frame at source-pixel maps, after a Gaussian low-pass.

    Parameters
    ----------
    band : float32 (H, W)
        One band of a frame, NaN = invalid.
    map_x, map_y : float32 (h, w)
        Source column and row of each cell (:func:`ground_maps`; -1 = not seen).
    sigma_px : float
        Gaussian sigma of the anti-alias filter, frame pixels (0: none).

    Returns
    -------
    float32 (h, w)
        NaN where the map points outside the frame. ``cv2`` (fast kernels) or scipy's
        ``gaussian_filter`` and ``map_coordinates`` (``--kernels reference``).
    """
    return kernels.kernel("resample")(band, map_x, map_y, sigma_px)


def project_frame(frame: np.ndarray, camera, pose: CameraPose, grid: GroundGrid,
                  max_incidence_deg: float = 85.0, antialias: bool = True,
                  footprint: Polygon | None = None, sigma_px: float | None = None,
                  ) -> ProjectedFrame | None:
    """Resample a frame onto the part of ``grid`` it sees.

    Parameters
    ----------
    frame : float32 (H, W) or (B, H, W)
        Apparent temperature, degrees C (NaN = invalid pixel).
    camera : EquiangularCamera or PinholeCamera
    pose : CameraPose
        Camera pose in the survey CRS (E, N, z above ground).
    grid : GroundGrid
        The mosaic grid.
    max_incidence_deg : float
        Cells seen at a more grazing angle are left out.
    antialias : bool
        Low-pass the frame to the cell size first (:func:`antialias_sigma_px`).
    footprint : Polygon, optional
        The frame's :func:`~clearfast_gis.geometry.projection.frame_footprint`, when it is
        already known (:func:`frame_geometry` computes a scan's frames at once).
    sigma_px : float, optional
        Its :func:`antialias_sigma_px`, likewise (used when ``antialias``).

    Returns
    -------
    ProjectedFrame or None
        None when the frame sees no cell of the grid.
    """
    stack = frame[None] if frame.ndim == 2 else frame
    if footprint is None:
        footprint = frame_footprint(camera, pose)
    window = footprint_window(footprint, grid)
    if window is None:
        return None
    sub = subgrid(grid, window)
    map_x, map_y = ground_maps(camera, pose, sub, bound=False)
    seen = map_x >= 0
    if not seen.any():
        return None
    values = np.empty((stack.shape[0], *sub.shape), dtype=np.float32)
    sigma = 0.0
    if antialias:
        sigma = antialias_sigma_px(camera, pose, grid.pixel_size) if sigma_px is None else sigma_px
    for b in range(stack.shape[0]):
        values[b] = resample(np.ascontiguousarray(stack[b], dtype=np.float32), map_x, map_y,
                             sigma)
    incidence = incidence_angle_map(pose, sub)
    keep = seen & (incidence <= max_incidence_deg) & np.all(np.isfinite(values), axis=0)
    unseen = np.where(keep, np.float32(1.0), np.float32(np.nan))
    values *= unseen  # NaN where not kept (faster than boolean-mask assignment)
    incidence = (incidence * unseen).astype(np.float32, copy=False)
    return ProjectedFrame(values, incidence, window)


def frame_geometry(camera, poses: Sequence[CameraPose], cell_m: float
                   ) -> tuple[list[Polygon], list[float]]:
    """The footprints and anti-alias sigmas (frame pixels) of many frames, for
    :func:`project_frame`: their rays computed together, a few milliseconds for a scan
    instead of a quarter of a millisecond a frame (the same values, bit for bit)."""
    poses = list(poses)
    return frame_footprints(camera, poses), antialias_sigmas_px(camera, poses, cell_m)
