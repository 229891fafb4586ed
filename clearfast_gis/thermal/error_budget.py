"""The chain's own error terms of the depth and diffusivity estimates.

The fit's covariance (:func:`clearfast_gis.thermal.inversion.invert_anomaly`) covers the
scatter of the contrast curve about the model: what changes from scan to scan shows in the
residuals. What the chain does to the whole curve before the fit does not: the fit absorbs it
into the estimates. Two kinds of chain terms are added in quadrature:

**Errors of the curve, propagated through the fit.** A systematic error ``delta_c`` (K, one
value per scan) of the contrast curve moves the estimates by ``(J^T J)^-1 J^T delta_c``, with
``J`` the fit's own Jacobian at the estimate (:attr:`Inversion.jacobian`; ``J^T J`` plus the
prior's term :attr:`Inversion.prior_normal` for a fit with a prior): the same error
costs a weak (deep) object's estimate much more than a strong one's, and how much depends on
when the survey's scans sample the day. Three such errors, each measured as 1 sigma on
simulated surveys (``benchmarks/contrast_gain.py``):

================================  ==============  =========================================
term                              1 sigma         how it was measured
================================  ==============  =========================================
gain: blur and registration       8 % of the      the mosaics' contrast curve of each mine
(sensor, mosaic, sub-pixel        contrast        (at its detection) against the model's
shifts between scans)                             curve at its true depth and diffusivity,
                                                  through the modelled blur and gain: slope
                                                  0.93 +- 0.03 (22 mines at 0-5 cm, demo
                                                  seeds 3-6, ``benchmarks/chain_curve_gain.
                                                  py``); the mean loss the model leaves and
                                                  the spread, 0.075 rms
gain: the estimated band          2 %             the moisture field's spread of the sand's
emissivity (the apparent                          band emissivity around a mine (about
contrast's gain is modelled,                      0.015); the estimate's own error against
:mod:`~clearfast_gis.thermal.                     the twin's emissivity is not measured
apparent`)                                        separately (the slope above holds it)
offset: background ring           0.012 K         the disc-minus-ring regressions'
                                                  intercepts on the truth rasters (rms)
================================  ==============  =========================================

The propagation is linear. Where the fit's valley is flat in depth, a few per cent of gain
moves the best fit onto another branch: the chain fits each curve again with the model times
``1 +- G`` (:func:`gain_sigma`; :attr:`Inversion.gain_refits`) and the gain term's shift is the
larger of the two (:func:`chain_sigmas`).

**The mine's body.** The spread of the fits with the object at each body heat capacity
(:attr:`Inversion.body_sigma`, :mod:`clearfast_gis.thermal.bodies`) is a term of depth and
log10 diffusivity, with the gain refits' (not in the curve's own status).

**Errors of the model, as depth (m) and log10 diffusivity terms**, measured by changing one
link at a time (BENCHMARKS.md, "Depth bias"; ``benchmarks/depth_bias.py``):

================================  =============  ==========================================
term                              depth, cm      how it was measured
================================  =============  ==========================================
object height (the table is the   0.1            tables for 5 and 8 cm objects against an
mine type's; a mine of another                   8 cm mine: 0.3-0.5 cm for 3 cm of height
height)
background ring (texture; the     0.05           the modelled ring against a ring beyond
halo is modelled)                                the halo on ideal curves: within 0.03 cm
soil terms (diffusivity, surface  0.2            surface terms from the thermocouple
fit, heat capacity)                              against the exact soil
depth-proportional part           5 % of depth   the mine type against the modelled ring
                                                 on ideal curves: within 0.11 cm at 1-7 cm
================================  =============  ==========================================

Diffusivity: the soil's heat capacity is inferred from its diffusivity (+-10 %), 0.04 in
log10 alpha; and the measure's residual (the gain estimate, the blur model), 0.05 in log10
alpha (docs/thermal.md, "Error budget").

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


def model_depth_variance(depth_m: float, relative: float = DEPTH_RELATIVE,
                         terms: dict[str, float] | None = None) -> float:
    """The model's depth terms at ``depth_m`` (m) in quadrature: ``terms`` (m; default
    :data:`DEPTH_TERMS_M`) and ``relative`` times the depth, as a variance, m²."""
    const = DEPTH_TERMS_M if terms is None else terms
    return sum(v * v for v in const.values()) + (relative * max(depth_m, 0)) ** 2


def gain_sigma(extra_gain: float = 0.0) -> float:
    """1-sigma relative error of the contrast curve's amplitude: :data:`GAIN_TERM` and
    ``extra_gain`` (a canopy's seen share) in quadrature."""
    return math.hypot(GAIN_TERM, extra_gain)


def curve_term_shifts(jacobian: np.ndarray, model_k: np.ndarray,
                      extra_gain: float = 0.0, prior_normal: np.ndarray | None = None
                      ) -> np.ndarray:
    """1-sigma shifts of (depth m, log10 alpha) from the curve terms, through the fit.

    Parameters
    ----------
    jacobian : ndarray, shape (S, 2)
        d contrast / d (depth m, log10 alpha) at the estimate, K/m and K.
    model_k : ndarray, shape (S,)
        Modelled contrast at the estimate, K.
    prior_normal : ndarray, shape (2, 2), optional
        The fit's prior term of its normal matrix (:attr:`Inversion.prior_normal`): a curve
        error moves a penalised fit's estimates by ``(J^T J + prior_normal)^-1 J^T delta_c``.

    Returns
    -------
    ndarray, shape (2, 2)
        Rows: the gain term (:data:`GAIN_TERM` times the model curve) and the offset term
        (:data:`OFFSET_TERM_K` in every scan); columns: depth (m), log10 alpha. Infinite when
        the Jacobian is singular (the fit cannot tell the two apart).
    """
    j = np.asarray(jacobian, dtype=float)
    gain = gain_sigma(extra_gain)
    curves = np.stack([gain * np.asarray(model_k, dtype=float),
                       np.full(j.shape[0], OFFSET_TERM_K)], axis=1)
    jtj = j.T @ j if prior_normal is None else j.T @ j + np.asarray(prior_normal, float)
    if not np.all(np.isfinite(jtj)) or np.linalg.cond(jtj) > 1e12:
        return np.full((2, 2), np.inf)
    return np.linalg.solve(jtj, j.T @ curves).T


def chain_sigmas(inv: Inversion, extra_gain: float = 0.0, refits: bool = True,
                 prior: bool = True) -> tuple[float, float]:
    """The chain's 1-sigma (depth m, log10 alpha) error of ``inv``: every term of the module
    notes in quadrature, the curve terms through ``inv``'s own Jacobian; ``extra_gain``: a
    further relative gain error of the curve (a canopy's seen share,
    :func:`clearfast_gis.thermal.canopy.cover_gain_sigma`).

    When ``inv`` was fitted again with the gain off by +- 1 sigma (:attr:`Inversion.gain_refits`,
    the same ``extra_gain``), the gain term's shift is the larger of the propagated one and
    the refits' largest move: a flat valley's jump to another branch counts in full
    (``refits=False``: the propagated shift alone). The spread of the fits of several mine
    bodies (:attr:`Inversion.body_sigma`, :mod:`clearfast_gis.thermal.bodies`) is one more
    term, not with ``refits=False``: the curve's own status, which the likelihood reads,
    does not hang on which body a mine has. ``prior=False``: propagated as if the fit
    had no prior on the diffusivity (the curve's own diffusivity,
    :attr:`Inversion.curve_alpha_m2s`)."""
    sd2 = model_depth_variance(inv.depth_m)
    sa2 = sum(v * v for v in LOG10_ALPHA_TERMS.values())
    if inv.jacobian is not None:
        shifts = np.abs(curve_term_shifts(inv.jacobian, inv.model_contrast_k, extra_gain,
                                          inv.prior_normal if prior else None))
        if refits and inv.gain_refits is not None:
            moved = np.max(np.abs(inv.gain_refits - [inv.depth_m, math.log10(inv.alpha_m2s)]),
                           axis=0)
            shifts[0] = np.maximum(shifts[0], moved)
        sd2 += float(np.sum(shifts[:, 0] ** 2))
        sa2 += float(np.sum(shifts[:, 1] ** 2))
    if refits and inv.body_sigma is not None:
        sd2 += float(inv.body_sigma[0]) ** 2
        sa2 += float(inv.body_sigma[1]) ** 2
    return math.sqrt(sd2), math.sqrt(sa2)


MAX_REPORTED_DEPTH_SIGMA_M = float(DEFAULT_DEPTHS_M[-1])
"""Depth sigmas are capped at the table's depth range, m (20 cm): a flat fit's covariance can
claim metres, which says no more than that the depth is undetermined."""


def with_chain_errors(inv: Inversion, extra_gain: float = 0.0) -> Inversion:
    """``inv`` with the chain's error terms (:func:`chain_sigmas`, ``extra_gain`` among the
    gain terms) added in quadrature to its fit sigmas (the depth sigma capped at
    :data:`MAX_REPORTED_DEPTH_SIGMA_M`).

    An estimate that was ``ok`` becomes ``not_characterised`` when the total depth sigma
    exceeds :data:`~clearfast_gis.thermal.inversion.MAX_DEPTH_SIGMA_M`. ``fit_status`` is the
    status the propagated terms alone give (without the gain refits' moves): whether the
    curve is well explained by a buried object, which the mine likelihood reads, apart from
    whether its depth survives a gain error. For a fit with a prior it is the curve's own
    (:attr:`Inversion.curve_status`, its depth sigma and the terms propagated as if there
    were no prior, through the penalised fit's Jacobian): the prior is a mine's diffusivity,
    and what the likelihood weighs must not assume a mine. The curve's own diffusivity
    (:attr:`Inversion.curve_alpha_m2s`) likewise takes the propagated terms as if there were
    no prior.
    """
    chain_d, chain_la = chain_sigmas(inv, extra_gain)
    sd = _capped(math.hypot(inv.depth_sigma_m, chain_d))
    sla = math.hypot(inv.log10_alpha_sigma, chain_la)
    if inv.curve_status is None:
        fit_status = _flagged(inv.status, _capped(math.hypot(
            inv.depth_sigma_m, chain_sigmas(inv, extra_gain, False)[0])))
    else:
        fit_status = _flagged(inv.curve_status, _capped(math.hypot(
            inv.curve_depth_sigma_m, chain_sigmas(inv, extra_gain, False, False)[0])))
    curve_sigma = inv.curve_alpha_sigma_m2s
    if inv.curve_alpha_m2s is not None and curve_sigma is not None:
        fit_la = curve_sigma / (inv.curve_alpha_m2s * math.log(10.0))
        curve_sigma = inv.curve_alpha_m2s * math.log(10.0) * math.hypot(
            fit_la, chain_sigmas(inv, extra_gain, False, False)[1])
    return dataclasses.replace(inv, depth_sigma_m=sd, log10_alpha_sigma=sla,
                               curve_alpha_sigma_m2s=curve_sigma,
                               alpha_sigma_m2s=inv.alpha_m2s * math.log(10.0) * sla,
                               status=_flagged(inv.status, sd),
                               fit_status=fit_status)


def _capped(sigma_m: float) -> float:
    return min(sigma_m, MAX_REPORTED_DEPTH_SIGMA_M) if math.isfinite(sigma_m) \
        else MAX_REPORTED_DEPTH_SIGMA_M


def _flagged(status: str, depth_sigma_m: float) -> str:
    """``ok`` becomes ``not_characterised`` beyond the depth sigma limit."""
    return "not_characterised" if status == "ok" and depth_sigma_m > MAX_DEPTH_SIGMA_M \
        else status
