"""The inversion's prior on a mine's diffusivity (``invert_anomaly(alpha_prior=...)``).

Six scans of a day on dry sand explain a TNT mine at 3 cm about as well as an object a few
millimetres deep that conducts faster: the free fit's chi-square is flat along that trade. The
prior of mine fills (:data:`clearfast_gis.thermal.materials.MINE_FILL_LOG10_ALPHA`) picks the
depth there; where the curve does determine the diffusivity (a stone, 48 scans) it stays the
curve's.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from clearfast_gis.thermal import (
    MATERIALS,
    BuriedObject,
    clear_sky_forcing,
    invert_anomaly,
    simulate_object,
)
from clearfast_gis.thermal.error_budget import curve_term_shifts, with_chain_errors
from clearfast_gis.thermal.materials import MINE_FILL_LOG10_ALPHA, MINE_FILLS
from clearfast_gis.thermal.measure import anomaly_measure
from clearfast_gis.thermal.sitesoil import chain_site_table
from clearfast_gis.thermal.table import build_site_table
from clearfast_gis.timeutil import parse_utc
from clearfast_gis.units import ZERO_CELSIUS_K

from .test_chain_object import GAIN, anomaly

RADIUS_M, HEIGHT_M = 0.052, 0.05
DRY = MATERIALS["dry_sand"]
MOIST = MATERIALS["moist_sand"]
DEPTHS_M = [0.0, 0.01, 0.02, 0.03, 0.04, 0.06, 0.08, 0.10, 0.15, 0.20]
LOG10_ALPHA = [-7.5, -7.25, -7.0, -6.75, -6.5, -6.25, -6.0, -5.5, -5.0, -4.5]


def test_the_prior_is_the_handbook_range_of_fills_and_casings():
    """1.2e-7 m2/s, 1 sigma 0.85-1.7e-7: TNT (1.0e-7), Composition B (1.1e-7) and plastic
    casings (1.7e-7) inside,
    dry sand (2.3e-7) beyond 1 sigma, moist sand (6.1e-7) and stone (1.3e-6) beyond 2."""
    mean, sigma = MINE_FILL_LOG10_ALPHA
    assert 10**mean == pytest.approx(1.2e-7, rel=0.01)
    for name in ("tnt", "comp_b", "plastic"):
        assert abs(math.log10(MATERIALS[name].alpha_m2s) - mean) <= sigma
    # every body the twin can give a mine within 1.2 sigma (the wooden box mine, 0.82e-7,
    # at 1.1), and their mean within a third of sigma of the prior's
    fills = [math.log10(MATERIALS[name].alpha_m2s) for name in MINE_FILLS]
    assert max(abs(f - mean) for f in fills) <= 1.2 * sigma
    assert abs(np.mean(fills) - mean) <= sigma / 3
    assert abs(math.log10(MATERIALS["dry_sand"].alpha_m2s) - mean) > sigma
    for name in ("moist_sand", "stone"):
        assert abs(math.log10(MATERIALS[name].alpha_m2s) - mean) > 2 * sigma


SIX_HOURS = np.array([2.0, 6.0, 10.0, 14.0, 18.0, 22.0])
"""Six scans 4 h apart, hours after the forcing's start."""


def _curves(forcing, scans, soil, depth_m, material, noise_k, seeds):
    obj = BuriedObject(RADIUS_M, HEIGHT_M, depth_m, material)
    run = simulate_object(soil, obj, forcing, scans, refine=1)
    for seed in seeds:
        rng = np.random.default_rng(seed)
        yield run.surface_k[:, 0] + rng.normal(0.0, noise_k, scans.size), run.background_k


def test_a_prior_as_wide_as_the_table_is_the_free_fit(forcing):
    scans = forcing.time_s[0] + 3600.0 * SIX_HOURS
    table = build_site_table(forcing, DRY, RADIUS_M, scans, height_m=HEIGHT_M,
                             depths_m=DEPTHS_M, log10_alpha=LOG10_ALPHA)
    centre, bg = next(_curves(forcing, scans, DRY, 0.02, MATERIALS["tnt"], 0.02, [0]))
    free = invert_anomaly(scans, centre, bg, forcing, DRY, RADIUS_M, table=table)
    wide = invert_anomaly(scans, centre, bg, forcing, DRY, RADIUS_M, table=table,
                          alpha_prior=(-6.9, 1e3))
    assert wide.depth_m == pytest.approx(free.depth_m, abs=1e-4)
    assert math.log10(wide.alpha_m2s) == pytest.approx(math.log10(free.alpha_m2s), abs=1e-3)
    assert free.prior_normal is None and wide.prior_normal[1, 1] > 0


def _dry_season_mine():
    """An AP mine (TNT) at 3 cm in moist sand under the dry season's sun at 12 N, six scans,
    measured as the chain measures it: (forcing, times s, feature, measure, the inversion's
    keywords, ring K)."""
    forcing = clear_sky_forcing(12.0, 0.0, parse_utc("2026-02-15T00:00:00Z"), 86400.0)
    times = forcing.time_s[0] + 3600.0 * SIX_HOURS
    feature = anomaly(forcing, times, 0.03, 1, soil=MOIST)
    m = anomaly_measure(feature)
    table = chain_site_table(forcing, MOIST, m.radius_m, times, 0.0, m.height_m)
    kw = dict(table=table, over_m=m.over_m, ring_m=m.ring_m, gain=np.full(times.size, GAIN))
    ring = feature.ring_k + ZERO_CELSIUS_K
    return forcing, times, feature, m, kw, ring


