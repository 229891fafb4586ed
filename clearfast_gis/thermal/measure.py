"""The object the thermal model takes an anomaly for, and how the chain measured its contrast.

The chain measures each anomaly's contrast as the mean over its half-maximum footprint minus
the mean over a background ring around its blob (:mod:`clearfast_gis.detection.features`),
on mosaics blurred by the camera's pixels and the mosaic cells (:mod:`clearfast_gis.mosaic.blur`)
and in apparent temperature (:mod:`clearfast_gis.thermal.apparent`). The model's object is the
expected mine type nearest the footprint's size (:func:`clearfast_gis.minetypes.nearest_mine_type`),
not a cylinder of the footprint's size: over a shallow mine the footprint is smaller than the
casing, over a deep one larger (docs/thermal.md, "The object and the measure").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from clearfast_gis.detection.features import AnomalyFeatures, ring_radii_px
from clearfast_gis.minetypes import MineType, nearest_mine_type


@dataclass(frozen=True)
class Measure:
    """An anomaly's model object and measure: ``kind`` (the mine type), ``over_m`` (radius of
    the footprint the centre was averaged over, m), ``ring_m`` (inner, outer radius of the
    background ring, m)."""

    kind: MineType
    over_m: float
    ring_m: tuple[float, float]


def anomaly_measure(feature: AnomalyFeatures) -> Measure:
    """The :class:`Measure` of one anomaly from its features: the footprint's radius
    ``diameter_m / 2``, the ring's radii from the blob's equivalent radius
    (:func:`~clearfast_gis.detection.features.ring_radii_px`) times the cell size
    ``diameter_m / diameter_px`` (m)."""
    over = 0.5 * float(feature.diameter_m)
    cell = float(feature.diameter_m) / float(feature.diameter_px) \
        if feature.diameter_px > 0 else float("nan")
    r_eq = 0.5 * float(feature.blob_diameter_px)
    if not (np.isfinite(r_eq) and r_eq > 0):
        r_eq = 0.5 * float(feature.diameter_px)
    r_in, r_out = ring_radii_px(r_eq)
    return Measure(nearest_mine_type(float(feature.diameter_m)), over,
                   (r_in * cell, r_out * cell))
