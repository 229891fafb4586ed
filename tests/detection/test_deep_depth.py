"""A deep core's depth from its curve's shape: a deep mine of known depth comes out within
its sigma, and what the data cannot tell is flagged."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from clearfast_gis.detection.deep_depth import (
    DISC_RING_GAIN,
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
from tests.detection.test_classify import _feat

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
