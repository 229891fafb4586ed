"""A stone and a mine on one clear day: the diurnal-curve match tells them apart."""

from __future__ import annotations

import math

import numpy as np
import pytest

from clearfast_gis.detection.classify import (
    CLUTTER_CURVE_R,
    MAX_MINE_CURVE_LEVEL,
    MINE_CURVE_R,
    classify,
)
from clearfast_gis.detection.curve import match_curves, mine_curve_level, mine_curve_match
from clearfast_gis.detection.features import AnomalyFeatures
from clearfast_gis.thermal import clear_sky_forcing
from clearfast_gis.thermal.daycontrast import day_contrast
from clearfast_gis.thermal.forward import BuriedObject, ObjectModel
from clearfast_gis.thermal.materials import MATERIALS
from clearfast_gis.thermal.soils import soil_of_type
from clearfast_gis.timeutil import parse_utc

LAT_DEG, LON_DEG = 35.17, 33.36
DAY0_S = parse_utc("2026-11-15T00:00:00Z")
#: The demo survey's six scans: 03:00 to 23:00 local time (UTC+2), every 4 h.
SCANS_S = DAY0_S + 3600.0 + 4 * 3600.0 * np.arange(6)


@pytest.fixture(scope="module")
def clay_day():
    """The day's forcing, the moist clay soil and the reference mine curves at 0-5 cm."""
    forcing = clear_sky_forcing(LAT_DEG, LON_DEG, DAY0_S, 86400.0)
    soil = soil_of_type("clay", 0.4)
    day = day_contrast(forcing, soil, SCANS_S, 0.05, LAT_DEG, LON_DEG)
    return forcing, soil, match_curves(day.depths_m, day.curves_k)


def _contrast(forcing, soil, radius_m, height_m, depth_m, material):
    model = ObjectModel(soil, forcing, SCANS_S, radius_m)
    obj = BuriedObject(radius_m, height_m, depth_m, MATERIALS[material])
    return model.surface_at(obj, [0.0])[:, 0] - model.background_k


def test_reference_curves_stop_at_five_centimetres(clay_day):
    _, _, curves = clay_day
    assert curves.shape == (5, SCANS_S.size)  # 0, 1, 2, 3, 5 cm
    # a mine is warmest in the 09:00-13:00 scan and coolest at night, at every depth
    assert np.all(curves[:, 2] > 0) and np.all(curves[:, 0] < 0)


@pytest.mark.parametrize(("radius_m", "height_m", "depth_m"), [
    (0.052, 0.08, 0.01), (0.052, 0.08, 0.03), (0.052, 0.08, 0.05), (0.1685, 0.094, 0.0)])
def test_a_mine_follows_the_model(clay_day, radius_m, height_m, depth_m):
    forcing, soil, curves = clay_day
    c = _contrast(forcing, soil, radius_m, height_m, depth_m, "tnt")
    assert mine_curve_match(c, curves) > 0.98
    # scale, an offset and noise of a tenth of the contrast do not change that
    rng = np.random.default_rng(0)
    noisy = 0.7 * c + 0.3 + 0.1 * np.abs(c).max() * rng.standard_normal(c.size)
    assert mine_curve_match(noisy, curves) > 0.9


@pytest.mark.parametrize("radius_m", [0.03, 0.055, 0.08])
def test_a_surface_stone_runs_against_it(clay_day, radius_m):
    forcing, soil, curves = clay_day
    c = _contrast(forcing, soil, radius_m, radius_m, 0.0, "stone")
    # the stone stores heat: coolest at the late-morning scan, warmest at night
    assert np.argmin(c) == 2
    # seen with its emissivity offset (warm at every scan), its curve still runs against
    warm = c - c.min() + 0.2
    assert np.all(warm > 0)
    r = mine_curve_match(warm, curves)
    assert r < CLUTTER_CURVE_R
    assert r == pytest.approx(mine_curve_match(c, curves), abs=1e-12)


def test_undefined_match():
    curves = np.array([[-0.5, -0.3, 0.8, 0.4, -0.2, -0.4]])
    assert math.isnan(mine_curve_match(np.full(6, 0.3), curves))  # flat
    assert math.isnan(mine_curve_match(np.array([1.0, np.nan, np.nan, np.nan, 2.0, 0.5]),
                                       curves))  # three scans
    with pytest.raises(ValueError, match="5 scans, the model curves 6"):
        mine_curve_match(np.zeros(5), curves)


def _features(**kw) -> AnomalyFeatures:
    base = dict(id=1, row=10.0, col=10.0, x=0.0, y=0.0, area_px=40, area_m2=0.008,
                diameter_px=5.5, diameter_m=0.11, circularity=0.95, axis_ratio=0.95,
                compactness=0.95, polarity_per_scan=np.ones(6, int), polarity="warm",
                n_scans=6, centre_k=np.zeros(6), ring_k=np.zeros(6), contrast_k=np.ones(6),
                noise_k=np.full(6, 0.05), score=40.0)
    base.update(kw)
    return AnomalyFeatures(**base)


