"""The model object and measure of an anomaly (:mod:`clearfast_gis.thermal.measure`)."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.detection.features import AnomalyFeatures
from clearfast_gis.minetypes import MINE_TYPES
from clearfast_gis.thermal.measure import TYPE_SIZE_RATIO, anomaly_measure
from clearfast_gis.thermal.table import DEFAULT_HEIGHT_M

CELL_M = 0.02


def feature(diameter_m: float, blob_diameter_m: float) -> AnomalyFeatures:
    """A round anomaly of that half-maximum footprint and detector blob, 2 cm cells."""
    n = 6
    return AnomalyFeatures(
        id=1, row=0.0, col=0.0, x=0.0, y=0.0, area_px=1, area_m2=0.0,
        diameter_px=diameter_m / CELL_M, diameter_m=diameter_m, circularity=1.0,
        axis_ratio=1.0, compactness=1.0, polarity_per_scan=np.ones(n, dtype=int),
        polarity="warm", n_scans=n, centre_k=np.zeros(n), ring_k=np.zeros(n),
        contrast_k=np.zeros(n), noise_k=np.full(n, 0.02), score=10.0,
        blob_diameter_px=blob_diameter_m / CELL_M)


def test_a_mine_sized_footprint_is_the_type_against_its_blobs_ring():
    ap = MINE_TYPES[0]
    m = anomaly_measure(feature(0.10, 0.16))
    assert m.kind == ap
    assert (m.radius_m, m.height_m, m.over_m) == pytest.approx((ap.radius_m, ap.height_m, 0.05))
    # ring at 1.5-2.5 blob radii (8 cm): 12-20 cm
    assert m.ring_m == pytest.approx((0.12, 0.20))


def test_a_small_blob_keeps_a_ring_beyond_it():
    m = anomaly_measure(feature(0.10, 0.04))
    # blob radius 1 cell: ring from 1 + 1 to 2 + 2 cells
    assert m.ring_m == pytest.approx((0.04, 0.08))


def test_a_footprint_much_smaller_than_its_type_is_its_own_cylinder():
    ap, at = MINE_TYPES[0], MINE_TYPES[1]
    # larger than the AP type (heat spreads over a deep mine): still the AP type
    assert anomaly_measure(feature(1.7 * ap.diameter_m, 0.2)).kind == ap
    assert anomaly_measure(feature(ap.diameter_m / (0.99 * TYPE_SIZE_RATIO), 0.1)).kind == ap
    assert anomaly_measure(feature(at.diameter_m / (0.99 * TYPE_SIZE_RATIO), 0.3)).kind == at
    for d in (0.2, at.diameter_m / (1.01 * TYPE_SIZE_RATIO), ap.diameter_m / 1.4):
        m = anomaly_measure(feature(d, d))
        assert m.kind is None
        assert (m.radius_m, m.height_m, m.over_m) == pytest.approx((d / 2, DEFAULT_HEIGHT_M,
                                                                     d / 2))
