"""Known surveyed markers among the detected anomalies and in the mosaics (a check of the
georeferencing)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from clearfast_gis.detection.features import AnomalyFeatures
from clearfast_gis.detection.stack import as_scan_stack, map_scans


@dataclass(frozen=True)
class MarkerMatch:
    """A known marker found among the anomalies (a check of the georeferencing).

    Attributes
    ----------
    marker_id : str
    x, y : float
        Surveyed position, survey CRS metres.
    found_x, found_y : float
        Centroid of the matching anomaly, survey CRS metres.
    """

    marker_id: str
    x: float
    y: float
    found_x: float
    found_y: float

    @property
    def offset_m(self) -> float:
        """Distance between the surveyed and the found position, metres."""
        return math.hypot(self.found_x - self.x, self.found_y - self.y)


def split_markers(features: list[AnomalyFeatures], marker_ids: list[str],
                  marker_xy: np.ndarray, radius_m: float = 0.3
                  ) -> tuple[list[AnomalyFeatures], list[MarkerMatch]]:
    """Separate anomalies that are known surveyed markers from the suspects.

    Parameters
    ----------
    features : list of AnomalyFeatures
    marker_ids : list of str
    marker_xy : float (M, 2)
        Surveyed marker positions, survey CRS metres.
    radius_m : float
        An anomaly whose centroid lies this close to a marker is that marker.

    Returns
    -------
    suspects : list of AnomalyFeatures
        The anomalies that are not markers.
    matches : list of MarkerMatch
        The nearest anomaly of each marker found.
    """
    if len(marker_ids) == 0 or not features:
        return features, []
    fx = np.array([f.x for f in features])
    fy = np.array([f.y for f in features])
    d = np.hypot(fx[:, None] - marker_xy[None, :, 0], fy[:, None] - marker_xy[None, :, 1])
    is_marker = d.min(axis=1) <= radius_m
    matches = []
    for j, mid in enumerate(marker_ids):
        i = int(np.argmin(d[:, j]))
        if d[i, j] <= radius_m:
            matches.append(MarkerMatch(str(mid), float(marker_xy[j, 0]), float(marker_xy[j, 1]),
                                       float(fx[i]), float(fy[i])))
    return [f for f, m in zip(features, is_marker, strict=True) if not m], matches


def markers_in_mosaics(stack_c, grid, marker_ids: list[str],
                       marker_xy: np.ndarray) -> list[MarkerMatch]:
    """Where each surveyed marker appears in the mosaics: the median over the scans of its
    contrast-weighted centroid (:func:`clearfast_gis.mosaic.markers.locate_marker`).

    Parameters
    ----------
    stack_c : ScanStack or float32 (N, B, H, W)
        Mosaics, degrees C (band 0 searched; read scan by scan,
        :mod:`clearfast_gis.detection.stack`).
    grid : GroundGrid
    marker_ids : list of str
    marker_xy : float (M, 2)
        Surveyed positions, survey CRS metres.
    """
    from clearfast_gis.mosaic.markers import locate_marker

    if len(marker_ids) == 0:
        return []
    points = [(float(x), float(y)) for x, y in marker_xy]
    found: list[list] = [[] for _ in points]
    for per_marker in map_scans(lambda _, bands: [locate_marker(bands[0], grid, x, y)
                                                  for x, y in points], as_scan_stack(stack_c)):
        for where, p in zip(found, per_marker, strict=True):
            if p is not None:
                where.append(p)
    out = []
    for mid, (x, y), where in zip(marker_ids, points, found, strict=True):
        if where:
            fx, fy = np.median(np.array(where), axis=0)
            out.append(MarkerMatch(str(mid), x, y, float(fx), float(fy)))
    return out