def test_a_warm_stone_against_the_curve_is_clutter():
    f = _features()
    assert classify(f, contrast_day_k=0.77)[0] == "ap_mine"
    assert classify(f, contrast_day_k=0.77, mine_curve_r=0.9)[0] == "ap_mine"
    cue, conf = classify(f, contrast_day_k=0.77, mine_curve_r=-0.8)
    assert cue == "clutter" and conf == pytest.approx(1 - (1 - math.exp(-40 / 3)) * 0.95 * 0.8
                                                      * 0.8, abs=1e-4)
    assert classify(f, mine_curve_r=float("nan"))[0] == "ap_mine"
    # a curve that neither follows nor runs against the mine's: no mine cue
    assert classify(f, mine_curve_r=0.3)[0] == "unknown"
    assert classify(f, mine_curve_r=0.6)[0] == "ap_mine"
    weak = _features(score=1.0)
    assert classify(weak, mine_curve_r=-0.8)[0] == "unknown"


# --- the level of a curve against the mine's: the bare edge of a grass patch ---------------

SOUTH_LAT_DEG, SOUTH_LON_DEG = -15.16, 19.17
SOUTH_DAY0_S = parse_utc("2026-01-15T00:00:00Z")
#: The demo's six scans of the southern-summer day of ``benchmarks/conditions.py``.
SOUTH_SCANS_S = SOUTH_DAY0_S + 3664.7 + 4 * 3600.0 * np.arange(6)
#: Measured contrast curves (first band, K) on the demo's southern-summer survey of seed 10
#: (a tuning seed): four suspects on the bare edges of two grass patches, cued ``ap_mine`` /
#: ``at_mine`` before the level was used, and the four mines at 0-5 cm of that survey.
EDGES_K = [[0.073, 0.513, 1.524, 2.207, 1.110, 0.586], [0.291, 0.982, 1.638, 1.978, 1.104, 0.828],
           [0.323, 0.925, 1.473, 1.664, 0.971, 0.741], [0.196, 0.847, 1.865, 2.401, 1.303, 0.819]]
MINES_K = [[-0.804, -0.291, 1.026, 0.848, -0.494, -0.627], [-0.364, -0.280, 0.318, 0.298, -0.156,
                                                             -0.271],
           [-1.005, -0.499, 0.749, 0.554, -0.698, -0.806], [-0.113, -0.073, 0.074, 0.110, 0.015,
                                                            -0.080]]


@pytest.fixture(scope="module")
def south_curves():
    """The reference mine curves at 0-5 cm of a clear southern-summer day on moist sand."""
    forcing = clear_sky_forcing(SOUTH_LAT_DEG, SOUTH_LON_DEG, SOUTH_DAY0_S, 86400.0,
                                t_air_min_c=17.0, t_air_max_c=29.0, rh_min_pct=55.0,
                                rh_max_pct=85.0)
    day = day_contrast(forcing, soil_of_type("sand", 0.3), SOUTH_SCANS_S, 0.05,
                       SOUTH_LAT_DEG, SOUTH_LON_DEG)
    return match_curves(day.depths_m, day.curves_k)


def test_a_mine_sits_on_the_model(south_curves, clay_day):
    for curves in (south_curves, clay_day[2]):
        for m in curves:  # the model's own curves, scaled: level 0
            assert mine_curve_level(0.6 * m, curves) == pytest.approx(0.0, abs=1e-9)
    for c in MINES_K:
        assert abs(mine_curve_level(np.array(c), south_curves)) < 0.15
    forcing, soil, curves = clay_day
    c = _contrast(forcing, soil, 0.052, 0.08, 0.02, "tnt")
    assert abs(mine_curve_level(c, curves)) < 0.05


def test_a_grass_edge_follows_the_shape_but_sits_above(south_curves):
    for c in EDGES_K:
        c = np.array(c)
        assert mine_curve_match(c, south_curves) > MINE_CURVE_R  # the shape follows
        assert mine_curve_level(c, south_curves) > MAX_MINE_CURVE_LEVEL  # warm at night
    f = _features(diameter_m=0.30, diameter_px=15.0)
    c = np.array(EDGES_K[1])
    r, level = mine_curve_match(c, south_curves), mine_curve_level(c, south_curves)
    assert classify(f, contrast_day_k=1.98, mine_curve_r=r)[0] == "at_mine"
    assert classify(f, contrast_day_k=1.98, mine_curve_r=r, mine_curve_level=level)[0] \
        == "unknown"


def test_level_undefined():
    curves = np.array([[-0.5, -0.3, 0.8, 0.4, -0.2, -0.4]])
    assert math.isnan(mine_curve_level(np.full(6, 0.3), curves))  # flat
    stone = np.array([1.9, 1.5, -0.1, 0.8, 1.4, 1.7])
    assert math.isnan(mine_curve_level(stone, curves))  # runs against the mine's


def test_mixed_polarity_that_follows_the_mine_curve_is_not_clutter():
    """A 3 cm mine under grass (demo grass seed 10, a tuning seed): warm in two day scans,
    cool in the morning one, unseen at night; its curve follows the model (+0.98)."""
    pol = np.array([0, -1, 1, 1, -1, 0])
    f = _features(polarity_per_scan=pol, polarity="mixed", n_scans=4, score=2.5,
                  circularity=0.89)
    # not clutter; not a mine cue either (vegetation pieces do the same: clear seed 10)
    assert classify(f, contrast_day_k=0.11, mine_curve_r=0.98)[0] == "unknown"
    assert classify(f, contrast_day_k=0.11, mine_curve_r=0.3)[0] == "clutter"
    assert classify(f, contrast_day_k=0.11)[0] == "clutter"  # no model: as before
