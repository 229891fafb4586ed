"""Burial depth and object diffusivity of one anomaly.

theta = (d, log10 alpha): the best node of the site table (coarse grid), then bounded
least squares (trust-region reflective) on the tensor-spline interpolant of the table,
fitting the centre-minus-background contrast over all scans. Covariance from the
Jacobian, scaled by the residual variance (inflated for lag-1 autocorrelation of the
residuals, floored at the noise variance when the noise is known).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike
from scipy.optimize import least_squares

from clearfast_gis.errors import InvalidInput
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.thermal.materials import Soil
from clearfast_gis.thermal.soilfit import ar1_inflation
from clearfast_gis.thermal.table import (
    DEFAULT_HEIGHT_M,
    SiteTable,
    build_site_table,
    contrast_spline,
)

STATUSES = ("ok", "at_bound", "weak_contrast", "not_characterised")
"""Possible :attr:`Inversion.status` values."""

MAX_DEPTH_SIGMA_M = 0.02
"""Depth uncertainty above which an estimate is not characterised, m."""

MAX_LOG10_ALPHA_SIGMA = 0.5
"""log10 diffusivity uncertainty above which an estimate is not characterised (x3)."""

MIN_CONTRAST_SNR = 3.0
"""Peak modelled contrast below this many noise sigmas is a weak contrast."""

AMBIGUITY_DCHI2 = 4.0
"""A second local optimum at another depth whose chi-square is within this of the best one
makes the estimate ambiguous (not characterised)."""

PROFILE_STEPS = (201, 61)
"""Depth and log10 alpha samples of the chi-square profile over the table's range
(:func:`depth_profile_sigma`)."""

MAX_MISFIT_RATIO = 3.0
"""Residual rms above this many noise sigmas: the cylinder model does not explain the data."""


@dataclass(frozen=True)
class Inversion:
    """Result of :func:`invert_anomaly`.

    Attributes
    ----------
    depth_m, depth_sigma_m : float
        Depth of the object's top and its 1-sigma uncertainty, m.
    alpha_m2s, alpha_sigma_m2s : float
        Object diffusivity and its 1-sigma uncertainty, m2 s-1.
    log10_alpha_sigma : float
        Uncertainty of log10 alpha (the fit's own parameter).
    status : str
        First that applies: ``weak_contrast`` (peak modelled contrast < 3 noise sigma);
        ``not_characterised`` when the misfit exceeds 3 noise sigma or the diffusivity
        sits at the table's low end (below any solid's: the depth was traded for it);
        ``at_bound`` (depth at the deepest node or diffusivity at the table's high end,
        metal-like);
        ``not_characterised`` (depth sigma > 2 cm, log10 alpha sigma > 0.5 or a rival
        optimum at another depth within delta chi-square 4); else ``ok``.
    residual_rms_k : float
        Root-mean-square misfit, K.
    noise_k : float
        Noise sigma of the contrast used (given or the residual rms), K.
    peak_contrast_k : float
        Largest |modelled contrast| over the scans, K.
    correlation : float
        Correlation of the depth and log10 alpha estimates.
    model_contrast_k : ndarray, shape (S,)
        Best-fit contrast at the scan times, K.
    jacobian : ndarray, shape (S, 2), optional
        Derivatives of the modelled contrast at the scan times with respect to the depth
        (K/m) and log10 alpha (K) at the estimate: how the fit maps an error of the curve to
        the estimates (:mod:`clearfast_gis.thermal.error_budget`). None when not known.
    gain_refits : ndarray, shape (2, 2), optional
        (depth m, log10 alpha) of the fit made again with the model's contrast times
        ``1 + gain_sigma`` (row 0) and ``1 - gain_sigma`` (row 1), each from every local
        minimum of the table (:func:`invert_anomaly` ``gain_sigma``). None when not made.
    fit_status : str, optional
        The status without the gain refits' moves
        (:func:`clearfast_gis.thermal.error_budget.with_chain_errors`); None: as ``status``.
    prior_normal : ndarray, shape (2, 2), optional
        What the diffusivity prior adds to ``jacobian.T @ jacobian`` (K² per unit of the
        parameters): ``s2 / sigma²`` on log10 alpha, ``s2`` the residual variance the fit
        was weighed with (:func:`invert_anomaly` ``alpha_prior``). None without a prior.
    curve_alpha_m2s, curve_alpha_sigma_m2s : float, optional
        With a prior: the diffusivity of the fit without it (the curve's own) and its
        1-sigma, m2 s-1 (:attr:`diffusivity_m2s`). ``alpha_m2s`` is then the penalised fit's,
        whose depth is the estimate. None without a prior.
    curve_status : str, optional
        With a prior: the status the fit without it gives (the same rules as ``status``):
        whether the curve alone is explained by a buried object, which the mine likelihood
        reads (``fit_status``); the prior assumes a mine, so it must not vouch for one.
        None without a prior.
    curve_depth_sigma_m : float, optional
        With a prior: the depth's 1-sigma of the fit without it, m. None without a prior.
    fit_variance_k2 : float, optional
        The residual variance the fit was weighed with, K² (the residuals' mean square over
        ``S - 2`` degrees of freedom, inflated for their lag-1 autocorrelation; at least the
        given noise's square).
    body_rho_c_jm3k : float, optional
        The body's volumetric heat capacity, J m-3 K-1, when the fits of several bodies were
        combined (:func:`clearfast_gis.thermal.bodies.combine_bodies`): their weighted mean.
    body_sigma : ndarray, shape (2,), optional
        The 1-sigma spread of (depth m, log10 alpha) over those fits, which
        :func:`clearfast_gis.thermal.error_budget.chain_sigmas` adds. None when not made.
    """

    depth_m: float
    depth_sigma_m: float
    alpha_m2s: float
    alpha_sigma_m2s: float
    log10_alpha_sigma: float
    status: str
    residual_rms_k: float
    noise_k: float
    peak_contrast_k: float
    correlation: float
    model_contrast_k: np.ndarray
    jacobian: np.ndarray | None = field(default=None, compare=False)
    gain_refits: np.ndarray | None = field(default=None, compare=False)
    fit_status: str | None = None
    prior_normal: np.ndarray | None = field(default=None, compare=False)
    curve_alpha_m2s: float | None = None
    curve_alpha_sigma_m2s: float | None = None
    curve_status: str | None = None
    curve_depth_sigma_m: float | None = None
    fit_variance_k2: float | None = None
    body_rho_c_jm3k: float | None = None
    body_sigma: np.ndarray | None = field(default=None, compare=False)

    @property
    def diffusivity_m2s(self) -> float:
        """The object's diffusivity as the curve alone gives it, m2 s-1: ``curve_alpha_m2s``
        when the fit had a prior, else ``alpha_m2s`` (what the products report and the
        material cue reads: a prior must not make an object look like a mine)."""
        return self.alpha_m2s if self.curve_alpha_m2s is None else self.curve_alpha_m2s

    @property
    def diffusivity_sigma_m2s(self) -> float:
        """1-sigma of :attr:`diffusivity_m2s`, m2 s-1."""
        return self.alpha_sigma_m2s if self.curve_alpha_sigma_m2s is None \
            else self.curve_alpha_sigma_m2s


def _local_minima(cost: np.ndarray, n: int) -> list[tuple[int, int]]:
    """Indices of up to ``n`` lowest local minima of a 2-D cost grid."""
    padded = np.pad(cost, 1, constant_values=np.inf)
    centre = padded[1:-1, 1:-1]
    is_min = np.ones_like(cost, dtype=bool)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            if di or dj:
                nb = padded[1 + di:padded.shape[0] - 1 + di, 1 + dj:padded.shape[1] - 1 + dj]
                is_min &= centre <= nb
    idx = np.argwhere(is_min)
    order = np.argsort(cost[is_min])[:n]
    return [tuple(idx[k]) for k in order]


def depth_profile_sigma(spline, obs: np.ndarray, lo: np.ndarray, hi: np.ndarray,
                        best_cost: float, s2: float,
                        prior: tuple[float, float, float] | None = None) -> float:
    """Half the width (m) of the depths whose profile chi-square lies within 1 of the best.

    The profile ``chi2(d) = min over log10 alpha of sum((model - obs)^2) / s2`` is sampled on
    :data:`PROFILE_STEPS` depths x diffusivities over the table's range ``lo..hi`` (depth m,
    log10 alpha); the depths with ``chi2(d) - chi2_best <= 1`` (every branch, so a fit with
    two depth branches spans both) give the interval. On a well-determined fit it equals the
    covariance's sigma; on a flat one (the chi-square varying by less than 1 over centimetres)
    it is the honest one. Shapes: ``obs`` (S,) K; ``spline`` maps (M, 2) to (M, S) K.
    ``prior``: (mean, 1 sigma of log10 alpha, weight K²) of :func:`_fits`, whose penalty is
    part of the profile (and of ``best_cost``).
    """
    d = np.linspace(lo[0], hi[0], PROFILE_STEPS[0])
    la = np.linspace(lo[1], hi[1], PROFILE_STEPS[1])
    pts = np.stack(np.meshgrid(d, la, indexing="ij"), axis=-1).reshape(-1, 2)
    cost = 0.5 * np.sum((spline(pts) - obs) ** 2, axis=-1).reshape(d.size, la.size)
    cost = cost + _penalty(la, prior)[None, :]
    dchi2 = 2.0 * (np.min(cost, axis=1) - min(best_cost, float(cost.min()))) / s2
    inside = d[dchi2 <= 1.0]
    return 0.5 * float(inside.max() - inside.min()) if inside.size else 0.0


def invert_anomaly(
    time_s: ArrayLike,
    centre_k: ArrayLike,
    background_k: ArrayLike,
    forcing: Forcing,
    soil: Soil,
    radius_m: float,
    noise_k: float | None = None,
    table: SiteTable | None = None,
    height_m: float = DEFAULT_HEIGHT_M,
    over_m: float | None = None,
    ring_m: tuple[float, float] | None = None,
    blur_m: float = 0.0,
    gain: ArrayLike | None = None,
    gain_sigma: float = 0.0,
    alpha_prior: tuple[float, float] | None = None,
) -> Inversion:
    """Estimate burial depth and diffusivity of one anomaly.

    Parameters
    ----------
    time_s : array_like, shape (S,)
        Times the anomaly was observed (one per scan), UTC epoch seconds.
    centre_k, background_k : array_like, shape (S,)
        Temperature at the anomaly's centre and of its background ring, K. NaN scans are
        dropped.
    forcing : Forcing
        Weather.
    soil : Soil
        Site soil (fitted diffusivity and surface parameters).
    radius_m : float
        Object radius, m: the mine type's the chain takes the anomaly for, or the
        footprint's.
    noise_k : float, optional
        1-sigma noise of the contrast ``centre - background`` per scan, K; default: the fit's
        residual rms.
    table : SiteTable, optional
        Site table covering ``radius_m`` and ``time_s``; built on the fly when omitted
        (seconds per call, so build it once per site for many anomalies).
    height_m : float
        Object height when the table is built here, m.
    over_m : float, optional
        Radius of the disc the centre was averaged over, m, when it is not the object's
        (the anomaly's half-maximum footprint; needs a "disc" table,
        :meth:`SiteTable.contrast_for`).
    ring_m : (float, float), optional
        Inner and outer radius of the ring ``background_k`` was averaged over, m: the
        model's contrast is then taken against that ring, in the object's thermal halo,
        instead of the undisturbed surface ("disc" table).
    blur_m : float
        Gaussian sigma of the images' blur the curve was measured through, m ("disc" table).
    gain : array_like, shape (S,), optional
        Per-scan factor from the model's kinetic contrast to the measured one (the apparent
        contrast, :func:`clearfast_gis.thermal.apparent.apparent_gain`); 1 when omitted.
    gain_sigma : float
        1-sigma relative error of the curve's amplitude that the fit cannot see (the chain's
        gain terms, :func:`clearfast_gis.thermal.error_budget.gain_sigma`). When positive the
        curve is fitted twice more, with the model's contrast times ``1 + gain_sigma`` and
        ``1 - gain_sigma``, each from every local minimum of the table
        (:attr:`Inversion.gain_refits`): where the fit's valley is flat in depth, a small
        gain error moves the estimate onto another branch, which the error propagated
        through the Jacobian at the estimate does not show.
    alpha_prior : (float, float), optional
        (mean, 1 sigma) of the object's log10 diffusivity (m2 s-1) before the curve is seen
        (the chain's: :data:`clearfast_gis.thermal.materials.MINE_FILL_LOG10_ALPHA`). The
        curve is fitted without it first, for the residual variance ``s2``; then again with
        ``s2 ((log10 alpha - mean) / sigma)²`` added to the squared residuals: where the
        chi-square is flat along the depth-diffusivity trade (a few scans), the prior picks
        the depth; where the curve determines the diffusivity, the curve does. Depth sigma,
        covariance, rivals and gain refits are all of the penalised fit.

    Returns
    -------
    Inversion
    """
    t = np.asarray(time_s, dtype=float)
    c = np.asarray(centre_k, dtype=float)
    b = np.asarray(background_k, dtype=float)
    if t.ndim != 1 or c.shape != t.shape or b.shape != t.shape:
        raise InvalidInput("time, centre and background must be 1-D of one length",
                           field="centre_k")
    if not (np.isfinite(radius_m) and radius_m > 0):
        raise InvalidInput("radius must be positive", field="radius_m")
    ok = np.isfinite(t) & np.isfinite(c) & np.isfinite(b)
    if ok.sum() < 4:
        raise InvalidInput("fewer than 4 valid scans", field="centre_k")
    g = np.ones(t.shape) if gain is None else np.asarray(gain, dtype=float)
    if g.shape != t.shape:
        raise InvalidInput("gain must have one value per scan", field="gain")
    t, obs, g = t[ok], c[ok] - b[ok], g[ok]
    if table is None:
        table = build_site_table(forcing, soil, radius_m, t, height_m=height_m,
                                 centre="axis" if over_m is None and ring_m is None
                                 and not blur_m > 0 else "disc")
    grid = table.contrast_for(radius_m, t, over_m, ring_m, blur_m) * g
    depths, la = table.depths_m, table.log10_alpha
    spline = contrast_spline(depths, la, grid)
    fits = _fits(spline, grid, obs, depths, la)
    r = fits[0].fun
    n, p = r.size, 2
    # scan-to-scan residuals of a smooth model misfit are correlated: inflate the variance
    # for lag-1 autocorrelation (as the soil fit does), else 48 scans claim 0.1 cm
    s2 = float(np.sum(r**2)) / max(n - p, 1) * ar1_inflation(r[:, None])
    if noise_k is not None:
        s2 = max(s2, float(noise_k) ** 2)
    prior = None if alpha_prior is None else (float(alpha_prior[0]), float(alpha_prior[1]),
                                              max(s2, 1e-12))
    curve = None
    if prior is not None:  # the curve alone first: its diffusivity and status
        curve = _judged(fits, spline, obs, depths, la, s2, noise_k, n)
        fits = _fits(spline, grid, obs, depths, la, prior=prior)
    prior_normal = None if prior is None else np.diag([0.0, prior[2] / prior[1] ** 2])
    best = _judged(fits, spline, obs, depths, la, s2, noise_k, n, prior, prior_normal)
    d, lalpha = best.fit.x
    sig = best.sigma
    refits = None
    if gain_sigma > 0:
        refits = np.array([_fits(spline, grid, obs, depths, la, 1.0 + k * gain_sigma,
                                 prior)[0].x for k in (1.0, -1.0)])
    alpha = 10.0**lalpha
    return Inversion(
        depth_m=float(d), depth_sigma_m=float(sig[0]), alpha_m2s=float(alpha),
        alpha_sigma_m2s=float(alpha * np.log(10.0) * sig[1]),
        log10_alpha_sigma=float(sig[1]), status=best.status, residual_rms_k=best.rms_k,
        noise_k=best.noise_k, peak_contrast_k=best.peak_k, correlation=best.correlation,
        model_contrast_k=best.model_k, jacobian=best.jacobian, gain_refits=refits,
        prior_normal=prior_normal,
        curve_alpha_m2s=None if curve is None else curve.alpha_m2s,
        curve_alpha_sigma_m2s=None if curve is None else curve.alpha_sigma_m2s,
        curve_status=None if curve is None else curve.status,
        curve_depth_sigma_m=None if curve is None else float(curve.sigma[0]),
        fit_variance_k2=float(s2),
    )


@dataclass(frozen=True)
class _Judged:
    """The best of a set of fits, its sigmas and status (:func:`_judged`)."""

    fit: object
    sigma: np.ndarray
    correlation: float
    status: str
    rms_k: float
    noise_k: float
    peak_k: float
    model_k: np.ndarray
    jacobian: np.ndarray

    @property
    def alpha_m2s(self) -> float:
        """The fit's diffusivity, m2 s-1."""
        return float(10.0 ** self.fit.x[1])

    @property
    def alpha_sigma_m2s(self) -> float:
        """Its 1-sigma, m2 s-1 (infinite when the covariance is singular)."""
        return float(self.alpha_m2s * np.log(10.0) * self.sigma[1])


def _judged(fits: list, spline, obs: np.ndarray, depths: np.ndarray, la: np.ndarray,
            s2: float, noise_k: float | None, n: int,
            prior: tuple[float, float, float] | None = None,
            prior_normal: np.ndarray | None = None) -> _Judged:
    """The best of ``fits`` (:func:`_fits`, best first) with its 1-sigma (depth m, log10
    alpha), their correlation and its :attr:`Inversion.status`.

    ``obs`` (S,) K; ``s2`` the residual variance, K²; ``n`` = S (a fit with a prior has one
    more residual); ``noise_k`` the given noise, K, or None; ``prior`` and ``prior_normal``
    the fit's prior (:func:`_fits`, :attr:`Inversion.prior_normal`)."""
    best = fits[0]
    d, lalpha = best.x
    r = best.fun[:n]
    rms = float(np.sqrt(np.mean(r**2)))
    noise = rms if noise_k is None else float(noise_k)
    jm = np.asarray(best.jac[:n], dtype=float)
    cov = _covariance(jm, s2, prior_normal)
    if cov is None:
        sig = np.array([np.inf, np.inf])
        corr = 0.0
    else:
        sig = np.sqrt(np.clip(np.diag(cov), 0, None))
        corr = float(cov[0, 1] / (sig[0] * sig[1])) if sig.all() else 0.0
    # a flat chi-square along the depth (a curve many depths explain): the covariance's
    # local slope understates the depth's spread; the profile's interval does not
    lo, hi = np.array([depths[0], la[0]]), np.array([depths[-1], la[-1]])
    sig[0] = max(sig[0], depth_profile_sigma(spline, obs, lo, hi, float(best.cost), s2,
                                             prior))
    model = spline(best.x[None, :])[0]
    peak = float(np.max(np.abs(model)))
    tol_d = 0.02 * (depths[-1] - depths[-2])
    tol_a = 0.02 * (la[1] - la[0])
    # another minimum statistically as good (delta chi2 < 4) but at another depth
    rivals = [f for f in fits[1:]
              if 2 * (f.cost - best.cost) / s2 < AMBIGUITY_DCHI2
              and abs(f.x[0] - d) > max(2 * sig[0], 0.005)]
    misfit = noise_k is not None and rms > MAX_MISFIT_RATIO * noise
    if peak < MIN_CONTRAST_SNR * noise:
        status = "weak_contrast"
    elif misfit:
        status = "not_characterised"
    elif lalpha <= la[0] + tol_a:
        # slower than any solid (the table's low end is 3e-8 m2/s, a third of TNT's): the
        # fit traded depth for an impossible diffusivity, so the depth says nothing
        status = "not_characterised"
    elif d >= depths[-1] - tol_d or lalpha >= la[-1] - tol_a:
        status = "at_bound"
    elif sig[0] > MAX_DEPTH_SIGMA_M or sig[1] > MAX_LOG10_ALPHA_SIGMA or rivals:
        status = "not_characterised"
    else:
        status = "ok"
    return _Judged(fit=best, sigma=sig, correlation=corr, status=status, rms_k=rms,
                   noise_k=noise, peak_k=peak, model_k=model, jacobian=jm)


def _covariance(jac: np.ndarray, s2: float, prior_normal: np.ndarray | None = None
                ) -> np.ndarray | None:
    """Covariance (2, 2) of (depth m, log10 alpha): ``(J^T J + prior_normal)^-1 s2`` with
    ``jac`` (S, 2) the fit's Jacobian and ``s2`` its residual variance, K²; None when
    singular."""
    jtj = jac.T @ jac if prior_normal is None else jac.T @ jac + prior_normal
    try:
        return np.linalg.inv(jtj) * s2
    except np.linalg.LinAlgError:
        return None


def _penalty(log10_alpha: np.ndarray, prior: tuple[float, float, float] | None) -> np.ndarray:
    """Half the prior's squared residual at ``log10_alpha``, K² (0 without a prior)."""
    if prior is None:
        return np.zeros(np.shape(log10_alpha))
    mean, sigma, weight = prior
    return 0.5 * weight * ((np.asarray(log10_alpha, dtype=float) - mean) / sigma) ** 2


def _fits(spline, grid: np.ndarray, obs: np.ndarray, depths: np.ndarray, la: np.ndarray,
          scale: float = 1.0, prior: tuple[float, float, float] | None = None) -> list:
    """Bounded least-squares fits of ``scale`` times the table's contrast to ``obs``, one
    from each of the (up to 4) lowest local minima of the table's cost grid, best first.

    ``spline`` interpolates ``grid`` (depth x log10 alpha x scans, K) over the nodes
    ``depths`` (m) and ``la`` (log10 m2/s); ``obs`` (S,) is the measured contrast, K.
    ``prior``: (mean, sigma, weight K²) of log10 alpha: a last residual
    ``sqrt(weight) (log10 alpha - mean) / sigma`` is appended (``fun`` and ``jac`` have
    S + 1 rows). Returns scipy ``OptimizeResult`` objects (``x`` = (depth m, log10 alpha)).
    """
    lo, hi = np.array([depths[0], la[0]]), np.array([depths[-1], la[-1]])
    w = 0.0 if prior is None else float(np.sqrt(prior[2]) / prior[1])

    def resid(p: np.ndarray) -> np.ndarray:
        r = scale * spline(p[None, :])[0] - obs
        return r if prior is None else np.append(r, w * (p[1] - prior[0]))

    def jac(p: np.ndarray) -> np.ndarray:
        x = p[None, :]
        j = scale * np.stack([spline(x, nu=(1, 0))[0], spline(x, nu=(0, 1))[0]], axis=1)
        return j if prior is None else np.vstack([j, [0.0, w]])

    cost = np.sum((scale * grid - obs) ** 2, axis=-1) + 2.0 * _penalty(la, prior)[None, :]
    span = hi - lo
    fits = []
    for i, j in _local_minima(cost, 4):
        x0 = np.clip([depths[i], la[j]], lo + 1e-4 * span, hi - 1e-4 * span)
        fits.append(least_squares(resid, x0, jac=jac, bounds=(lo, hi), method="trf",
                                  x_scale=[0.01, 0.25], xtol=1e-10, ftol=1e-12))
    fits.sort(key=lambda s: s.cost)
    return fits
