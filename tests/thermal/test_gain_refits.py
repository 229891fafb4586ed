"""The error budget's gain refits and the low-diffusivity rule of the inversion.

The gain term is propagated through the fit's Jacobian (linear); the chain also fits every
curve again with the model's contrast times 1 +- G, and keeps the larger move. A fit that asks
for a diffusivity at the table's low end (below any solid's) gives no depth.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from clearfast_gis.thermal import (
    MATERIALS,
    BuriedObject,
    invert_anomaly,
    simulate_object,
)
from clearfast_gis.thermal.error_budget import (
    GAIN_TERM,
    chain_sigmas,
    gain_sigma,
    with_chain_errors,
)
from clearfast_gis.thermal.inversion import MAX_DEPTH_SIGMA_M

RADIUS_M = 0.052
HEIGHT_M = 0.05
SOIL = MATERIALS["moist_sand"]
NOISE_K = 0.05


def _observe(forcing, scans, depth_m, material, seed=0):
    obj = BuriedObject(RADIUS_M, HEIGHT_M, depth_m, material)
    run = simulate_object(SOIL, obj, forcing, scans, refine=1)
    rng = np.random.default_rng(seed)
    return run.surface_k[:, 0] + rng.normal(0, NOISE_K, scans.size), run.background_k


def test_gain_sigma_is_the_terms_in_quadrature():
    assert gain_sigma() == pytest.approx(GAIN_TERM) == pytest.approx(math.hypot(0.08, 0.02))
    assert gain_sigma(0.2) == pytest.approx(math.hypot(GAIN_TERM, 0.2))


def test_refits_are_the_fits_of_the_rescaled_curve(forcing, scans, table):
    """Fitting (1 + G) times the model to a curve is fitting the model to the curve / (1 + G)."""
    centre, bg = _observe(forcing, scans, 0.02, MATERIALS["tnt"])
    g = 0.1
    inv = invert_anomaly(scans, centre, bg, forcing, SOIL, RADIUS_M, NOISE_K, table,
                         gain_sigma=g)
    assert inv.gain_refits.shape == (2, 2)
    for row, k in ((0, 1.0), (1, -1.0)):
        scaled = invert_anomaly(scans, bg + (centre - bg) / (1.0 + k * g), bg, forcing, SOIL,
                                RADIUS_M, NOISE_K, table)
        assert inv.gain_refits[row, 0] == pytest.approx(scaled.depth_m, abs=2e-4)
        assert inv.gain_refits[row, 1] == pytest.approx(math.log10(scaled.alpha_m2s), abs=2e-3)
    # along the depth-diffusivity valley: even this 48-scan fit moves by millimetres
    assert np.all(np.abs(inv.gain_refits[:, 0] - inv.depth_m) > 5e-4)


def test_no_refit_leaves_the_inversion_unchanged(forcing, scans, table):
    centre, bg = _observe(forcing, scans, 0.03, MATERIALS["tnt"])
    plain = invert_anomaly(scans, centre, bg, forcing, SOIL, RADIUS_M, NOISE_K, table)
    refit = invert_anomaly(scans, centre, bg, forcing, SOIL, RADIUS_M, NOISE_K, table,
                           gain_sigma=gain_sigma())
    assert plain.gain_refits is None
    assert (refit.depth_m, refit.alpha_m2s, refit.depth_sigma_m, refit.status) \
        == (plain.depth_m, plain.alpha_m2s, plain.depth_sigma_m, plain.status)


def test_a_refit_on_another_branch_counts_in_full(forcing, scans, table):
    """Where the refit jumps 3 cm, the depth sigma takes the jump and the status flags."""
    centre, bg = _observe(forcing, scans, 0.02, MATERIALS["tnt"])
    inv = invert_anomaly(scans, centre, bg, forcing, SOIL, RADIUS_M, NOISE_K, table,
                         gain_sigma=gain_sigma())
    narrow_d, _ = chain_sigmas(inv)
    assert narrow_d < MAX_DEPTH_SIGMA_M
    la = math.log10(inv.alpha_m2s)
    jumped = dataclasses.replace(inv, gain_refits=np.array([[inv.depth_m + 0.03, la],
                                                            [inv.depth_m, la]]))
    wide_d, _ = chain_sigmas(jumped)
    assert wide_d >= 0.03
    flagged = with_chain_errors(jumped)
    assert flagged.status == "not_characterised"
    # the curve is still well explained by a buried object: the likelihood reads that
    assert flagged.fit_status == "ok"
    assert with_chain_errors(inv).status == inv.status == "ok"


def test_linear_propagation_kept_when_the_refits_move_less(forcing, scans, table):
    centre, bg = _observe(forcing, scans, 0.02, MATERIALS["tnt"])
    inv = invert_anomaly(scans, centre, bg, forcing, SOIL, RADIUS_M, NOISE_K, table,
                         gain_sigma=gain_sigma())
    la = math.log10(inv.alpha_m2s)
    still = dataclasses.replace(inv, gain_refits=np.array([[inv.depth_m, la]] * 2))
    no_refit = dataclasses.replace(inv, gain_refits=None)
    assert chain_sigmas(still) == pytest.approx(chain_sigmas(no_refit))


def test_diffusivity_below_any_solid_gives_no_depth(forcing, scans, table):
    """A TNT mine's curve seen 10 % too strong: on 48 scans the fit trades depth for a
    diffusivity at the table's low end (3e-8 m2/s, a third of TNT's): no depth is given."""
    centre, bg = _observe(forcing, scans, 0.02, MATERIALS["tnt"])
    inv = invert_anomaly(scans, bg + (centre - bg) / 0.9, bg, forcing, SOIL, RADIUS_M,
                         NOISE_K, table)
    assert math.log10(inv.alpha_m2s) == pytest.approx(-7.5, abs=0.01)
    assert inv.status == "not_characterised"
    fine = invert_anomaly(scans, centre, bg, forcing, SOIL, RADIUS_M, NOISE_K, table)
    assert fine.status == "ok"


def test_the_likelihood_reads_the_fit_status():
    from clearfast_gis.detection.likelihood import FEATURES, features

    k = FEATURES.index("characterised")
    rec = {"score": 10.0, "diameter_m": 0.1, "circularity": 0.9}
    assert features({**rec, "status": "not_characterised", "fit_status": "ok"})[k] == 1.0
    assert features({**rec, "status": "not_characterised",
                     "fit_status": "not_characterised"})[k] == 0.0
    assert features({**rec, "status": "ok"})[k] == 1.0  # products without fit_status
