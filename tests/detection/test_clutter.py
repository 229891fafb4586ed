"""Background clutter of mosaics against images of known noise."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.detection.clutter import background_clutter_k


def test_white_noise_is_measured_and_smooth_trends_are_not():
    rng = np.random.default_rng(0)
    yy, xx = np.mgrid[0:200, 0:200]
    trend = 3.0 * np.sin(xx / 60.0) + 0.02 * yy  # kelvins over metres: not clutter
    stack = np.stack([trend + 0.1 * rng.standard_normal(trend.shape) for _ in range(4)])
    labels = np.zeros(trend.shape, int)
    assert background_clutter_k(stack, labels, 0.02) == pytest.approx(0.1, rel=0.1)


def test_anomalies_and_outside_cells_are_left_out():
    rng = np.random.default_rng(1)
    img = 0.05 * rng.standard_normal((120, 120))
    img[40:60, 40:60] += 5.0  # a hot object, labelled
    img[:, :20] = np.nan  # outside the footprint
    labels = np.zeros(img.shape, int)
    labels[35:65, 35:65] = 1
    est = background_clutter_k(img[None], labels, 0.02)
    assert est == pytest.approx(0.05, rel=0.15)
    assert np.isnan(background_clutter_k(np.full((2, 10, 10), np.nan), labels[:10, :10], 0.02))
