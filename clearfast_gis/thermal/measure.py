"""The object the thermal model takes an anomaly for, and how the chain measured its contrast.

The chain measures each anomaly's contrast as the mean over its half-maximum footprint minus
the mean over a background ring around its blob (:mod:`clearfast_gis.detection.features`),
on mosaics blurred by the camera's pixels and the mosaic cells (:mod:`clearfast_gis.mosaic.blur`)
and in apparent temperature (:mod:`clearfast_gis.thermal.apparent`). The model's object is the
expected mine type nearest the footprint's size (:func:`clearfast_gis.minetypes.nearest_mine_type`),
not a cylinder of the footprint's size: over a shallow mine the footprint is smaller than the
casing, over a deep one larger (docs/thermal.md, "The object and the measure"). A footprint
more than :data:`TYPE_SIZE_RATIO` times smaller than the nearest type is no mine of that type
as the camera sees one (clutter between the types' sizes): it is modelled as a cylinder of its
own footprint's size, as before the types were modelled. A larger footprint keeps its type:
heat spreads over a deep mine.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from clearfast_gis.detection.features import AnomalyFeatures, ring_radii_px
from clearfast_gis.minetypes import MineType, nearest_mine_type
from clearfast_gis.thermal.table import DEFAULT_HEIGHT_M

TYPE_SIZE_RATIO = 1.3
"""Largest ratio of the nearest mine type's diameter to an anomaly's footprint diameter for
the type to be its model object: the half-maximum footprints of the mines at 0-3 cm on the
demo and conditions surveys were 0.94-1.10 times the AP type's and 0.98-1.00 times the AT
type's (5 cm AP mines up to 1.8 times); clutter of 18-25 cm, nearest the AT type, had been
fitted as an AT mine with status ``ok``."""


@dataclass(frozen=True)
class Measure:
    """An anomaly's model object and measure: ``kind`` (the mine type; None for a cylinder of
    the footprint's size), ``radius_m`` and ``height_m`` (the model object's, m), ``over_m``
    (radius of the footprint the centre was averaged over, m), ``ring_m`` (inner, outer
    radius of the background ring, m)."""

    kind: MineType | None
    radius_m: float
    height_m: float
    over_m: float
    ring_m: tuple[float, float]


def anomaly_measure(feature: AnomalyFeatures, max_ratio: float = TYPE_SIZE_RATIO) -> Measure:
    """The :class:`Measure` of one anomaly from its features: the nearest mine type unless
    the footprint's diameter is more than ``max_ratio`` times smaller (then a cylinder of the
    footprint's radius and :data:`~clearfast_gis.thermal.table.DEFAULT_HEIGHT_M`), the
    footprint's radius ``diameter_m / 2``, the ring's radii from the blob's equivalent radius
    (:func:`~clearfast_gis.detection.features.ring_radii_px`) times the cell size
    ``diameter_m / diameter_px`` (m)."""
    over = 0.5 * float(feature.diameter_m)
    cell = float(feature.diameter_m) / float(feature.diameter_px) \
        if feature.diameter_px > 0 else float("nan")
    r_eq = 0.5 * float(feature.blob_diameter_px)
    if not (np.isfinite(r_eq) and r_eq > 0):
        r_eq = 0.5 * float(feature.diameter_px)
    r_in, r_out = ring_radii_px(r_eq)
    ring = (r_in * cell, r_out * cell)
    kind = nearest_mine_type(float(feature.diameter_m))
    if over > 0 and 2.0 * over * max_ratio >= kind.diameter_m:
        return Measure(kind, kind.radius_m, kind.height_m, over, ring)
    return Measure(None, over, DEFAULT_HEIGHT_M, over, ring)
