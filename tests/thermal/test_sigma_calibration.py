"""The depth and diffusivity sigmas cover the errors on small cases, on 6 scans and on 48.

AP-sized TNT objects at 1, 2 and 3 cm in moist sand (the forward model), their disc-mean
contrast observed through curve errors of the sizes the error budget states: a gain about 1 with
the budget's gain sigma, a ring offset with the budget's offset sigma, and 0.02 K of
scan-to-scan noise. Sampled by 48 scans over the day (the trial) and by 6 (the demo). The fit's
covariance with the curve terms propagated through its Jacobian must cover these errors (about
68 % within 1 sigma, 95 % within 2); the whole budget, which adds the model's terms (no model
error here, so it is cautious on these cases), must cover them too.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from clearfast_gis import thermal
from clearfast_gis.thermal.error_budget import (
    GAIN_TERM,
    OFFSET_TERM_K,
    curve_term_shifts,
    with_chain_errors,
)

RADIUS_M = 0.052
HEIGHT_M = 0.08
SOIL = thermal.MATERIALS["moist_sand"]
TNT = thermal.MATERIALS["tnt"]
NOISE_K = 0.02
DEPTHS_M = (0.01, 0.02, 0.03)
DRAWS = 12


@pytest.fixture(scope="module", params=[48, 6], ids=["48 scans", "6 scans"])
def scores(request, forcing, scans):
    """Per characterised draw: abs(error) / sigma of depth and of log10 diffusivity, with the
    fit's sigma and the curve terms only (columns 0, 1) and with the whole budget (2, 3)."""
    times = scans if request.param == 48 else scans[4::8]
    table = thermal.build_site_table(forcing, SOIL, RADIUS_M, times, height_m=HEIGHT_M,
                                     centre="disc")
    radii = (np.arange(6) + 0.5) / 6 * RADIUS_M  # annulus centres; weights: their areas
    rng = np.random.default_rng(21)
    rows = []
    for depth in DEPTHS_M:
        mine = thermal.BuriedObject(RADIUS_M, HEIGHT_M, depth, TNT)
        run = thermal.simulate_object(SOIL, mine, forcing, times, radii_m=radii, refine=1)
        disc = np.average(run.surface_k, axis=1, weights=radii) - run.background_k
        for _ in range(DRAWS):
            curve = (1.0 + rng.normal(0.0, GAIN_TERM)) * disc + rng.normal(0.0, OFFSET_TERM_K) \
                + rng.normal(0.0, NOISE_K, times.size)
            raw = thermal.invert_anomaly(times, curve, np.zeros_like(curve), forcing, SOIL,
                                         RADIUS_M, table=table)
            inv = with_chain_errors(raw)
            if inv.status != "ok":
                continue
            shifts = curve_term_shifts(raw.jacobian, raw.model_contrast_k)
            sd = math.hypot(raw.depth_sigma_m, *shifts[:, 0])
            sla = math.hypot(raw.log10_alpha_sigma, *shifts[:, 1])
            ed = abs(inv.depth_m - depth)
            ea = abs(math.log10(inv.alpha_m2s / TNT.alpha_m2s))
            rows.append((ed / sd, ea / sla, ed / inv.depth_sigma_m, ea / inv.log10_alpha_sigma))
    return np.array(rows)


def test_most_draws_are_characterised(scores):
    assert len(scores) >= 0.8 * len(DEPTHS_M) * DRAWS


@pytest.mark.parametrize("column", [0, 1], ids=["depth", "diffusivity"])
def test_the_propagated_curve_terms_cover_the_curve_errors(scores, column):
    z = scores[:, column]
    assert 0.5 <= np.mean(z <= 1) <= 0.9
    assert np.mean(z <= 2) >= 0.9


@pytest.mark.parametrize("column", [2, 3], ids=["depth", "diffusivity"])
def test_the_whole_budget_covers_them(scores, column):
    z = scores[:, column]
    assert np.mean(z <= 2) >= 0.95
    assert np.all(z <= scores[:, column - 2] + 1e-12)  # the model's terms only widen
