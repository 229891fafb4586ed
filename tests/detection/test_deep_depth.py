"""A deep core's depth from its curve's shape: a deep mine of known depth comes out within
its sigma, and what the data cannot tell is flagged."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from clearfast_gis.detection.deep import core_contrast
from clearfast_gis.detection.deep_depth import (
    DISC_RING_GAIN,
    DISC_RING_GAIN_SIGMA,
    MAX_DEEP_SIGMA_M,
    MAX_WIDE_RATIO,
    PROFILE_DEPTHS_M,
    characterise_cores,
    deep_inversion,
    depth_profile,
    model_sigma_m,
    wide_ratio,
    with_core_depths,
)
from clearfast_gis.thermal import clear_sky_forcing
from clearfast_gis.thermal.daycontrast import (
    REFERENCE_HEIGHT_M,
    REFERENCE_RADIUS_M,
    reference_curves,
)
from clearfast_gis.thermal.forward import BuriedObject, ObjectModel
from clearfast_gis.thermal.materials import MATERIALS
from clearfast_gis.thermal.soils import soil_of_type
from tests.detection.test_classify import _feat
from tests.detection.test_curve import DAY0_S, LAT_DEG, LON_DEG, SCANS_S

DAMPING_M = 0.12  # damping depth of the diurnal wave in sand, m
TIMES_S = np.arange(48) * 1800.0  # 48 scans over a day
DEPTHS = np.asarray(PROFILE_DEPTHS_M)


def _curves(depths_m: np.ndarray) -> np.ndarray:
    """Diurnal contrast of a buried object (D, S), K: a damped wave that lags with depth,
    2 K at the surface."""
    omega = 2.0 * np.pi / 86400.0
    d = np.asarray(depths_m, dtype=float)[:, None]
    return 2.0 * np.exp(-d / DAMPING_M) * np.sin(omega * TIMES_S[None] - d / DAMPING_M)


TEMPLATES = _curves(DEPTHS)


def _observed(depth_m: float, noise_k: float, seed: int, gain: float = DISC_RING_GAIN
              ) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return gain * _curves([depth_m])[0] + rng.normal(0.0, noise_k, TIMES_S.size)


@pytest.mark.parametrize("depth_m", [0.06, 0.08, 0.10])
def test_a_deep_mine_comes_out_within_its_sigma(depth_m):
    noise = np.full(TIMES_S.size, 0.03)
    errors = []
    for seed in range(20):
        inv = deep_inversion(depth_profile(_observed(depth_m, 0.03, seed), noise, TEMPLATES),
                             0.03)
        assert inv.status == "ok"
        assert inv.depth_sigma_m <= MAX_DEEP_SIGMA_M
        assert np.isnan(inv.alpha_m2s)
        errors.append((inv.depth_m - depth_m) / inv.depth_sigma_m)
    errors = np.abs(errors)
    # the sigma covers the error (68 % within 1 sigma, 95 % within 2) and is not far too wide
    assert np.mean(errors <= 1.0) >= 0.68 and np.mean(errors <= 2.0) >= 0.95
    assert np.median(errors) > 0.05
    assert inv.depth_sigma_m >= model_sigma_m(inv.depth_m)


def test_a_gain_other_than_the_prior_still_gives_the_depth():
    noise = np.full(TIMES_S.size, 0.02)
    for gain in (0.35, 0.7):
        inv = deep_inversion(depth_profile(_observed(0.07, 0.02, 1, gain), noise, TEMPLATES),
                             0.02)
        assert inv.status == "ok" and abs(inv.depth_m - 0.07) <= 2 * inv.depth_sigma_m


def test_a_curve_lost_in_noise_is_flagged():
    noise = np.full(TIMES_S.size, 0.5)
    inv = deep_inversion(depth_profile(_observed(0.08, 0.5, 3), noise, TEMPLATES), 0.5)
    assert inv.status == "not_characterised"
    assert inv.depth_sigma_m > MAX_DEEP_SIGMA_M


def test_an_object_below_the_profile_is_flagged():
    noise = np.full(TIMES_S.size, 0.01)
    profile = depth_profile(_observed(0.22, 0.01, 4), noise, TEMPLATES)
    assert profile.at_end and not np.isfinite(profile.fit_sigma_m)
    assert deep_inversion(profile, 0.01).status == "not_characterised"


def test_the_noise_is_scaled_by_the_misfit():
    told = np.full(TIMES_S.size, 0.01)  # the truth is 0.05 K
    profile = depth_profile(_observed(0.08, 0.05, 5), told, TEMPLATES)
    assert 3.5 < profile.noise_scale < 6.5


def test_only_deep_cores_are_characterised():
    blob = _feat(0.104, n=TIMES_S.size)
    seen = _observed(0.07, 0.03, 6)
    core = dataclasses.replace(blob, id=blob.id + 1, core_contrast_k=seen,
                               core_wide_contrast_k=0.4 * seen,
                               core_noise_k=np.full(TIMES_S.size, 0.03))
    out = characterise_cores([blob, core], TEMPLATES)
    assert list(out) == [core.id]
    assert out[core.id].status == "ok"
    assert abs(out[core.id].depth_m - 0.07) <= out[core.id].depth_sigma_m


def test_a_core_larger_than_the_ap_type_is_flagged():
    """An AT mine's ring at the AP radius lies inside it: its contrast at the AT radius is
    several times that at the AP radius, and the AP template does not give its depth."""
    seen = _observed(0.07, 0.03, 7)
    assert wide_ratio(seen, 4.0 * seen) == pytest.approx(4.0)
    assert wide_ratio(seen, 4.0 * seen) > MAX_WIDE_RATIO
    core = dataclasses.replace(_feat(0.104, n=TIMES_S.size), core_contrast_k=seen,
                               core_wide_contrast_k=4.0 * seen,
                               core_noise_k=np.full(TIMES_S.size, 0.03))
    assert characterise_cores([core], TEMPLATES)[core.id].status == "not_characterised"
    without = dataclasses.replace(core, core_wide_contrast_k=None)
    assert characterise_cores([without], TEMPLATES)[core.id].status == "not_characterised"


def test_inputs_are_checked():
    with pytest.raises(ValueError):
        depth_profile(np.zeros(5), np.ones(5), TEMPLATES)
    few = np.full(TIMES_S.size, np.nan)
    few[:3] = 0.1
    with pytest.raises(ValueError):
        depth_profile(few, np.ones(TIMES_S.size), TEMPLATES)


def test_a_core_keeps_the_general_inversion_only_where_that_one_is_ok():
    profile = depth_profile(_observed(0.07, 0.03, 8), np.full(TIMES_S.size, 0.03), TEMPLATES)
    ok = deep_inversion(profile, 0.03)
    flagged = dataclasses.replace(ok, status="not_characterised")
    general_ok = dataclasses.replace(ok, depth_m=0.075, alpha_m2s=1e-7, status="ok")
    general_flagged = dataclasses.replace(general_ok, status="weak_contrast")
    out = with_core_depths({1: general_ok, 2: general_flagged, 3: general_ok, 9: general_ok},
                           {1: ok, 2: flagged, 3: flagged, 4: flagged})
    assert out[1] is ok and out[2] is flagged and out[3] is general_ok and out[4] is flagged
    assert out[9] is general_ok


PIXEL_M = 0.01  # mosaic cell, m
HALF_PX = 20  # the rendered window is (41, 41) cells around the mine's axis


@pytest.fixture(scope="module")
def sand_day():
    """The demo's six scans of a clear November day on dry sand: the reference mine's
    profile curves (D, 6) K, and a function giving a buried AP mine's disc-ring contrast
    per scan (6,) K as the deep search measures it on an image of its modelled surface."""
    forcing = clear_sky_forcing(LAT_DEG, LON_DEG, DAY0_S, 86400.0)
    soil = soil_of_type("sand", 0.1)
    model = ObjectModel(soil, forcing, SCANS_S, REFERENCE_RADIUS_M)
    y, x = np.mgrid[-HALF_PX:HALF_PX + 1, -HALF_PX:HALF_PX + 1]
    radii = np.hypot(x, y).ravel() * PIXEL_M

    def measured(depth_m: float) -> np.ndarray:
        mine = BuriedObject(REFERENCE_RADIUS_M, REFERENCE_HEIGHT_M, depth_m, MATERIALS["tnt"])
        images = (model.surface_at(mine, radii) - model.background_k[:, None]).reshape(
            SCANS_S.size, *x.shape).astype(np.float32)
        return core_contrast(images, [(1, HALF_PX, HALF_PX)], REFERENCE_RADIUS_M / PIXEL_M)[:, 0]

    return reference_curves(forcing, soil, SCANS_S, PROFILE_DEPTHS_M), measured


@pytest.mark.parametrize(("depth_m", "score", "min_ok"), [
    (0.06, 10.0, 0.95), (0.07, 10.0, 0.95), (0.08, 10.0, 0.95), (0.07, 6.0, 0.4)])
def test_a_modelled_deep_mine_is_characterised_or_flagged(sand_day, depth_m, score, min_ok):
    """An AP mine at 6-8 cm in the thermal model, measured as disc minus ring on an image of
    its surface, with noise that puts it ``score`` sigmas over the six scans (the deep
    scenario's mines: 6-15): its depth within 1.5 cm on average and within its sigmas;
    at the deep search's cut (6) a fair share characterised, none confidently wrong."""
    templates, measured = sand_day
    curve = measured(depth_m)
    # what the disc and ring keep of the axis contrast: the gain's prior holds it
    axis = templates[int(np.argmin(np.abs(DEPTHS - depth_m)))]
    gain = float(curve @ axis / (axis @ axis))
    assert abs(gain - DISC_RING_GAIN) <= 2 * DISC_RING_GAIN_SIGMA
    noise = float(np.linalg.norm(curve)) / score
    rows = []
    for seed in range(40):
        seen = curve + np.random.default_rng(seed).normal(0.0, noise, curve.size)
        inv = deep_inversion(depth_profile(seen, np.full(curve.size, noise), templates), noise)
        rows.append((inv.status == "ok", inv.depth_m - depth_m, inv.depth_sigma_m))
    ok = np.array([r[0] for r in rows])
    error = np.abs([r[1] for r in rows])[ok]
    sigma = np.array([r[2] for r in rows])[ok]
    assert ok.mean() >= min_ok
    assert np.all(error <= 0.02)  # never confidently wrong
    assert np.mean(error) <= 0.01
    assert np.mean(error <= sigma) >= 0.5 and np.mean(error <= 2 * sigma) >= 0.9


@pytest.mark.parametrize("depth_m", [0.01, 0.20])
def test_a_modelled_mine_off_the_profile_is_flagged(sand_day, depth_m):
    """A mine shallower or deeper than the profile's depths (3-16 cm) meets its end: its
    depth is not characterised, however clean the curve."""
    templates, measured = sand_day
    curve = measured(depth_m)
    noise = 1e-3 * float(np.abs(curve).max())
    profile = depth_profile(curve, np.full(curve.size, noise), templates)
    assert profile.at_end
    assert deep_inversion(profile, noise).status == "not_characterised"
