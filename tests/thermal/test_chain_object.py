"""The chain's characterisation on small cases whose truth is known: an AP mine (M2A4, TNT)
in moist sand at 1, 3 and 5 cm under a clear November day (12 scans), measured as the chain
measures it (mean over the half-maximum footprint minus the mean over the blob's background
ring, :mod:`clearfast_gis.detection.features`) and seen in apparent temperature: the kinetic
contrast times a gain of 0.9 (a sand of band emissivity about 0.88 in 8-9.2 um).

:func:`clearfast_gis.thermal.sitesoil.characterise` models it as the mine type over the
footprint against the ring, times the gain it is given: within 0.25 cm and 12 % (0.15 cm
while the object's body was TNT's alone; the chain now averages over the mine bodies'
heat capacities, :mod:`clearfast_gis.thermal.bodies`, which these curves cannot tell apart
within the curve's own error terms). Without the gain the same curves come out shallow with
a higher diffusivity."""

from __future__ import annotations

import math

import numpy as np
import pytest

from clearfast_gis import thermal
from clearfast_gis.detection.features import AnomalyFeatures, ring_radii_px
from clearfast_gis.minetypes import MINE_TYPES
from clearfast_gis.thermal.sitesoil import characterise
from clearfast_gis.units import ZERO_CELSIUS_K

SOIL = thermal.MATERIALS["moist_sand"]
TNT = thermal.MATERIALS["tnt"]
AP = MINE_TYPES[0]
RADII_M = np.linspace(0.0, 0.3, 301)
CELL_M = 0.01
GAIN = 0.9


def mean_over(prof, a, b):
    """Area-weighted mean (S,) of the radial profile (S, R) between radii ``a`` and ``b``, m."""
    sel = (RADII_M >= a) & (RADII_M <= b)
    w = RADII_M[sel] + 1e-9
    return (prof[:, sel] * w).sum(axis=1) / w.sum()


def anomaly(forcing, times, depth_m, ident, soil=SOIL, material=TNT):
    """The features of an AP mine of body ``material`` at ``depth_m`` in ``soil`` as the
    detector would give them."""
    run = thermal.simulate_object(soil, thermal.BuriedObject(AP.radius_m, AP.height_m, depth_m,
                                                             material), forcing, times,
                                  radii_m=RADII_M)
    prof = GAIN * (np.asarray(run.surface_k) - np.asarray(run.background_k)[:, None])
    amp = np.sqrt(np.mean(prof**2, axis=0))
    r_half = float(RADII_M[np.nonzero(amp >= 0.5 * amp[0])[0].max()])
    d_px = 2.0 * r_half / CELL_M
    r_in, r_out = (CELL_M * r for r in ring_radii_px(0.5 * d_px))
    bg = np.asarray(run.background_k) - ZERO_CELSIUS_K
    centre, ring = bg + mean_over(prof, 0.0, r_half), bg + mean_over(prof, r_in, r_out)
    n = times.size
    return AnomalyFeatures(
        id=ident, row=0.0, col=0.0, x=0.0, y=0.0, area_px=int(np.pi * (0.5 * d_px) ** 2),
        area_m2=np.pi * r_half**2, diameter_px=d_px, diameter_m=2 * r_half, circularity=1.0,
        axis_ratio=1.0, compactness=1.0, polarity_per_scan=np.ones(n, dtype=int),
        polarity="warm", n_scans=n, centre_k=centre, ring_k=ring, contrast_k=centre - ring,
        noise_k=np.full(n, 0.02), score=10.0, blob_diameter_px=d_px)


@pytest.fixture(scope="module")
def case(forcing):
    times = forcing.time_s[0] + 3600.0 * (1.0 + 2.0 * np.arange(12))
    depths = (0.01, 0.03, 0.05)
    return times, depths, [anomaly(forcing, times, d, i + 1) for i, d in enumerate(depths)]


def test_the_chain_recovers_depth_and_diffusivity_with_the_gain(forcing, case):
    times, depths, feats = case
    out = characterise(feats, times, forcing, SOIL, gain=np.full(times.size, GAIN))
    for f, depth in zip(feats, depths, strict=True):
        inv = out[f.id]
        assert inv.status == "ok"
        assert abs(inv.depth_m - depth) < 0.0025, (depth, inv.depth_m)
        assert abs(math.log(inv.alpha_m2s / TNT.alpha_m2s)) < math.log(1.12)
        assert abs(inv.depth_m - depth) < 2 * inv.depth_sigma_m


def test_without_the_gain_the_contrast_looks_too_weak(forcing, case):
    times, depths, feats = case
    out = characterise(feats, times, forcing, SOIL)
    ratios = [out[f.id].alpha_m2s / TNT.alpha_m2s for f in feats]
    assert np.median(ratios) > 1.1
