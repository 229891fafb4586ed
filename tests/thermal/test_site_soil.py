"""The site's soil for the inversion: heat capacity from the diffusivity, surface terms from
the shallowest thermocouple (kinetic), not from the apparent temperature of the mosaics."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from clearfast_gis.simulate.surface import soils
from clearfast_gis.thermal import MATERIALS, fit_surface_parameters, simulate_background
from clearfast_gis.thermal.sitesoil import site_soil, soil_from_diffusivity

from .conftest import DAY0_S

DEPTHS = np.array([0.02, 0.05, 0.10, 0.20, 0.50])


@pytest.mark.parametrize("name", ["dry_sand", "moist_sand"])
def test_end_member_sands_are_themselves(name):
    sand = MATERIALS[name]
    soil = soil_from_diffusivity(sand.alpha_m2s)
    assert soil.rho_c_jm3k == pytest.approx(sand.rho_c_jm3k, rel=1e-6)
    assert soil.k_wmk == pytest.approx(sand.k_wmk, rel=1e-6)


def test_half_moist_sand_conductivity_within_five_percent():
    """The simulator's site soil (mean of the end-members): k 0.70 W/m/K. A moist-sand heat
    capacity would give 0.82 (+17 %)."""
    site = soils()["site"]
    soil = soil_from_diffusivity(site.alpha_m2s)
    assert soil.k_wmk == pytest.approx(site.k_wmk, rel=0.05)


def test_surface_terms_from_a_thermocouple_at_two_centimetres(forcing, scans):
    truth = replace(MATERIALS["moist_sand"], albedo=0.27, hc_scale=0.8)
    run = simulate_background(truth, forcing, scans, depths_m=(0.02,))
    fitted, rms = fit_surface_parameters(MATERIALS["moist_sand"], forcing, scans,
                                         run.profile_k[:, 0], depth_m=0.02)
    assert fitted.albedo == pytest.approx(0.27, abs=0.02)
    assert fitted.hc_scale == pytest.approx(0.8, rel=0.1)
    assert rms < 0.05


def test_site_soil_ignores_an_apparent_temperature_background(forcing, scans):
    """With a thermocouple at 2 cm, a background 4 K colder with a 30 % smaller swing (what a
    0.85-emissivity sand under a cold sky shows) does not move the surface terms."""
    truth = replace(soils()["site"], albedo=0.26, hc_scale=1.0)
    t = DAY0_S + 600.0 * np.arange(145)
    run = simulate_background(truth, forcing, t, depths_m=DEPTHS)
    rng = np.random.default_rng(1)
    log = {"time_s": t, "depth_m": DEPTHS,
           "temp_c": run.profile_k - 273.15 + rng.normal(0, 0.05, run.profile_k.shape)}
    surface = simulate_background(truth, forcing, scans).surface_k - 273.15
    apparent = surface.mean() - 4.0 + 0.7 * (surface - surface.mean())
    soil, alpha, sigma = site_soil(log, forcing, scans, apparent)
    assert alpha == pytest.approx(truth.alpha_m2s, rel=0.05)
    assert soil.albedo == pytest.approx(0.26, abs=0.03)
    assert soil.hc_scale == pytest.approx(1.0, rel=0.15)
    assert soil.k_wmk == pytest.approx(truth.k_wmk, rel=0.07)
