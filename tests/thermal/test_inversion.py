from __future__ import annotations

import time

import numpy as np
import pytest

from clearfast_gis.errors import InvalidInput
from clearfast_gis.thermal import (
    MATERIALS,
    BuriedObject,
    build_site_table,
    invert_anomaly,
    simulate_object,
)

RADIUS_M = 0.052
SOIL = MATERIALS["moist_sand"]
NOISE_K = 0.05
HEIGHT_M = 0.05


def _observe(forcing, scans, depth_m, material="tnt", seed=0):
    """Truth from the twice-finer model, 0.05 K noise on the centre."""
    obj = BuriedObject(RADIUS_M, HEIGHT_M, depth_m, MATERIALS[material])
    run = simulate_object(SOIL, obj, forcing, scans, refine=1)
    rng = np.random.default_rng(seed)
    return run.surface_k[:, 0] + rng.normal(0, NOISE_K, scans.size), run.background_k


@pytest.mark.parametrize("depth_m", [0.0, 0.02, 0.04])
def test_shallow_tnt_recovered(forcing, scans, table, depth_m):
    centre, bg = _observe(forcing, scans, depth_m)
    inv = invert_anomaly(scans, centre, bg, forcing, SOIL, RADIUS_M, NOISE_K, table)
    assert inv.status == "ok"
    assert inv.depth_m == pytest.approx(depth_m, abs=0.005)
    assert inv.alpha_m2s == pytest.approx(MATERIALS["tnt"].alpha_m2s, rel=0.25)
    assert 0 < inv.depth_sigma_m < 0.005
    assert inv.residual_rms_k < 2 * NOISE_K


def test_deep_object_is_weak_contrast(forcing, scans, table):
    centre, bg = _observe(forcing, scans, 0.15)
    inv = invert_anomaly(scans, centre, bg, forcing, SOIL, RADIUS_M, NOISE_K, table)
    assert inv.status == "weak_contrast"


def test_metal_object_is_at_bound(forcing, scans, table):
    centre, bg = _observe(forcing, scans, 0.01, "aluminium")
    inv = invert_anomaly(scans, centre, bg, forcing, SOIL, RADIUS_M, NOISE_K, table)
    assert inv.status == "at_bound"
    assert inv.alpha_m2s > 1e-5


def test_data_the_cylinder_cannot_explain_is_not_characterised(forcing, scans, table):
    centre, bg = _observe(forcing, scans, 0.02)
    wobble = 0.6 * np.sin(2 * np.pi * (scans - scans[0]) / 21600.0)
    inv = invert_anomaly(scans, centre + wobble, bg, forcing, SOIL, RADIUS_M, NOISE_K, table)
    assert inv.status == "not_characterised"


def test_inversion_is_fast_with_a_table(forcing, scans, table):
    centre, bg = _observe(forcing, scans, 0.03)
    tic = time.perf_counter()
    for _ in range(5):
        invert_anomaly(scans, centre, bg, forcing, SOIL, RADIUS_M, NOISE_K, table)
    assert (time.perf_counter() - tic) / 5 < 0.5


def test_radius_outside_the_table_is_rejected(forcing, scans, table):
    centre, bg = _observe(forcing, scans, 0.02)
    with pytest.raises(InvalidInput, match="radius_m"):
        invert_anomaly(scans, centre, bg, forcing, SOIL, 0.17, NOISE_K, table)


def test_disc_table_holds_the_footprint_mean(forcing, scans):
    """The chain's table (centre="disc"): per radius the model's mean over the object's disc,
    smaller than the axis value (the surface falls off towards the rim) but of its sign; the
    same values whether a radius is built alone or with others."""
    grid = {"depths_m": [0.0, 0.01, 0.02, 0.04], "log10_alpha": [-7.5, -7.0, -6.5, -6.0]}
    disc = build_site_table(forcing, SOIL, [RADIUS_M, 0.1], scans, centre="disc", **grid)
    alone = build_site_table(forcing, SOIL, RADIUS_M, scans, centre="disc", **grid)
    axis = build_site_table(forcing, SOIL, RADIUS_M, scans, **grid)
    assert disc.centre == "disc" and axis.centre == "axis"
    np.testing.assert_allclose(disc.contrast_k[0], alone.contrast_k[0], atol=1e-9)
    a, d = axis.contrast_k[0, 1, 1], disc.contrast_k[0, 1, 1]  # TNT-like object at 1 cm
    peak = np.argmax(np.abs(a))
    assert np.sign(d[peak]) == np.sign(a[peak])
    assert 0.3 * abs(a[peak]) < abs(d[peak]) < abs(a[peak])
    with pytest.raises(InvalidInput):
        build_site_table(forcing, SOIL, RADIUS_M, scans, centre="rim", **grid)
