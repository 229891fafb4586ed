"""A stone and a mine on one clear day: the diurnal-curve match tells them apart."""

from __future__ import annotations

import math

import numpy as np
import pytest

from clearfast_gis.detection.classify import CLUTTER_CURVE_R, classify
from clearfast_gis.detection.curve import match_curves, mine_curve_match
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