def test_on_six_scans_the_prior_gives_the_mine_depth_the_free_fit_trades_away():
    """An AP mine (TNT) at 3 cm in moist sand (a soil six times as diffusive as the fill)
    under the dry season's sun at 12 N, six scans, measured as the chain measures it
    (footprint minus ring, an apparent gain of 0.9), 30 mK of noise, 20 draws: the free
    fit wanders along the depth-diffusivity trade (MAE 0.42 cm), the prior halves that
    (0.20 cm), and its sigmas with the chain's terms cover the errors."""
    forcing, times, feature, m, kw, ring = _dry_season_mine()
    free_err, prior_err, z = [], [], []
    for seed in range(20):
        centre = feature.centre_k + ZERO_CELSIUS_K \
            + np.random.default_rng(seed).normal(0.0, 0.03, times.size)
        free = invert_anomaly(times, centre, ring, forcing, MOIST, m.radius_m, **kw)
        fill = with_chain_errors(invert_anomaly(times, centre, ring, forcing, MOIST,
                                                m.radius_m, alpha_prior=MINE_FILL_LOG10_ALPHA,
                                                **kw))
        free_err.append(abs(free.depth_m - 0.03))
        prior_err.append(abs(fill.depth_m - 0.03))
        z.append(prior_err[-1] / fill.depth_sigma_m)
    assert np.mean(prior_err) < 0.75 * np.mean(free_err)
    assert np.mean(prior_err) <= 0.003
    assert np.mean(np.asarray(z) <= 1.0) >= 0.6 and np.mean(np.asarray(z) <= 2.0) >= 0.9


def test_a_stone_keeps_its_own_diffusivity(forcing, scans):
    """48 scans of a granite cobble at 1 cm: the curve fixes its diffusivity (1.3e-6 m2/s),
    seven prior sigmas from a mine's, and the prior does not pull it to a mine's."""
    table = build_site_table(forcing, DRY, RADIUS_M, scans, height_m=HEIGHT_M,
                             depths_m=DEPTHS_M, log10_alpha=LOG10_ALPHA)
    centre, bg = next(_curves(forcing, scans, DRY, 0.01, MATERIALS["stone"], 0.02, [1]))
    free = invert_anomaly(scans, centre, bg, forcing, DRY, RADIUS_M, table=table)
    fill = invert_anomaly(scans, centre, bg, forcing, DRY, RADIUS_M, table=table,
                          alpha_prior=MINE_FILL_LOG10_ALPHA)
    assert fill.alpha_m2s > 6e-7
    assert abs(math.log10(fill.alpha_m2s / free.alpha_m2s)) < 0.15
    # what the products report and the material cue reads is the curve's own
    assert fill.diffusivity_m2s == pytest.approx(free.alpha_m2s, rel=1e-6)
    assert fill.diffusivity_sigma_m2s == pytest.approx(free.alpha_sigma_m2s, rel=1e-3)
    assert free.diffusivity_m2s == free.alpha_m2s


def test_the_prior_damps_the_curve_terms_along_the_diffusivity():
    """``(J^T J + P)^-1 J^T delta``: a zero P is the plain propagation; a positive one on
    log10 alpha shrinks the diffusivity's shift."""
    j = np.array([[1.0, 0.9], [0.8, 0.75], [0.5, 0.48], [0.2, 0.21]])
    model = np.array([0.5, 0.4, 0.2, 0.1])
    plain = curve_term_shifts(j, model)
    np.testing.assert_allclose(curve_term_shifts(j, model, prior_normal=np.zeros((2, 2))),
                               plain)
    damped = curve_term_shifts(j, model, prior_normal=np.diag([0.0, 1.0]))
    assert np.all(np.abs(damped[:, 1]) < np.abs(plain[:, 1]))


def test_what_the_likelihood_reads_is_the_curve_alone():
    """The prior is a mine's diffusivity, so it must not vouch for a mine: the fit status the
    mine likelihood reads (``fit_status``) is the curve's own. The same six dry-season scans
    of an AP mine at 3 cm, nine noise draws: with the prior every depth is ``ok``, but where
    the free fit's depth valley is flat (or has a rival) the curve alone is not
    characterised, and ``fit_status`` says so, as it does without the prior."""
    forcing, times, feature, m, kw, ring = _dry_season_mine()
    flagged = 0
    for seed in range(9):
        centre = feature.centre_k + ZERO_CELSIUS_K \
            + np.random.default_rng(seed).normal(0.0, 0.03, times.size)
        free = invert_anomaly(times, centre, ring, forcing, MOIST, m.radius_m, **kw)
        fill = invert_anomaly(times, centre, ring, forcing, MOIST, m.radius_m,
                              alpha_prior=MINE_FILL_LOG10_ALPHA, **kw)
        assert fill.status == "ok"
        assert fill.curve_status == free.status
        assert fill.curve_depth_sigma_m == pytest.approx(free.depth_sigma_m, rel=1e-9)
        assert free.curve_status is None and free.curve_depth_sigma_m is None
        judged = with_chain_errors(fill)
        assert judged.fit_status == with_chain_errors(free).fit_status
        flagged += judged.fit_status != "ok"
    assert flagged >= 2
