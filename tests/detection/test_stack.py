"""The detector and what follows it read the mosaics scan by scan: the same bits as on the
stack in memory, and memory that does not grow with the scans beyond a few bits a pixel."""

from __future__ import annotations

import dataclasses
import tracemalloc

import numpy as np
from affine import Affine
from scipy import ndimage

from clearfast_gis.detection.clutter import background_levels
from clearfast_gis.detection.markers import markers_in_mosaics
from clearfast_gis.detection.voting import detect_on_mosaics
from clearfast_gis.export.cog import mosaic_stack, write_cog
from clearfast_gis.export.layout import mosaic_rel
from clearfast_gis.geometry.grid import GroundGrid

PIXEL_M = 0.02
SHAPE = (160, 224)
BANDS = 2
X0, Y0 = 500000.0, 4000000.0
TRANSFORM = Affine(PIXEL_M, 0.0, X0, 0.0, -PIXEL_M, Y0)
GRID = GroundGrid(X0, Y0, PIXEL_M, SHAPE[1], SHAPE[0], 32636)
MARKER_RC = (40, 180)  # row, col of the marker plate's centre
MARKER_XY = np.array([[X0 + (MARKER_RC[1] + 0.5) * PIXEL_M, Y0 - (MARKER_RC[0] + 0.5) * PIXEL_M]])
# (row, col, diameter px, amplitude K): mines, and a warm patch with a mine on its flank
OBJECTS = [(50.0, 60.0, 5.0, 0.8), (110.0, 150.0, 7.0, -0.6), (120.0, 40.0, 4.0, 0.7),
           (100.0, 100.0, 40.0, 1.2), (88.0, 112.0, 5.0, 0.9)]


def _scans(n: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """(N, 2, H, W) float32 mosaics over a day (ground texture following the sun, objects
    warm by day and cool by night, a hot marker plate, a corner no scan sees, a strip of the
    site left out of every third scan) and the scan times."""
    rng = np.random.default_rng(seed)
    texture = ndimage.gaussian_filter(rng.standard_normal(SHAPE), 12.0).astype(np.float32)
    texture *= np.float32(0.3 / texture.std())
    rr, cc = np.mgrid[0:SHAPE[0], 0:SHAPE[1]]
    times = 1.7e9 + np.arange(n) * 86400.0 / n
    phase = np.cos(2 * np.pi * (np.arange(n) / n - 0.5))
    out = np.empty((n, BANDS, *SHAPE), dtype=np.float32)
    for i in range(n):
        for b in range(BANDS):
            img = 20.0 + b + (1.0 + 0.5 * phase[i]) * texture
            img += 0.03 * rng.standard_normal(SHAPE).astype(np.float32)
            for row, col, diameter, amp in OBJECTS:
                disc = (rr - row) ** 2 + (cc - col) ** 2 <= (diameter / 2) ** 2
                img += np.float32(amp * phase[i]) * disc
            img[MARKER_RC[0] - 7:MARKER_RC[0] + 8, MARKER_RC[1] - 7:MARKER_RC[1] + 8] += 6.0
            img[:20, :30] = np.nan
            if i % 3 == 1:
                img[:, 200:] = np.nan
            out[i, b] = img
    return out, times


def _write(tmp_path, stack: np.ndarray):
    for i, bands in enumerate(stack):
        write_cog(tmp_path / mosaic_rel(i), bands, TRANSFORM, 32636, ["a", "b"])
    return mosaic_stack(tmp_path, list(range(len(stack))))


def _chain(stack, times):
    """Detection, markers and the site's background, as the chain runs them."""
    labels, feats = detect_on_mosaics(stack, times, TRANSFORM, PIXEL_M, 0.0, d1_m=0.5,
                                      d2_m=0.06, epsilon=0.01, level=None, gamma=None,
                                      max_anomalies=50, level_fraction=0.25,
                                      gamma_fraction=0.25, threshold_snr=4.0)
    markers = markers_in_mosaics(stack, GRID, ["M1"], MARKER_XY)
    return labels, feats, markers, background_levels(stack, labels, PIXEL_M)


def _same(a, b) -> bool:
    if isinstance(a, np.ndarray):
        return a.dtype == b.dtype and np.array_equal(a, b, equal_nan=a.dtype.kind == "f")
    if isinstance(a, float):
        return a == b or (np.isnan(a) and np.isnan(b))
    return a == b


def test_streamed_chain_equals_the_stack_in_memory(tmp_path):
    stack, times = _scans(8)
    labels, feats, markers, (median, clutter) = _chain(stack, times)
    s_labels, s_feats, s_markers, (s_median, s_clutter) = _chain(_write(tmp_path, stack), times)
    assert len(feats) >= 4 and labels.max() == len(feats)
    assert np.array_equal(labels, s_labels)
    assert len(s_feats) == len(feats)
    for f, g in zip(feats, s_feats, strict=True):
        for field in dataclasses.fields(f):
            assert _same(getattr(f, field.name), getattr(g, field.name)), field.name
    assert len(markers) == 1 and markers == s_markers
    assert median.dtype == np.float32 and np.array_equal(median, s_median)
    assert np.isfinite(clutter) and clutter == s_clutter


def _peak_mib(tmp_path, n: int) -> float:
    stack, times = _scans(n)
    cogs = _write(tmp_path / f"n{n}", stack)
    del stack
    _chain(cogs, times)  # compiled kernels and caches made once, outside the measure
    tracemalloc.start()
    try:
        _chain(cogs, times)
        return tracemalloc.get_traced_memory()[1] / 2**20
    finally:
        tracemalloc.stop()


def test_memory_does_not_grow_with_the_scans(tmp_path, monkeypatch):
    """From 6 to 24 scans the peak of detection, features, markers and the background grows
    by at most the packed maps: per scan, one bit a pixel per image and polarity (the
    thresholded hats G_i) and one bit a pixel per polarity (the per-scan maps L_i), plus the
    blobs' series and 16 KiB: (B + 1) H W / 4 bytes + 16 KiB a scan (15 % of the scan's
    float32 bands here, 8 % on the trial's 3 x 1097 x 1600 mosaics), where holding the stack
    costs 100 %."""
    monkeypatch.setenv("CLEARFAST_THREADS", "1")  # the same scans in flight on every run
    small, large = _peak_mib(tmp_path, 6), _peak_mib(tmp_path, 24)
    per_scan_bound = ((BANDS + 1) * SHAPE[0] * SHAPE[1] / 4 + 16 * 2**10) / 2**20
    stack_per_scan = BANDS * SHAPE[0] * SHAPE[1] * 4 / 2**20
    assert large - small <= 18 * per_scan_bound, (small, large)
    assert large < 24 * stack_per_scan  # less than the stack itself
