"""Erosion by a disk's chords (detection._chords) against OpenCV, bit for bit."""

import cv2
import numpy as np
import pytest

from clearfast_gis.detection._chords import (
    chord_half_widths,
    erode_chords,
    segment_schedule,
)
from clearfast_gis.detection.compact import _compact_term
from clearfast_gis.detection.morphology import dilate_disk, disk_footprint, erode_disk

SHAPES = [(1, 1), (1, 9), (7, 1), (3, 3), (6, 40), (40, 6), (13, 14), (31, 58), (97, 83)]


def _image(shape, dtype, rng) -> np.ndarray:
    """Values with ties (quarter steps) and a tenth of the cells at +inf (no-data as the
    erosion sees it); no -0.0 (of two zeros either may be returned)."""
    a = np.round(rng.normal(size=shape) * 4.0) / 4.0 + 0.0
    a[rng.random(shape) < 0.1] = np.inf
    return a.astype(dtype)


def _same_bits(a: np.ndarray, b: np.ndarray) -> bool:
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("diameter", [3, 5, 7, 9, 13, 25, 27, 49])
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_erode_chords_equals_cv2_erode(diameter, dtype):
    rng = np.random.default_rng(diameter)
    fp = disk_footprint(diameter)
    half_widths = chord_half_widths(fp)
    schedule = segment_schedule(half_widths)
    for shape in SHAPES:
        image = _image(shape, dtype, rng)
        out = np.empty_like(image)
        erode_chords(image, half_widths, schedule, out)
        ref = cv2.erode(image, fp, borderType=cv2.BORDER_CONSTANT, borderValue=np.inf)
        assert _same_bits(out, ref), (diameter, shape)


def test_segment_schedule_reaches_every_half_width():
    for diameter in (3, 7, 25, 49, 101):
        half_widths = chord_half_widths(disk_footprint(diameter))
        made = {0}
        for k, j, m in segment_schedule(half_widths):
            assert j in made and m == k - j and 1 <= m <= 2 * j + 1
            made.add(int(k))
        assert set(half_widths.tolist()) <= made


def test_chord_half_widths_refuses_other_footprints():
    assert chord_half_widths(np.ones((3, 4), np.uint8)) is None
    ring = disk_footprint(9).copy()
    ring[4, 4] = 0
    assert chord_half_widths(ring) is None
    assert chord_half_widths(disk_footprint(9)).tolist() == [0, 2, 3, 3, 4, 3, 3, 2, 0]


@pytest.mark.parametrize("diameter", [7, 25])
def test_disk_erosion_and_dilation_with_nan_equal_cv2(diameter):
    rng = np.random.default_rng(3)
    fp = disk_footprint(diameter)
    for shape in SHAPES:
        image = _image(shape, np.float32, rng)
        image[image == np.inf] = np.nan
        nan = np.isnan(image)
        ero = cv2.erode(np.where(nan, np.inf, image).astype(np.float32), fp,
                        borderType=cv2.BORDER_CONSTANT, borderValue=np.inf)
        dil = cv2.dilate(np.where(nan, -np.inf, image).astype(np.float32), fp,
                         borderType=cv2.BORDER_CONSTANT, borderValue=-np.inf)
        ero[nan] = np.nan
        dil[nan] = np.nan
        assert _same_bits(erode_disk(image, diameter), ero)
        assert _same_bits(dilate_disk(image, diameter), dil)


def test_opening_and_closing_equal_cv2_with_a_replicated_border():
    """The compact objects' pass opens and closes without OpenCV's replicated border: for a
    disk it gives the same values."""
    rng = np.random.default_rng(4)
    for diameter in (7, 25):
        fp = disk_footprint(diameter)
        for shape in SHAPES:
            f = np.round(rng.normal(size=shape) * 8.0).astype(np.float32) / 8.0 + 0.0
            opened = cv2.morphologyEx(f, cv2.MORPH_OPEN, fp, borderType=cv2.BORDER_REPLICATE)
            closed = cv2.morphologyEx(f, cv2.MORPH_CLOSE, fp, borderType=cv2.BORDER_REPLICATE)
            assert _same_bits(dilate_disk(erode_disk(f, diameter), diameter), opened)
            assert _same_bits(erode_disk(dilate_disk(f, diameter), diameter), closed)


def test_compact_term_keeps_its_values():
    """``_compact_term`` as it was computed with ``cv2.morphologyEx``."""
    from clearfast_gis.detection.multiscale import robust_sigma
    from clearfast_gis.detection.selection import median

    rng = np.random.default_rng(6)
    f = rng.normal(size=(120, 90)).astype(np.float32)
    f[rng.random(f.shape) < 0.05] = np.nan
    ok = np.isfinite(f)
    filled = np.where(ok, f, median(f[ok])).astype(np.float32)
    kernel = disk_footprint(25)
    white = filled - cv2.morphologyEx(filled, cv2.MORPH_OPEN, kernel,
                                      borderType=cv2.BORDER_REPLICATE)
    black = cv2.morphologyEx(filled, cv2.MORPH_CLOSE, kernel,
                             borderType=cv2.BORDER_REPLICATE) - filled
    sigma = robust_sigma(np.where(ok, white - black, np.nan))
    term, used = _compact_term(f, 25)
    assert _same_bits(term, np.where(ok, np.maximum(white, black) / sigma, 0.0))
    assert np.array_equal(used, ok)
