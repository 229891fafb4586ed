"""The ground truth grid: per-cell surface classes, moisture and object footprints.

The scene lives on a fine square grid in the survey CRS (the "truth grid", 1-3 cm cells, finer
than the camera's footprint at range). Background soil is a mixture of a dry and a moist soil
with a smooth random moisture fraction; vegetation and disturbed-soil patches and marker plates
are soft-edged cover fractions; mines, stones and debris are disc footprints that the thermal
runs fill with radial temperature profiles.
"""

from __future__ import annotations

from dataclasses import dataclass

import cv2
import numpy as np
from scipy import ndimage

from clearfast_gis.simulate.objects import SceneObject

#: Kinds whose surface temperature comes from an axisymmetric thermal run.
THERMAL_OBJECT_KINDS = ("at_mine", "ap_mine", "stone", "metal")

#: Lateral reach of an object's thermal footprint beyond its radius, metres.
FOOTPRINT_MARGIN_M = 0.2


@dataclass(frozen=True)
class GridSpec:
    """A north-up square grid: (x0, y0) upper-left corner, ``pixel_size`` metres per cell."""

    x0: float
    y0: float
    pixel_size: float
    width: int
    height: int
    epsg: int

    def cell_centres(self) -> tuple[np.ndarray, np.ndarray]:
        """Cell-centre coordinates: x (W,) and y (H,), metres in the grid's CRS."""
        x = self.x0 + (np.arange(self.width) + 0.5) * self.pixel_size
        y = self.y0 - (np.arange(self.height) + 0.5) * self.pixel_size
        return x, y


@dataclass(frozen=True)
class Footprint:
    """Cells an object affects: flat indices into the grid and their distance to its centre."""

    obj: SceneObject
    index: np.ndarray  # (K,) int64 flat cell indices
    r_m: np.ndarray  # (K,) float32 distance to the centre, metres


@dataclass
class SceneFields:
    """Per-cell fields of the scene, all (H, W) float32 on ``grid``.

    moisture : fraction of the moist soil end-member (0-1) in the background soil
    vegetation, disturbed : cover fractions (0-1) of vegetation and disturbed-soil patches
    marker_hot, marker_cold : cover fractions of the two marker plate kinds
    footprints : the thermal objects' footprints
    """

    grid: GridSpec
    moisture: np.ndarray
    vegetation: np.ndarray
    disturbed: np.ndarray
    marker_hot: np.ndarray
    marker_cold: np.ndarray
    footprints: list[Footprint]


def smooth_random_field(shape: tuple[int, int], cell_m: float, scale_m: float,
                        rng: np.random.Generator) -> np.ndarray:
    """A smooth random field with unit standard deviation and correlation length ``scale_m``.

    White noise on a coarse grid (scale/4 cells) is Gaussian-filtered and resized bilinearly to
    ``shape`` (H, W). Cost is independent of the fine grid's size.
    """
    coarse_cell = max(scale_m / 4.0, cell_m)
    ch = max(4, int(np.ceil(shape[0] * cell_m / coarse_cell)) + 1)
    cw = max(4, int(np.ceil(shape[1] * cell_m / coarse_cell)) + 1)
    noise = rng.standard_normal((ch, cw))
    field = ndimage.gaussian_filter(noise, sigma=scale_m / coarse_cell / 2.0, mode="wrap")
    field = (field - field.mean()) / (field.std() + 1e-12)
    return cv2.resize(field.astype(np.float32), (shape[1], shape[0]),
                      interpolation=cv2.INTER_LINEAR)


def _ellipse_cover(xx: np.ndarray, yy: np.ndarray, obj: SceneObject, x_c: float, y_c: float,
                   edge: np.ndarray, soft_m: float) -> np.ndarray:
    """Soft-edged elliptic cover fraction of a patch, with a wavy boundary from ``edge``."""
    a = obj.radius_m / np.sqrt(obj.aspect)
    b = obj.radius_m * np.sqrt(obj.aspect)
    t = np.deg2rad(obj.angle_deg)
    dx, dy = xx - x_c, yy - y_c
    u = dx * np.cos(t) + dy * np.sin(t)
    v = -dx * np.sin(t) + dy * np.cos(t)
    rho = np.sqrt((u / a) ** 2 + (v / b) ** 2)
    dist_m = (rho - 1.0 - 0.15 * edge) * np.sqrt(a * b)
    return np.clip(0.5 - dist_m / soft_m, 0.0, 1.0).astype(np.float32)


