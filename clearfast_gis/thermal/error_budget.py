"""The chain's own error terms of the depth and diffusivity estimates.

The fit's covariance (:func:`clearfast_gis.thermal.inversion.invert_anomaly`) covers the
scatter of the contrast curve about the model: what changes from scan to scan shows in the
residuals. What the chain does to the whole curve before the fit does not: the fit absorbs it
into the estimates. Two kinds of chain terms are added in quadrature:

**Errors of the curve, propagated through the fit.** A systematic error ``delta_c`` (K, one
value per scan) of the contrast curve moves the estimates by ``(J^T J)^-1 J^T delta_c``, with
``J`` the fit's own Jacobian at the estimate (:attr:`Inversion.jacobian`): the same error
costs a weak (deep) object's estimate much more than a strong one's, and how much depends on
when the survey's scans sample the day. Three such errors, each measured as 1 sigma on
simulated surveys (``benchmarks/contrast_gain.py``):

================================  ==============  =========================================
term                              1 sigma         how it was measured
================================  ==============  =========================================
gain: blur and registration       8 % of the      mosaic contrast against the truth
(sensor, mosaic, sub-pixel        contrast        raster's at the mines' true positions,
shifts between scans)                             slope per mine: 0.84 +- 0.08 (27 mines at
                                                  0-5 cm, demo seeds 20-22 and the deep
                                                  scenario's 20-22); the mean loss is
                                                  modelled (footprint mean in the table),
                                                  the spread is the term
gain: band emissivity and         6 %             sand's band emissivity 0.84-0.97 and the
Planck slope of the apparent                      Planck slope of the apparent contrast
contrast
offset: background ring           0.012 K         the same regression's intercepts (rms)
================================  ==============  =========================================

**Errors of the model, as depth (m) and log10 diffusivity terms**, measured by changing one
link at a time (BENCHMARKS.md, "Depth bias"; ``benchmarks/depth_bias.py``):

================================  =============  ==========================================
term                              depth, cm      how it was measured
================================  =============  ==========================================
object height (4-10 cm mines,     0.3            table built for 5 cm and 8 cm objects
table at 8 cm)                                   against an 8 cm mine: 0.3-0.5 cm apart
background ring (halo, texture)   0.1            ring at 1.5-2.5 radii against 5 cm beyond
                                                 the halo
soil terms (diffusivity, surface  0.2            surface terms from the thermocouple
fit, heat capacity)                              against the exact soil
depth-proportional part           10 % of depth  deep, small objects trade depth for
                                                 diffusivity: AP mines at 5-10 cm came out
                                                 1-2 cm shallow from their true positions
                                                 (truth rasters and mosaics alike)
================================  =============  ==========================================

Diffusivity: the soil's heat capacity is inferred from its diffusivity (+-10 %), 0.04 in
log10 alpha; and the apparent contrast and the blur the footprint-mean table does not model,
0.09 in log10 alpha: the chain's diffusivities of the 17 mines at 0-4 cm characterised on demo
seeds 20-22 and the deep scenario's seeds 20-22 were 10^(0.085 +- 0.064) times the true ones
(median 10^0.092; the truth rasters alone gave 1.20-1.22 times, the emissivity-weighted
apparent contrast). It is a bias, not a spread: it is in the sigma until its cause is modelled.

Without a Jacobian (an inversion made elsewhere) the curve terms cannot be propagated; the
depth then carries the model terms only.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from clearfast_gis.thermal.inversion import MAX_DEPTH_SIGMA_M, Inversion
from clearfast_gis.thermal.table import DEFAULT_DEPTHS_M

GAIN_TERMS = {"blur_registration": 0.08, "emissivity_estimate": 0.02}
"""1-sigma relative errors of the contrast curve's amplitude (module notes)."""

OFFSET_TERM_K = 0.012
"""1-sigma error of the contrast curve's level, K (module notes)."""

DEPTH_TERMS_M = {"object_height": 0.001, "background_ring": 0.0005, "soil_terms": 0.002}
"""Constant 1-sigma depth terms of the model, m (module notes)."""

DEPTH_RELATIVE = 0.05
"""Depth-proportional 1-sigma term of the model, fraction of the estimated depth."""

