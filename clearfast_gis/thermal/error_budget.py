"""The chain's own error terms of the depth and diffusivity estimates.

The fit's covariance (:func:`clearfast_gis.thermal.inversion.invert_anomaly`) covers the
scatter of the contrast curve about the model. What the chain does to that curve before the
fit is not in it; each term below is a 1-sigma depth (or log10 diffusivity) error measured on
simulated surveys by changing one link of the chain at a time (BENCHMARKS.md, "Depth bias";
the commands are in ``benchmarks/depth_bias.py``):

================================  =============  ==========================================
term                              depth, cm      how it was measured
================================  =============  ==========================================
object height (4-10 cm mines,     0.3            table built for 5 cm and 8 cm objects
table at 8 cm)                                   against an 8 cm mine: 0.3-0.5 cm apart
blur (sensor, mosaic, 1 cm        0.3            mosaics against the truth raster, the
lateral)                                         footprint mean in the table: 0.17 cm
                                                 (demo) and 0.38 cm (trial seed 0) apart
background ring (halo, texture)   0.1            ring at 1.5-2.5 radii against 5 cm beyond
                                                 the halo
soil terms (diffusivity, surface  0.2            surface terms from the thermocouple
fit, heat capacity)                              against the exact soil
registration (sub-pixel shifts    0.1            mosaics against the truth raster at the
between scans)                                   true positions
depth-proportional part           10 % of depth  the contrast falls ~e-fold per 3 cm: every
                                                 term above grows with depth
================================  =============  ==========================================

Diffusivity: the apparent-temperature contrast is the kinetic one times the band emissivity
(0.84-0.97 on sand) and a Planck-slope ratio; the soil's heat capacity is inferred from its
diffusivity (+-10 %). Together 0.1 in log10 alpha (26 %). The sensor's and the mosaic's blur
spread a 10 cm object's contrast beyond its footprint: with the footprint mean modelled in
the table, the mosaics gave 1.38-1.44 times the true diffusivity where the truth rasters gave
1.20-1.22 (trial and demo seed 0), 0.07 in log10 alpha.

The terms are independent and add in quadrature to the fit's variance.
"""

from __future__ import annotations

import dataclasses
import math

from clearfast_gis.thermal.inversion import MAX_DEPTH_SIGMA_M, Inversion
from clearfast_gis.thermal.table import DEFAULT_DEPTHS_M

DEPTH_TERMS_M = {"object_height": 0.003, "blur": 0.003, "background_ring": 0.001,
                 "soil_terms": 0.002, "registration": 0.001}
"""Constant 1-sigma depth terms of the chain, m (module notes)."""

DEPTH_RELATIVE = 0.10
"""Depth-proportional 1-sigma term, fraction of the estimated depth."""

LOG10_ALPHA_TERMS = {"emissivity_heat_capacity": 0.10, "blur": 0.07}
"""1-sigma log10 diffusivity terms of the chain (module notes)."""

LOG10_ALPHA_TERM = math.sqrt(sum(v * v for v in LOG10_ALPHA_TERMS.values()))
"""Their sum in quadrature."""


def chain_depth_sigma_m(depth_m: float) -> float:
    """The chain's 1-sigma depth error at an estimated depth ``depth_m`` (m), m."""
    const = math.sqrt(sum(v * v for v in DEPTH_TERMS_M.values()))
    return math.hypot(const, DEPTH_RELATIVE * max(depth_m, 0.0))


MAX_REPORTED_DEPTH_SIGMA_M = float(DEFAULT_DEPTHS_M[-1])
"""Depth sigmas are capped at the table's depth range, m (20 cm): a flat fit's covariance can
claim metres, which says no more than that the depth is undetermined."""


def with_chain_errors(inv: Inversion) -> Inversion:
    """``inv`` with the chain's error terms added in quadrature to its fit sigmas (the depth
    sigma capped at :data:`MAX_REPORTED_DEPTH_SIGMA_M`).

    An estimate that was ``ok`` becomes ``not_characterised`` when the total depth sigma
    exceeds :data:`~clearfast_gis.thermal.inversion.MAX_DEPTH_SIGMA_M`.
    """
    sd = math.hypot(inv.depth_sigma_m, chain_depth_sigma_m(inv.depth_m))
    sd = min(sd, MAX_REPORTED_DEPTH_SIGMA_M) if math.isfinite(sd) else MAX_REPORTED_DEPTH_SIGMA_M
    sla = math.hypot(inv.log10_alpha_sigma, LOG10_ALPHA_TERM)
    status = inv.status
    if status == "ok" and sd > MAX_DEPTH_SIGMA_M:
        status = "not_characterised"
    return dataclasses.replace(inv, depth_sigma_m=sd, log10_alpha_sigma=sla,
                               alpha_sigma_m2s=inv.alpha_m2s * math.log(10.0) * sla,
                               status=status)