def _box_cover(xx: np.ndarray, yy: np.ndarray, x_c: float, y_c: float, half_m: float,
               cell_m: float) -> np.ndarray:
    """Fraction of each cell (centres ``xx``, ``yy``, metres) covered by the square plate of
    half-side ``half_m`` centred on (``x_c``, ``y_c``).

    Exact area coverage: the plate's cover-weighted centroid is its centre whatever the plate's
    position on the grid (a test of cell centres against the edges would take or leave a whole
    row of cells when an edge falls on a row of centres, moving the plate by half a cell).
    """
    def overlap(c: np.ndarray, centre: float) -> np.ndarray:
        lo = np.maximum(c - 0.5 * cell_m, centre - half_m)
        hi = np.minimum(c + 0.5 * cell_m, centre + half_m)
        return np.clip((hi - lo) / cell_m, 0.0, 1.0)

    return (overlap(xx, x_c) * overlap(yy, y_c)).astype(np.float32)


def build_scene(grid: GridSpec, objects: list[SceneObject], origin_m: tuple[float, float],
                rng: np.random.Generator) -> SceneFields:
    """Rasterise the scene's objects and draw the moisture field.

    Parameters
    ----------
    grid : GridSpec
        The truth grid (survey CRS).
    objects : list of SceneObject
        Objects in local metres.
    origin_m : (float, float)
        Survey-CRS coordinates of the local origin (the area's south-west corner), metres.
    rng : numpy.random.Generator
        The survey's generator (moisture field, patch edges).

    Returns
    -------
    SceneFields
    """
    shape = (grid.height, grid.width)
    ps = grid.pixel_size
    moisture = 0.5 + 0.17 * smooth_random_field(shape, ps, 2.5, rng)
    moisture = np.clip(moisture, 0.1, 0.9).astype(np.float32)
    edge = smooth_random_field(shape, ps, 0.15, rng)
    xs, ys = grid.cell_centres()
    zeros = np.zeros(shape, np.float32)
    fields = SceneFields(grid, moisture, zeros.copy(), zeros.copy(), zeros.copy(), zeros.copy(),
                         [])
    ox, oy = origin_m
    for obj in objects:
        xc, yc = obj.x_m + ox, obj.y_m + oy
        reach = obj.radius_m / min(obj.aspect, 1.0) + FOOTPRINT_MARGIN_M
        c0 = max(0, int(np.floor((xc - reach - grid.x0) / ps)))
        c1 = min(grid.width, int(np.ceil((xc + reach - grid.x0) / ps)) + 1)
        r0 = max(0, int(np.floor((grid.y0 - (yc + reach)) / ps)))
        r1 = min(grid.height, int(np.ceil((grid.y0 - (yc - reach)) / ps)) + 1)
        if c0 >= c1 or r0 >= r1:
            continue
        xx, yy = np.meshgrid(xs[c0:c1], ys[r0:r1])
        win = (slice(r0, r1), slice(c0, c1))
        if obj.kind in ("vegetation", "disturbed_soil"):
            cover = _ellipse_cover(xx, yy, obj, xc, yc, edge[win], soft_m=2.0 * ps)
            target = fields.vegetation if obj.kind == "vegetation" else fields.disturbed
            target[win] = np.maximum(target[win], cover)
        elif obj.kind == "marker":
            cover = _box_cover(xx, yy, xc, yc, obj.radius_m, ps)
            target = fields.marker_hot if obj.variant != "cold" else fields.marker_cold
            target[win] = np.maximum(target[win], cover)
        else:
            r = np.hypot(xx - xc, yy - yc)
            keep = r <= obj.radius_m + FOOTPRINT_MARGIN_M
            rows, cols = np.nonzero(keep)
            index = (rows + r0) * grid.width + (cols + c0)
            fields.footprints.append(Footprint(obj, index.astype(np.int64),
                                               r[keep].astype(np.float32)))
    # patches and plates exclude each other in the order plate > vegetation > disturbed soil
    plates = np.clip(fields.marker_hot + fields.marker_cold, 0.0, 1.0)
    fields.vegetation *= 1.0 - plates
    fields.disturbed *= 1.0 - plates - fields.vegetation
    np.clip(fields.disturbed, 0.0, 1.0, out=fields.disturbed)
    return fields
