"""A weak shallow mine inside a warm patch: its time-averaged compact contrast is below the
split's cut, its curve over the day is a mine's; a stone-like object and the patch's own cap
are not split out by their curves."""

from __future__ import annotations

import numpy as np

from clearfast_gis.detection.compact import (
    compact_contrast,
    curve_cores,
    oversized_mask,
    split_oversized,
)
from clearfast_gis.detection.deep import stack_match
from tests.detection.test_compact import PIXEL_M, SHAPE, _diurnal_stack, _nearest
from tests.detection.test_deep import (
    N_SCANS,
    RADIUS_M,
    RADIUS_PX,
    TEMPLATES,
    _curve,
    _with,
)

D1_PX = 25
SPACING_PX = 0.45 / PIXEL_M
MIN_AREA_PX = np.pi * (0.03 / PIXEL_M) ** 2
MINE = (104.0, 108.0)  # on the flank of the warm patch
STONE = (85.0, 112.0)
#: Shallow templates: the mine's curve with small lags (its own is 0.4 rad late).
SHALLOW = np.array([_curve(lag) for lag in (0.0, 0.2, 0.4, 0.6)])


def _scene() -> tuple[np.ndarray, np.ndarray]:
    """The test stack: a 1 K warm patch, a 0.1 K mine whose curve is the templates', and a
    stone of the same size and swing whose curve runs against a mine's (warm at night)."""
    base, times = _diurnal_stack(N_SCANS, [], dome=1.0)
    stack = _with(base, *MINE, 0.1 * _curve(0.4))
    return _with(stack, *STONE, -0.1 * _curve(0.4)), times


def _patch() -> np.ndarray:
    labels = np.zeros(SHAPE, np.int32)
    labels[60:140, 60:140] = 1  # the warm patch, one blob too large to be a mine
    return labels


def test_oversized_mask():
    labels = np.zeros((40, 40), np.int32)
    labels[2:32, 2:32] = 1  # 30 px square: equivalent diameter 33.9 px
    labels[35:38, 35:38] = 2
    mask = oversized_mask(labels, 25.0)
    assert mask[10, 10] and not mask[36, 36] and not mask[0, 39]
    assert not oversized_mask(labels, 34.0).any()


def test_the_time_average_misses_the_weak_mine_its_curve_does_not():
    stack, _ = _scene()
    cc = compact_contrast(stack[:, 0], d1_px=D1_PX)
    assert np.nanmax(cc[102:107, 106:111]) < 4.0  # below the split's cut
    split = split_oversized(_patch(), stack[:, 0], D1_PX, 3, D1_PX)
    assert split[int(MINE[0]), int(MINE[1])] == 1  # left inside the patch
    match = stack_match(stack, SHALLOW, RADIUS_PX)
    labels, cores = curve_cores(split, match, RADIUS_PX, D1_PX, SPACING_PX, MIN_AREA_PX)
    assert len(cores) == 1
    label, row, col = cores[0]
    assert np.hypot(row - MINE[0], col - MINE[1]) <= 1.0
    assert labels[int(MINE[0]), int(MINE[1])] == label
    assert labels[100, 100] == 1  # the patch keeps its label
    # the stone's curve runs against every template: no core
    assert match.score[int(STONE[0]), int(STONE[1])] < 0


def test_no_core_on_open_ground_or_in_a_mine_sized_blob():
    stack, _ = _scene()
    match = stack_match(stack, SHALLOW, RADIUS_PX)
    # on open ground (no blob) the per-scan detector is the one to find it
    labels, cores = curve_cores(np.zeros(SHAPE, np.int32), match, RADIUS_PX, D1_PX,
                                SPACING_PX, MIN_AREA_PX)
    assert cores == [] and not labels.any()
    small = np.zeros(SHAPE, np.int32)
    small[110:126, 92:108] = 1  # 16 px: a blob of mine size
    _, cores = curve_cores(small, match, RADIUS_PX, D1_PX, SPACING_PX, MIN_AREA_PX)
    assert cores == []


def test_a_patch_without_a_mine_gives_no_curve_core():
    base, _ = _diurnal_stack(N_SCANS, [], dome=1.0)
    stack = _with(base, *STONE, -0.1 * _curve(0.4))
    match = stack_match(stack, SHALLOW, RADIUS_PX)
    _, cores = curve_cores(_patch(), match, RADIUS_PX, D1_PX, SPACING_PX, MIN_AREA_PX)
    assert cores == []


def test_through_the_detector_the_weak_mine_is_an_anomaly_of_its_own():
    from clearfast_gis.detection.voting import detect_on_mosaics

    stack, times = _scene()
    deep = TEMPLATES[2:]  # late curves (1.2, 1.6 rad): a shallow mine's explains little

    def detect(shallow):
        return detect_on_mosaics(stack, times, None, PIXEL_M, 0.0, d1_m=0.5, d2_m=0.06,
                                 epsilon=0.01, level=None, gamma=None, max_anomalies=50,
                                 level_fraction=0.25, gamma_fraction=0.25,
                                 deep_templates_k=deep, deep_radius_m=RADIUS_M,
                                 curve_templates_k=shallow)[1]

    # without the shallow curves the mine stays inside the patch
    assert all(np.hypot(f.row - MINE[0], f.col - MINE[1]) > 3.0 for f in detect(None))
    feats = detect(SHALLOW)
    f = _nearest(feats, *MINE)
    assert np.hypot(f.row - MINE[0], f.col - MINE[1]) <= 2.0  # 4 cm
    assert f.n_scans >= N_SCANS // 2
    assert all(np.hypot(g.row - STONE[0], g.col - STONE[1]) > 3.0 for g in feats
               if g.diameter_px < 15)
