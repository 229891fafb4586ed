"""Suspected-hazard polygon proposals around clusters of mine indications, and geometry checks.

A thermal anomaly is indirect evidence: the polygons proposed here are *suspected* hazardous
areas (IMAS 07.11) for a mine action centre to review, never confirmed ones. Each proposal is
the union of discs of radius ``buffer_m`` around the mine indications of one cluster; two
indications belong to one cluster when their discs overlap (they are less than ``2 * buffer_m``
apart), so the clusters are the connected parts of the union. Everything is computed in the
survey's UTM CRS (metres).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from clearfast_gis.errors import InvalidInput

DEFAULT_BUFFER_M = 5.0
"""Radius of the disc around each mine indication, metres (docs/mine_action.md says why)."""

QUAD_SEGMENTS = 8
"""Segments per quarter circle of the buffer discs (a 32-gon per disc)."""

MAX_FIELD_NAME = 31
"""Longest field name a file geodatabase (IMSMA Core, ArcGIS) accepts."""


def hazard_clusters(easting_m: Sequence[float], northing_m: Sequence[float],
                    buffer_m: float = DEFAULT_BUFFER_M):
    """Group mine indications into proposed suspected-hazard polygons.

    Parameters
    ----------
    easting_m, northing_m : sequence of float, shape (N,)
        Positions of the mine indications in the survey's UTM CRS, metres.
    buffer_m : float
        Disc radius around each indication, metres (> 0).

    Returns
    -------
    list of (shapely.Polygon, list of int)
        One entry per cluster: its polygon (UTM) and the indices of its indications, ordered
        north to south, then west to east by the polygon's centroid (stable ids follow it).
    """
    import shapely

    if not (np.isfinite(buffer_m) and buffer_m > 0):
        raise ValueError("buffer_m must be a positive number of metres")
    e = np.asarray(easting_m, np.float64)
    n = np.asarray(northing_m, np.float64)
    if e.size == 0:
        return []
    points = shapely.points(e, n)
    union = shapely.union_all(shapely.buffer(points, buffer_m, quad_segs=QUAD_SEGMENTS))
    parts = list(getattr(union, "geoms", [union]))
    clusters = [(part, np.flatnonzero(shapely.covers(part, points)).tolist())
                for part in parts]
    clusters.sort(key=lambda c: (-round(c[0].centroid.y, 2), round(c[0].centroid.x, 2)))
    return clusters


def clean_polygon(polygon):
    """The polygon without repeated consecutive vertices (e.g. after rounding)."""
    import shapely

    return shapely.remove_repeated_points(polygon, tolerance=0.0)


def check_geometries(geometries, ids: Sequence[str], path, layer: str) -> None:
    """Raise :class:`InvalidInput` unless every geometry is fit for a mine action database.

    Points: finite coordinates. Polygons: valid (OGC), an exterior ring of at least 3 distinct
    vertices, no repeated vertex (the closing vertex aside). The error names the file, the
    layer and the record's ``imsma_id``.
    """
    import shapely

    for geom, rid in zip(geometries, ids, strict=True):
        where = f"{layer}.{rid}"
        if geom is None or geom.is_empty:
            raise InvalidInput("empty geometry", path, where)
        coords = shapely.get_coordinates(geom)
        if not np.all(np.isfinite(coords)):
            raise InvalidInput("non-finite coordinate", path, where)
        if geom.geom_type == "Point":
            continue
        for poly in getattr(geom, "geoms", [geom]):
            for ring in (poly.exterior, *poly.interiors):
                vertices = np.asarray(ring.coords)[:-1]
                distinct = len(np.unique(vertices, axis=0))
                if distinct < 3:
                    raise InvalidInput("a ring with fewer than 3 vertices", path, where)
                if distinct != len(vertices):
                    raise InvalidInput("a repeated vertex", path, where)
        if not geom.is_valid:
            raise InvalidInput(f"invalid polygon ({shapely.is_valid_reason(geom)})", path, where)


def check_field_names(names: Sequence[str], path, layer: str) -> None:
    """Raise :class:`InvalidInput` for a field name a geodatabase would refuse or truncate."""
    for name in names:
        if len(name) > MAX_FIELD_NAME or not name.isidentifier() or name != name.lower():
            raise InvalidInput(f"field name longer than {MAX_FIELD_NAME} characters or not "
                               "lower-case snake_case", path, f"{layer}.{name}")
