"""The surface balance fitted to the shallowest thermocouple: latent heat and heat capacity.

A dry model fitted to a soil that evaporates moved the latent heat into the albedo and put AP
mines 1-2 cm too shallow on clay and loam (issue #22); the balance fit (albedo, convective
scale, wetness, heat capacity) takes them from the thermocouple and the weather alone. Under
grass, the cover the survey records for its site puts the soil under the canopy.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from clearfast_gis.simulate.surface import soils
from clearfast_gis.thermal import simulate_background
from clearfast_gis.thermal.canopy import under_canopy
from clearfast_gis.thermal.inversion import invert_anomaly
from clearfast_gis.thermal.moisture import wetness_factor
from clearfast_gis.thermal.sitesoil import (
    CHAIN_TABLE_CENTRE,
    chain_site_table,
    site_soil,
    soil_from_diffusivity,
)
from clearfast_gis.thermal.soils import soil_of_type
from clearfast_gis.thermal.surface_fit import fit_surface_balance, fit_surface_parameters
from clearfast_gis.thermal.table import build_site_table

from .conftest import DAY0_S

TC_DEPTH_M = 0.02
RADIUS_M, HEIGHT_M = 0.052, 0.08
SCANS_S = DAY0_S + 3600.0 + 14400.0 * np.arange(6)
DEPTHS_M = (0.01, 0.03)


def thermocouple(truth, forcing):
    t = DAY0_S + 1200.0 * np.arange(72)
    return t, simulate_background(truth, forcing, t, depths_m=(TC_DEPTH_M,)).profile_k[:, 0]


def depth_errors_cm(truth, chain_soil, forcing):
    """Depth error (cm) of AP mines (TNT) at DEPTHS_M whose disc-mean contrast is the truth
    soil's, inverted with ``chain_soil``."""
    la = np.log10(1e-7)
    true_tab = build_site_table(forcing, truth, RADIUS_M, SCANS_S, height_m=HEIGHT_M,
                                depths_m=(0.0, *DEPTHS_M, 0.05),
                                log10_alpha=(la - 0.2, la - 0.1, la, la + 0.1),
                                centre=CHAIN_TABLE_CENTRE)
    curves = true_tab.contrast_for(RADIUS_M, SCANS_S)[1:1 + len(DEPTHS_M), 2]
    tab = build_site_table(forcing, chain_soil, RADIUS_M, SCANS_S, height_m=HEIGHT_M,
                           centre=CHAIN_TABLE_CENTRE)
    base = np.full(SCANS_S.size, 290.0)
    return np.array([100 * (invert_anomaly(SCANS_S, base + c, base, forcing, chain_soil,
                                           RADIUS_M, noise_k=0.05, table=tab).depth_m - d)
                     for d, c in zip(DEPTHS_M, curves, strict=True)])


@pytest.fixture(scope="module")
def clay():
    return replace(soil_of_type("clay", 0.4), albedo=0.17)


@pytest.fixture(scope="module")
def clay_fits(clay, forcing):
    t, tc = thermocouple(clay, forcing)
    start = soil_from_diffusivity(clay.alpha_m2s)
    dry, dry_rms = fit_surface_parameters(start, forcing, t, tc, depth_m=TC_DEPTH_M)
    wet, wet_rms = fit_surface_balance(start, forcing, t, tc, depth_m=TC_DEPTH_M)
    return dry, dry_rms, wet, wet_rms


def test_balance_fit_recovers_an_evaporating_clay(clay, clay_fits):
    dry, dry_rms, wet, wet_rms = clay_fits
    assert dry.albedo > 0.35 and dry_rms > 0.3      # the latent heat went into the albedo
    assert wet_rms < 0.05 and wet.water is not None
    assert wet.albedo == pytest.approx(clay.albedo, abs=0.04)
    assert wet.rho_c_jm3k == pytest.approx(clay.rho_c_jm3k, rel=0.06)
    assert wet.alpha_m2s == pytest.approx(clay.alpha_m2s, rel=1e-9)
    beta_true = wetness_factor(clay.water.theta_deep, clay.water.theta_fc)
    beta_fit = wetness_factor(wet.water.theta_deep, wet.water.theta_fc)
    assert beta_fit == pytest.approx(beta_true, abs=0.08)


