"""The mosaic's ground grid: the union of the frames' footprints, snapped to the pixel size."""

from __future__ import annotations

import math
from collections.abc import Iterable

import shapely
from shapely.geometry import Polygon

from clearfast_gis.geometry.grid import GroundGrid


def mosaic_grid(footprints: Iterable[Polygon], pixel_size_m: float, epsg: int | None,
                clip_to: tuple[float, float, float, float] | None = None,
                margin_m: float = 0.0) -> GroundGrid:
    """The north-up grid that covers the frames' ground footprints.

    Parameters
    ----------
    footprints : iterable of shapely Polygon
        Ground outlines of the frames, survey CRS metres.
    pixel_size_m : float
        Mosaic cell size, metres.
    epsg : int or None
        Survey CRS.
    clip_to : (xmin, ymin, xmax, ymax), optional
        Limit the grid to this rectangle (e.g. the planned area plus a margin).
    margin_m : float
        Extra border around the union, metres.

    Returns
    -------
    GroundGrid
        Corner snapped to whole multiples of the pixel size, so mosaics of different scans of
        one survey share the grid exactly.
    """
    union = shapely.unary_union([f for f in footprints if not f.is_empty])
    if union.is_empty:
        raise ValueError("no frame sees the ground")
    xmin, ymin, xmax, ymax = union.bounds
    if clip_to is not None:
        xmin, ymin = max(xmin, clip_to[0]), max(ymin, clip_to[1])
        xmax, ymax = min(xmax, clip_to[2]), min(ymax, clip_to[3])
        if not (xmax > xmin and ymax > ymin):
            raise ValueError("the frames do not overlap the requested area")
    ps = float(pixel_size_m)
    x0 = math.floor((xmin - margin_m) / ps) * ps
    y1 = math.floor((ymin - margin_m) / ps) * ps
    x1 = math.ceil((xmax + margin_m) / ps) * ps
    y0 = math.ceil((ymax + margin_m) / ps) * ps
    return GroundGrid.from_bounds(x0, y1, x1, y0, ps, epsg)
