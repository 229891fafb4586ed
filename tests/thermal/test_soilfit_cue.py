from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.errors import InvalidInput
from clearfast_gis.thermal import (
    MATERIALS,
    fit_soil_diffusivity,
    fit_surface_parameters,
    material_cue,
    simulate_background,
)

from .conftest import DAY0_S

DEPTHS = np.array([0.02, 0.05, 0.10, 0.20, 0.50])


@pytest.mark.parametrize("name", ["dry_sand", "moist_sand"])
def test_soil_diffusivity_recovered_from_a_simulated_log(forcing, name):
    soil = MATERIALS[name]
    t = DAY0_S + 600.0 * np.arange(145)
    run = simulate_background(soil, forcing, t, depths_m=DEPTHS)
    rng = np.random.default_rng(3)
    log = {"time_s": t, "depth_m": DEPTHS,
           "temp_c": run.profile_k - 273.15 + rng.normal(0, 0.05, run.profile_k.shape)}
    alpha, sigma = fit_soil_diffusivity(log)
    assert alpha == pytest.approx(soil.alpha_m2s, rel=0.10)
    assert 0 < sigma < 0.1 * alpha
    assert abs(alpha - soil.alpha_m2s) < 5 * sigma + 0.03 * soil.alpha_m2s


def test_soil_log_needs_three_depths():
    log = {"time_s": np.arange(20.0), "depth_m": np.array([0.02, 0.5]),
           "temp_c": np.zeros((20, 2))}
    with pytest.raises(InvalidInput, match="depth_m"):
        fit_soil_diffusivity(log)


def test_surface_parameters_recovered_from_background(forcing, scans):
    from dataclasses import replace

    truth = replace(MATERIALS["dry_sand"], albedo=0.22, hc_scale=1.3)
    bg = simulate_background(truth, forcing, scans).surface_k
    fitted, rms = fit_surface_parameters(MATERIALS["dry_sand"], forcing, scans, bg)
    assert fitted.albedo == pytest.approx(0.22, abs=0.02)
    assert fitted.hc_scale == pytest.approx(1.3, rel=0.1)
    assert rms < 0.05


@pytest.mark.parametrize(
    ("material", "best"),
    [("tnt", "explosive"), ("plastic", "explosive"), ("stone", "stone"), ("steel", "metal"),
     ("aluminium", "metal"), ("moist_sand", "soil")],
)
def test_material_cue_names_the_material_class(material, best):
    alpha = MATERIALS[material].alpha_m2s
    cue = material_cue(alpha, 0.1 * alpha)
    assert cue["best"] == best
    probs = [cue[k] for k in ("explosive", "soil", "stone", "metal")]
    assert sum(probs) == pytest.approx(1.0)
    assert cue[best] > 0.5


def test_material_cue_of_a_vague_or_missing_estimate():
    assert material_cue(float("nan"), 1.0)["best"] == "unknown"
    vague = material_cue(1e-7, 1e-6)  # sigma ten times the value: no class stands out
    assert max(vague[k] for k in ("explosive", "soil", "stone", "metal")) < 0.6
    assert material_cue(1e-2, 1e-3)["best"] == "metal"