LOG10_ALPHA_TERMS = {"soil_heat_capacity": 0.04, "measure_residual": 0.05}
"""1-sigma log10 diffusivity terms of the model (module notes)."""

GAIN_TERM = math.sqrt(sum(v * v for v in GAIN_TERMS.values()))
"""The gain terms in quadrature."""


def curve_term_shifts(jacobian: np.ndarray, model_k: np.ndarray,
                      extra_gain: float = 0.0) -> np.ndarray:
    """1-sigma shifts of (depth m, log10 alpha) from the curve terms, through the fit.

    Parameters
    ----------
    jacobian : ndarray, shape (S, 2)
        d contrast / d (depth m, log10 alpha) at the estimate, K/m and K.
    model_k : ndarray, shape (S,)
        Modelled contrast at the estimate, K.

    Returns
    -------
    ndarray, shape (2, 2)
        Rows: the gain term (:data:`GAIN_TERM` times the model curve) and the offset term
        (:data:`OFFSET_TERM_K` in every scan); columns: depth (m), log10 alpha. Infinite when
        the Jacobian is singular (the fit cannot tell the two apart).
    """
    j = np.asarray(jacobian, dtype=float)
    gain = math.hypot(GAIN_TERM, extra_gain)
    curves = np.stack([gain * np.asarray(model_k, dtype=float),
                       np.full(j.shape[0], OFFSET_TERM_K)], axis=1)
    jtj = j.T @ j
    if not np.all(np.isfinite(jtj)) or np.linalg.cond(jtj) > 1e12:
        return np.full((2, 2), np.inf)
    return np.linalg.solve(jtj, j.T @ curves).T


def chain_sigmas(inv: Inversion, extra_gain: float = 0.0) -> tuple[float, float]:
    """The chain's 1-sigma (depth m, log10 alpha) error of ``inv``: every term of the module
    notes in quadrature, the curve terms through ``inv``'s own Jacobian; ``extra_gain``: a
    further relative gain error of the curve (a canopy's seen share,
    :func:`clearfast_gis.thermal.canopy.cover_gain_sigma`)."""
    sd2 = sum(v * v for v in DEPTH_TERMS_M.values()) + (DEPTH_RELATIVE * max(inv.depth_m, 0)) ** 2
    sa2 = sum(v * v for v in LOG10_ALPHA_TERMS.values())
    if inv.jacobian is not None:
        shifts = curve_term_shifts(inv.jacobian, inv.model_contrast_k, extra_gain)
        sd2 += float(np.sum(shifts[:, 0] ** 2))
        sa2 += float(np.sum(shifts[:, 1] ** 2))
    return math.sqrt(sd2), math.sqrt(sa2)


MAX_REPORTED_DEPTH_SIGMA_M = float(DEFAULT_DEPTHS_M[-1])
"""Depth sigmas are capped at the table's depth range, m (20 cm): a flat fit's covariance can
claim metres, which says no more than that the depth is undetermined."""


def with_chain_errors(inv: Inversion, extra_gain: float = 0.0) -> Inversion:
    """``inv`` with the chain's error terms (:func:`chain_sigmas`, ``extra_gain`` among the
    gain terms) added in quadrature to its fit sigmas (the depth sigma capped at
    :data:`MAX_REPORTED_DEPTH_SIGMA_M`).

    An estimate that was ``ok`` becomes ``not_characterised`` when the total depth sigma
    exceeds :data:`~clearfast_gis.thermal.inversion.MAX_DEPTH_SIGMA_M`.
    """
    chain_d, chain_la = chain_sigmas(inv, extra_gain)
    sd = math.hypot(inv.depth_sigma_m, chain_d)
    sd = min(sd, MAX_REPORTED_DEPTH_SIGMA_M) if math.isfinite(sd) else MAX_REPORTED_DEPTH_SIGMA_M
    sla = math.hypot(inv.log10_alpha_sigma, chain_la)
    status = inv.status
    if status == "ok" and sd > MAX_DEPTH_SIGMA_M:
        status = "not_characterised"
    return dataclasses.replace(inv, depth_sigma_m=sd, log10_alpha_sigma=sla,
                               alpha_sigma_m2s=inv.alpha_m2s * math.log(10.0) * sla,
                               status=status)