def test_mines_in_evaporating_clay_come_out_at_their_depth(clay, clay_fits, forcing):
    dry, _, wet, _ = clay_fits
    assert np.all(depth_errors_cm(clay, dry, forcing) < -0.7)
    assert np.all(np.abs(depth_errors_cm(clay, wet, forcing)) < 0.25)


def test_a_soil_without_water_is_fitted_dry(forcing):
    truth = replace(soils()["site"], albedo=0.26)
    t, tc = thermocouple(truth, forcing)
    wet, rms = fit_surface_balance(soil_from_diffusivity(truth.alpha_m2s), forcing, t, tc,
                                   depth_m=TC_DEPTH_M)
    assert rms < 0.05
    assert wet.water is None          # a wet model fits no better: no latent heat, no dew
    assert wet.rho_c_jm3k == pytest.approx(truth.rho_c_jm3k, rel=0.06)
    assert wet.albedo == pytest.approx(0.26, abs=0.03)


def test_the_balance_fit_needs_a_buried_sensor(forcing):
    from clearfast_gis.errors import InvalidInput

    with pytest.raises(InvalidInput):
        fit_surface_balance(soils()["site"], forcing, SCANS_S, np.full(6, 290.0), depth_m=0.0)


def test_mines_under_grass_with_the_site_cover_come_out_at_their_depth(forcing):
    """Under a 40 % grass cover the soil (and its thermocouple) sees less sun and the leaves'
    long-wave, and the camera sees 0.6 of a buried mine's contrast: without the cover the
    mines came out 1-1.6 cm too deep; with the cover the survey records, at their depth."""
    cover = 0.4
    truth = replace(soils()["site"], albedo=0.26)
    shaded = under_canopy(forcing, cover)
    t = DAY0_S + 600.0 * np.arange(145)
    run = simulate_background(truth, shaded, t, depths_m=(0.02, 0.05, 0.10, 0.20, 0.50))
    log = {"time_s": t, "depth_m": np.array([0.02, 0.05, 0.10, 0.20, 0.50]),
           "temp_c": run.profile_k - 273.15}
    la = np.log10(1e-7)
    seen = (1 - cover) * build_site_table(
        shaded, truth, RADIUS_M, SCANS_S, height_m=HEIGHT_M, depths_m=(0.0, *DEPTHS_M, 0.05),
        log10_alpha=(la - 0.2, la - 0.1, la, la + 0.1),
        centre=CHAIN_TABLE_CENTRE).contrast_for(RADIUS_M, SCANS_S)[1:1 + len(DEPTHS_M), 2]
    base = np.full(SCANS_S.size, 290.0)
    nan = np.full(SCANS_S.size, np.nan)
    for canopy, ok in ((0.0, False), (cover, True)):
        soil, _, _ = site_soil(log, forcing, SCANS_S, nan, canopy=canopy)
        tab = chain_site_table(under_canopy(forcing, canopy), soil, RADIUS_M, SCANS_S, canopy)
        err = np.array([invert_anomaly(SCANS_S, base + c, base, forcing, soil, RADIUS_M,
                                       noise_k=0.05, table=tab).depth_m - d
                        for d, c in zip(DEPTHS_M, seen, strict=True)])
        if ok:
            assert np.all(np.abs(err) < 0.0025), err
        else:
            assert np.all(err > 0.007), err


def test_a_recorded_cover_is_uncertain_and_widens_the_depth_sigma(forcing):
    from clearfast_gis.thermal.canopy import RECORDED_COVER_SIGMA, cover_gain_sigma
    from clearfast_gis.thermal.error_budget import with_chain_errors

    assert cover_gain_sigma(0.0) == 0.0
    assert cover_gain_sigma(0.4) == pytest.approx(RECORDED_COVER_SIGMA / 0.6)
    soil = soils()["site"]
    tab = build_site_table(forcing, soil, RADIUS_M, SCANS_S, height_m=HEIGHT_M,
                           centre=CHAIN_TABLE_CENTRE)
    curve = tab.contrast_for(RADIUS_M, SCANS_S)[2, 2]          # a node: 1-2 cm, TNT-like
    base = np.full(SCANS_S.size, 290.0)
    inv = invert_anomaly(SCANS_S, base + curve, base, forcing, soil, RADIUS_M, noise_k=0.05,
                         table=tab)
    bare, grass = with_chain_errors(inv), with_chain_errors(inv, cover_gain_sigma(0.4))
    assert grass.depth_sigma_m > 1.1 * bare.depth_sigma_m
    assert with_chain_errors(inv, 0.0) == bare
