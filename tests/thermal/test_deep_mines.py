"""A deep mine is characterised within 2 sigma and 2 cm or flagged, never confidently wrong.

AP-sized TNT objects at 6, 7 and 8 cm in moist sand (the forward model), observed through the
chain's typical losses: 15 % of the contrast lost to blur (the mosaics' slope against the
truth raster was 0.69-0.96) and 0.02 K noise per scan. Sampled by 48 scans over the day (the
trial) and by 6 (the demo); the chain's terms follow the sampling through the fit's Jacobian.
"""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis import thermal
from clearfast_gis.thermal.error_budget import with_chain_errors

RADIUS_M = 0.052
HEIGHT_M = 0.08
SOIL = thermal.MATERIALS["moist_sand"]
NOISE_K = 0.02
GAIN = 0.85


@pytest.fixture(scope="module", params=[48, 6], ids=["48 scans", "6 scans"])
def sampled(request, forcing, scans):
    times = scans if request.param == 48 else scans[4::8]
    table = thermal.build_site_table(forcing, SOIL, RADIUS_M, times, height_m=HEIGHT_M,
                             centre="disc")
    return times, table


@pytest.mark.parametrize("depth_m", [0.06, 0.07, 0.08])
def test_deep_mine_within_two_sigma_or_flagged(forcing, sampled, depth_m):
    times, table = sampled
    mine = thermal.BuriedObject(RADIUS_M, HEIGHT_M, depth_m, thermal.MATERIALS["tnt"])
    radii = np.linspace(0.0, RADIUS_M, 7)[1:]
    run = thermal.simulate_object(SOIL, mine, forcing, times, radii_m=radii, refine=1)
    disc = np.average(run.surface_k, axis=1, weights=radii)  # area weights of the samples
    rng = np.random.default_rng(int(100 * depth_m))
    contrast = GAIN * (disc - run.background_k) + rng.normal(0, NOISE_K, times.size)
    inv = with_chain_errors(thermal.invert_anomaly(times, contrast, np.zeros_like(contrast),
                                                   forcing, SOIL, RADIUS_M, table=table))
    err = abs(inv.depth_m - depth_m)
    if inv.status == "ok":
        assert err <= 2 * inv.depth_sigma_m
        assert err <= 0.02
    else:
        assert inv.status in ("weak_contrast", "not_characterised", "at_bound")
