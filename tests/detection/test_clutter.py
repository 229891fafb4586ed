"""Background clutter of mosaics against images of known noise."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

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


def test_the_same_on_one_thread_as_on_several(monkeypatch):
    """The scans are measured on threads and combined in scan order: the bits do not depend
    on the thread count."""
    rng = np.random.default_rng(2)
    stack = rng.standard_normal((6, 90, 110)).astype(np.float32)
    stack[2, :, :30] = np.nan
    stack[4] = np.nan  # a scan that saw nothing
    labels = np.zeros(stack.shape[1:], int)
    labels[20:40, 50:70] = 3
    monkeypatch.setenv("CLEARFAST_THREADS", "1")
    one = background_clutter_k(stack, labels, 0.02)
    monkeypatch.setenv("CLEARFAST_THREADS", "3")
    assert background_clutter_k(stack, labels, 0.02) == one
    reference = np.median([1.4826 * np.median(np.abs(v - np.median(v))) for v in (
        (s - ndimage.uniform_filter(np.where(np.isfinite(s), s, np.nanmedian(s)), size=15,
                                        mode="nearest"))[
            np.isfinite(s) & (labels == 0)] for s in stack.astype(np.float64)
        if np.isfinite(s).any())])
    assert one == reference


def test_image_clutter_is_the_mad_of_the_high_pass_to_the_last_bit():
    """In-place selections give the very medians of the definition: 1.4826 MAD of the image
    (no-data filled with its median) minus its 15-cell box mean, over the kept cells."""
    from clearfast_gis.detection.clutter import image_clutter_k

    rng = np.random.default_rng(5)
    img = (20.0 + ndimage.gaussian_filter(rng.standard_normal((120, 150)), 3.0)
           + 0.05 * rng.standard_normal((120, 150))).astype(np.float32)
    img[:10, :40] = np.nan
    keep = rng.random(img.shape) > 0.1
    for k in (None, keep):
        x = img.astype(np.float64)
        ok = np.isfinite(x) if k is None else np.isfinite(x) & k
        filled = np.where(np.isfinite(x), x, np.median(x[np.isfinite(x)]))
        v = (filled - ndimage.uniform_filter(filled, size=15, mode="nearest"))[ok]
        expected = float(1.4826 * np.median(np.abs(v - np.median(v))))
        assert image_clutter_k(img, 0.02, k) == expected
        assert 0.01 < expected < 1.0


def test_background_levels_without_the_clutter():
    from clearfast_gis.detection.clutter import background_levels

    rng = np.random.default_rng(8)
    stack = rng.normal(20.0, 0.5, (3, 1, 60, 70)).astype(np.float32)
    labels = np.zeros((60, 70), dtype=np.int32)
    labels[10:20, 10:20] = 1
    levels, clutter = background_levels(stack, labels, 0.02)
    only, none = background_levels(stack, labels, 0.02, clutter=False)
    assert np.array_equal(levels, only) and np.isfinite(clutter) and np.isnan(none)
