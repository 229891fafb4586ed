"""Multi-scale snapshot mode: scale ladders, altitude parsing, suppression, synthetic scene."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy import ndimage

from clearfast_gis.detection.multiscale import (
    MultiScaleParams,
    altitude_from_name,
    altitude_ladder,
    detect_snapshot_multiscale,
    robust_sigma,
    scale_ladder,
    snapshot_score,
    suppress_overlaps,
)
from clearfast_gis.detection.snapshot import Detection

SMALL = (60.0, 70.0, 6.0)  # row, col, radius (px)
LARGE = (170.0, 180.0, 45.0)


def _scene(seed=0):
    rng = np.random.default_rng(seed)
    texture = ndimage.gaussian_filter(rng.normal(size=(256, 256)), 1.5)
    img = (20.0 + 0.1 * texture / texture.std()).astype(np.float32)
    rr, cc = np.mgrid[:256, :256]
    for r, c, rad in (SMALL, LARGE):
        img += 1.0 * (np.hypot(rr - r, cc - c) <= rad)
    img[20:24, 120:230] += 1.0  # clutter: a warm bar (elongated)
    img[200:203, 20:100] += 1.0  # another one
    img += 0.35 * (np.hypot(rr - 40.0, cc - 200.0) <= 5)  # a faint small blob
    return img


def test_multiscale_finds_small_and_large_disc_above_clutter():
    dets = detect_snapshot_multiscale(_scene(), polarity="hot")
    assert len(dets) >= 3
    top = sorted(dets[:2], key=lambda d: d.diameter_px)
    for det, (r, c, rad) in zip(top, (SMALL, LARGE), strict=True):
        assert (det.y_px, det.x_px) == pytest.approx((r, c), abs=1.5)
        assert det.diameter_px == pytest.approx(2 * rad, rel=0.5)  # smoothing widens it
        assert det.polarity == "warm"
    assert top[0].scale_px < 40 < top[1].scale_px
    # one detection per disc: nothing else centred on either disc
    for r, c, rad in (SMALL, LARGE):
        near = [d for d in dets if np.hypot(d.y_px - r, d.x_px - c) <= rad]
        assert len(near) == 1
    # a single scale with D1 fitted to the small disc misses the large one
    small_only = detect_snapshot_multiscale(_scene(), [16.0], polarity="hot")
    assert not any(np.hypot(d.y_px - LARGE[0], d.x_px - LARGE[1]) < 5 for d in small_only)


def test_scale_ladder_and_altitude_ladder():
    np.testing.assert_allclose(scale_ladder(16, 64, 2), [16, 22.6, 32, 45.3, 64])
    np.testing.assert_allclose(scale_ladder(10, 10), [10])
    lad = altitude_ladder(2.0, 200.0, spread=4.0, per_octave=1)
    np.testing.assert_allclose(lad, [50, 100, 200])  # centre 100 px, /2 .. x2
    # the window slides inside [16, 256] px: high flights keep the smallest scales
    np.testing.assert_allclose(altitude_ladder(100.0, 200.0, spread=4.0, per_octave=1),
                               [16, 32, 64])
    np.testing.assert_allclose(altitude_ladder(0.1, 200.0, spread=4.0, per_octave=1),
                               [64, 128, 256])
    with pytest.raises(ValueError):
        scale_ladder(20, 10)
    with pytest.raises(ValueError):
        altitude_ladder(0.0, 200.0)


@pytest.mark.parametrize("name,expected", [
    ("1273_Zone_7_Mine_5cm_depth__0-7m_TemperatureInCenter__29A-C_jpg.rf.ab.jpg", 0.7),
    ("1008_Zone_7_Mine_5cm_depth__10-m_TemperatureInCenter__38A-C_jpg.rf.ab.jpg", 10.0),
    ("16_Zone_2_Mine_1cm_depth__-0-m_TemperatureInCenter__28-C_jpg.rf.ab.jpg", None),
    ("plain.png", None),
])
def test_altitude_from_name(name, expected):
    assert altitude_from_name(name) == expected


@given(st.integers(0, 99), st.integers(0, 9))
def test_altitude_from_name_round_trip(whole, tenth):
    value = altitude_from_name(f"x__{whole}-{tenth}m_y.jpg")
    assert value == (pytest.approx(whole + tenth / 10) if whole or tenth else None)


def _det(x, y, diam, score):
    return Detection(x_px=x, y_px=y, area_px=int(np.pi * diam**2 / 4), diameter_px=diam,
                     circularity=1.0, score=score, polarity="warm", contrast=1.0,
                     bbox=(0, 0, 1, 1))


def test_suppress_overlaps_keeps_one_per_blob():
    dets = [_det(10, 10, 8, 2.0), _det(11, 10, 20, 3.0), _det(40, 40, 8, 1.0),
            _det(40, 52, 8, 1.5)]
    kept = suppress_overlaps(dets)
    assert [d.score for d in kept] == [3.0, 1.5, 1.0]  # the two at (10, 10) merge
    assert suppress_overlaps([]) == []


def test_robust_sigma_ignores_objects():
    rng = np.random.default_rng(2)
    img = rng.normal(0.0, 0.5, (200, 200)).astype(np.float32)
    img[:40, :40] += 10.0  # 4 % of the pixels
    img[0, 0] = np.nan
    assert robust_sigma(img) == pytest.approx(0.5, rel=0.1)
    assert np.nanstd(img) > 3 * robust_sigma(img)


def test_snapshot_score():
    assert snapshot_score(-2.0, 0.5, 1.0, 100.0, 0.0) == pytest.approx(4.0)
    assert snapshot_score(2.0, 0.5, 0.0, 100.0, 0.5) == pytest.approx(2.0 * 10.0)
    assert snapshot_score(2.0, 0.0, 1.0, 100.0, 0.1) == 0.0


def test_params_defaults_are_consistent():
    p = MultiScaleParams()
    assert p.d1_ratio > 1.0 > p.d2_ratio and p.size_band[0] < 1.0 < p.size_band[1]
