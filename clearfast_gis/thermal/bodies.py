"""The mine's body: its heat capacity as one more unknown of the inversion.

The inversion's object is a homogeneous cylinder described by its diffusivity at a fixed
volumetric heat capacity (:func:`clearfast_gis.thermal.table.object_material`). A curve does
not fix the diffusivity alone: a body of lower heat capacity than the one assumed warms and
cools more, and the fit reads that as a shallower object. In the twin's sand on a clear
November day, six scans, a plastic or wooden body (1.8e6 J m-3 K-1) fitted as TNT
(2.28e6) comes out 0.6-1.2 cm shallow, a Composition B one (2.01e6) about 0.6 cm
(noise-free curves of an AP mine at 1-3 cm; on the twin's surveys BENCHMARKS.md, "Mine
bodies other than TNT").

So the chain fits each curve with the object at each heat capacity of
:data:`~clearfast_gis.thermal.materials.MINE_BODY_RHO_C_JM3K` (:func:`fit_bodies`; a curve
whose fit with the middle body is ``weak_contrast`` reports no depth with any body and is
not fitted again) and combines the fits as a model average with equal prior weights: each
fit ``i`` weighs ``exp(-chi2_i / 2)``, ``chi2_i = S rms_i² / s2 + ((log10 alpha_i - m) /
s_a)²`` (its misfit over the ``S`` scans; its diffusivity against the prior of a mine's,
``(m, s_a)``).

``s2`` is the smallest of the fits' residual variances (:attr:`Inversion.fit_variance_k2`,
inflated for the residuals' autocorrelation) plus the chain's curve terms (the error
budget's gain, 8 % of the modelled contrast, and ring offset, 12 mK): the chain's own errors
of the curve move a fit as much as a body does, so they must not pick the body. Weighed by
the residuals alone, the fits picked bodies by those errors: on the TNT mines of the
held-out clear and loam surveys (demo seeds 15-19, 30 mines at 1-3 cm) 97 % of the errors
lay within 2 sigma and 77 % within 1; with the curve terms 100 % and 80 %.

The depth and log10 diffusivity are the weighted means; their weighted spread about the
means is :attr:`Inversion.body_sigma`, a term of the chain's sigmas
(:func:`clearfast_gis.thermal.error_budget.chain_sigmas`). Where the curve tells the bodies
apart (many scans, a strong object) one fit takes the weight and the spread vanishes; where
it cannot, the depth is the middle of the bodies' and the sigma holds their spread.
Everything else (the status, the Jacobian, the curve's own status and diffusivity that the
likelihood reads, the gain refits, moved with the estimate) is the heaviest fit's.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Sequence

import numpy as np

from clearfast_gis.thermal.error_budget import GAIN_TERM, OFFSET_TERM_K
from clearfast_gis.thermal.inversion import Inversion


def _estimates(invs: Sequence[Inversion]) -> tuple[np.ndarray, np.ndarray]:
    """Depths (B,) m and log10 diffusivities (B,) of the fits; NaN where not positive."""
    depth = np.array([i.depth_m for i in invs], dtype=float)
    la = np.array([math.log10(i.alpha_m2s) if i.alpha_m2s > 0 else np.nan for i in invs])
    return depth, la


def body_weights(invs: Sequence[Inversion], alpha_prior: tuple[float, float] | None,
                 gain: float = GAIN_TERM) -> np.ndarray:
    """Normalised weights (B,) of the fits of B bodies (module notes); 0 for a fit whose
    depth or diffusivity is not finite, all 0 when none is. ``gain``: the curve's 1-sigma
    relative amplitude error (:func:`clearfast_gis.thermal.error_budget.gain_sigma`)."""
    depth, la = _estimates(invs)
    n = np.array([np.size(i.model_contrast_k) for i in invs], dtype=float)
    rms = np.array([i.residual_rms_k for i in invs], dtype=float)
    ok = np.isfinite(rms) & np.isfinite(la) & np.isfinite(depth)
    if not ok.any():
        return np.zeros(len(invs))
    # a fit made without a recorded variance counts its mean squared residual
    s2s = np.array([i.residual_rms_k**2 if i.fit_variance_k2 is None else i.fit_variance_k2
                    for i in invs], dtype=float)
    curve = np.array([np.mean((gain * np.asarray(i.model_contrast_k, dtype=float)) ** 2)
                      for i in invs])
    s2 = max(float(np.min(s2s[ok])), 1e-12) + (float(np.mean(curve[ok])) + OFFSET_TERM_K**2)
    chi2 = n * rms**2 / s2
    if alpha_prior is not None:
        chi2 = chi2 + ((la - alpha_prior[0]) / alpha_prior[1]) ** 2
    chi2 = np.where(ok, chi2, np.inf)
    w = np.exp(-0.5 * (chi2 - chi2.min()))
    return w / w.sum()


def combine_bodies(invs: Sequence[Inversion], rho_c_jm3k: Sequence[float],
                   alpha_prior: tuple[float, float] | None = None,
                   gain: float = GAIN_TERM) -> Inversion:
    """One inversion from the fits ``invs`` of the same curve with the object at each body
    heat capacity ``rho_c_jm3k`` (J m-3 K-1; module notes).

    Parameters
    ----------
    invs : sequence of Inversion, length B
        The fits, from :func:`clearfast_gis.thermal.inversion.invert_anomaly` with a table
        per body.
    rho_c_jm3k : sequence of float, length B
        The bodies' volumetric heat capacities, J m-3 K-1.
    alpha_prior : (float, float), optional
        (mean, 1 sigma) of log10 alpha the fits were weighed with.
    gain : float
        The curve's 1-sigma relative amplitude error (:func:`body_weights`).

    Returns
    -------
    Inversion
        The heaviest fit with the weighted mean depth and diffusivity, the body's weighted
        mean heat capacity (:attr:`Inversion.body_rho_c_jm3k`) and the weighted spread
        (:attr:`Inversion.body_sigma`); the gain refits move with the estimate. The single
        fit unchanged when ``invs`` holds one, or when no fit has a finite estimate.
    """
    if len(invs) != len(rho_c_jm3k):
        raise ValueError(f"{len(invs)} fits for {len(rho_c_jm3k)} bodies")
    if len(invs) == 1:
        return invs[0]
    w = body_weights(invs, alpha_prior, gain)
    if not w.any():
        return invs[0]
    use = w > 0
    depth, la = (v[use] for v in _estimates(invs))
    wu = w[use]
    d_mean, la_mean = float(np.sum(wu * depth)), float(np.sum(wu * la))
    spread = np.sqrt([float(np.sum(wu * (depth - d_mean) ** 2)),
                      float(np.sum(wu * (la - la_mean) ** 2))])
    base = invs[int(np.argmax(w))]
    refits = base.gain_refits
    if refits is not None:
        refits = np.asarray(refits, float) + [d_mean - base.depth_m,
                                              la_mean - math.log10(base.alpha_m2s)]
    alpha = 10.0**la_mean
    return dataclasses.replace(
        base, depth_m=d_mean, alpha_m2s=alpha,
        alpha_sigma_m2s=alpha * math.log(10.0) * base.log10_alpha_sigma,
        gain_refits=refits, body_sigma=spread,
        body_rho_c_jm3k=float(np.sum(w * np.asarray(rho_c_jm3k, dtype=float))))


def other_bodies_needed(first: Inversion) -> bool:
    """Whether a curve whose fit with the middle body is ``first`` is fitted with the other
    bodies too: not when that fit is ``weak_contrast`` (no depth to report, whatever the
    body)."""
    return first.status != "weak_contrast"


def fit_bodies(fit: Callable[[int], Inversion], rho_c_jm3k: Sequence[float],
               alpha_prior: tuple[float, float] | None = None,
               gain: float = GAIN_TERM) -> Inversion:
    """The inversion of one curve over the bodies of heat capacities ``rho_c_jm3k`` (B,),
    J m-3 K-1: ``fit(i)`` fits it with the object at ``rho_c_jm3k[i]``, the middle body
    first; a ``weak_contrast`` fit (no depth to report, whatever the body) is returned as it
    is, else every body is fitted and the fits combined (:func:`combine_bodies`, ``gain``
    the curve's relative amplitude error)."""
    middle = len(rho_c_jm3k) // 2
    first = fit(middle)
    if not other_bodies_needed(first) or len(rho_c_jm3k) == 1:
        return first
    fits = [first if i == middle else fit(i) for i in range(len(rho_c_jm3k))]
    return combine_bodies(fits, rho_c_jm3k, alpha_prior, gain)


__all__ = ["body_weights", "combine_bodies", "fit_bodies", "other_bodies_needed"]
