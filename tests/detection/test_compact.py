"""Mines on warm patches and mines seen by part of the scans: recovered positions and sizes."""

from __future__ import annotations

import numpy as np
from affine import Affine

from clearfast_gis.detection.compact import compact_contrast, split_oversized
from clearfast_gis.detection.voting import detect_on_mosaics

PIXEL_M = 0.02
SHAPE = (200, 200)
TRANSFORM = Affine(PIXEL_M, 0.0, 500000.0, 0.0, -PIXEL_M, 4000000.0)


def _disc(row: float, col: float, diameter_px: float) -> np.ndarray:
    rr, cc = np.mgrid[0:SHAPE[0], 0:SHAPE[1]]
    return ((rr - row) ** 2 + (cc - col) ** 2 <= (diameter_px / 2) ** 2).astype(np.float32)


def _diurnal_stack(n: int, objects: list[tuple[float, float, float, float]], seed: int = 0,
                   dome: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """(N, 1, H, W) scans over a day: ground texture (0.3 K, correlated over ~0.6 m) whose
    contrast follows the sun, each object (row, col, diameter px, amplitude K) warm by day and
    cool by night, 0.03 K noise; an optional smooth warm dome (1.4 m wide) in the middle."""
    from scipy import ndimage

    rng = np.random.default_rng(seed)
    texture = ndimage.gaussian_filter(rng.standard_normal(SHAPE), 15.0).astype(np.float32)
    texture *= np.float32(0.3 / texture.std())
    times = 1.7e9 + np.arange(n) * 86400.0 / n
    phase = np.cos(2 * np.pi * (np.arange(n) / n - 0.5))  # +1 at noon, -1 at midnight
    rr, cc = np.mgrid[0:SHAPE[0], 0:SHAPE[1]]
    hump = np.exp(-((rr - 100) ** 2 + (cc - 100) ** 2) / (2 * 35.0**2)).astype(np.float32)
    stack = np.empty((n, 1, *SHAPE), dtype=np.float32)
    for i in range(n):
        img = 20.0 + (1.0 + 0.5 * phase[i]) * texture
        img += 0.03 * rng.standard_normal(SHAPE).astype(np.float32)
        img += dome * (1.0 + 0.5 * phase[i]) * hump
        for row, col, diameter, amp in objects:
            img += amp * phase[i] * _disc(row, col, diameter)
        stack[i, 0] = img
    return stack, times


def _detect(stack: np.ndarray, times: np.ndarray):
    return detect_on_mosaics(stack, times, TRANSFORM, PIXEL_M, 0.0, d1_m=0.5, d2_m=0.06,
                             epsilon=0.01, level=None, gamma=None, max_anomalies=50,
                             level_fraction=0.25, gamma_fraction=0.25)


def _nearest(feats, row: float, col: float):
    return min(feats, key=lambda f: np.hypot(f.row - row, f.col - col))


def test_compact_contrast_sees_the_disc_not_the_dome():
    stack, _ = _diurnal_stack(12, [(118.0, 100.0, 5.0, 0.8)], dome=2.0)
    c = compact_contrast(stack[:, 0], d1_px=25)
    assert c[118, 100] > 6.0
    # the dome's cap (20 px from the disc) responds at the noise level
    assert c[95, 100] < 3.0


def test_a_mine_on_a_warm_patch_gets_its_own_anomaly():
    stack, times = _diurnal_stack(16, [(118.0, 100.0, 5.0, 0.8)], dome=2.0)
    labels, feats = _detect(stack, times)
    f = _nearest(feats, 118.0, 100.0)
    assert np.hypot(f.row - 118.0, f.col - 100.0) < 1.0
    assert abs(f.diameter_px - 5.0) < 1.5
    # the split itself: one oversized blob, the compact object relabelled out of it
    blob = np.zeros(SHAPE, dtype=np.int32)
    blob[80:125, 80:120] = 1
    out = split_oversized(blob, stack[:, 0], 25, 3, 25)
    assert out[118, 100] not in (0, 1)
    assert out[90, 100] == 1
    assert set(np.unique(out)) == {0, 1, int(out[118, 100])}


def test_a_mine_left_out_of_most_scans_is_still_found():
    """A drifting platform (paper §6) sees a corner of the site in a few scans only."""
    n = 24
    stack, times = _diurnal_stack(n, [(50.0, 50.0, 5.0, 0.6), (150.0, 150.0, 16.0, 0.8)])
    # the left third of the site is seen by scans 0-6 only
    stack[7:, :, :, :70] = np.nan
    labels, feats = _detect(stack, times)
    for row, col, diameter in ((50.0, 50.0, 5.0), (150.0, 150.0, 16.0)):
        f = _nearest(feats, row, col)
        assert np.hypot(f.row - row, f.col - col) < 1.0, (row, col, f.row, f.col)
        assert abs(f.diameter_px - diameter) < 0.2 * diameter + 1.0
        assert f.score > 3.0
    # with one level for the whole stack (the paper's l over all images) it is lost
    from clearfast_gis.detection.voting import detect_on_mosaics as det

    _, fixed = det(stack, times, TRANSFORM, PIXEL_M, 0.0, 0.5, 0.06, 0.01, level=12,
                   gamma=None, max_anomalies=50)
    assert all(np.hypot(f.row - 50.0, f.col - 50.0) > 3.0 for f in fixed)


def test_object_inside_its_patch_is_measured_against_the_patch():
    """A compact object split from a warm patch has no free ring pixel: its contrast is
    taken against the patch around it (it was NaN in every scan, p_mine at the bottom)."""
    from clearfast_gis.detection.features import blob_features

    labels = np.zeros((60, 60), np.int32)
    yy, xx = np.mgrid[:60, :60]
    labels[(yy - 30) ** 2 + (xx - 30) ** 2 <= 20 ** 2] = 1  # the patch
    labels[(yy - 30) ** 2 + (xx - 30) ** 2 <= 3 ** 2] = 2  # the object inside it
    stack = np.full((4, 60, 60), 20.0, np.float32)
    stack[:, labels == 1] += 1.0  # the patch 1 K warm
    stack[:, labels == 2] += np.array([1.5, 1.2, 0.8, 1.4], np.float32)[:, None]
    stack[:, labels == 1] += 0.01 * np.random.default_rng(0).standard_normal(
        (4, int((labels == 1).sum()))).astype(np.float32)
    feats = {f.id: f for f in blob_features(labels, stack, pixel_size_m=0.02)}
    np.testing.assert_allclose(feats[2].contrast_k, [0.5, 0.2, -0.2, 0.4], atol=0.02)
    assert feats[2].score > 0
    # a blob with a free ring keeps it: the patch against the soil outside
    np.testing.assert_allclose(feats[1].ring_k, 20.0, atol=1e-6)
