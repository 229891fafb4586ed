"""The registration's fast kernels (``--kernels fast``, :mod:`clearfast_gis.kernels`).

:func:`register_conformal` is the registry's ``register_conformal``: the coarse-to-fine
maximisation of a Parzen-windowed mutual information with its analytic gradient, described in
:mod:`clearfast_gis.registration.conformal` (whose public function of the same name checks the
input and calls it through :func:`clearfast_gis.kernels.kernel`); its reference, SimpleITK, is
in :mod:`clearfast_gis.registration._reference`, judged by the same acceptance test
(:func:`_level_problem`, :func:`_normalised_mi`). One module of ~520 lines on purpose: the
compiled metric and the optimisation that drives it are one kernel, tuned together.

Numba kernels: Parzen-windowed joint histogram and its derivative (Mattes et al. 2003).

The fixed image is binned hard (zero-order B-spline), the moving image with a cubic B-spline
Parzen window, so the joint histogram -- and the mutual information computed from it -- is a
smooth function of the transform parameters with an analytic gradient.

Parameter order of the derivatives: ``(angle_rad, tx_px, ty_px, log_scale)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import cv2
import numpy as np
from numba import njit

from clearfast_gis.registration.conformal import MAX_LOG_SCALE
from clearfast_gis.registration.optimize import maximize_bfgs
from clearfast_gis.registration.pyramid import masked_gaussian, masked_pyramid, n_levels_for
from clearfast_gis.registration.search import gradient_magnitude, rotation_candidates
from clearfast_gis.registration.transform import ConformalTransform

N_PARAMS = 4

# fast maths without the no-NaN assumption: NaN marks no-data and is tested for
_FASTMATH = {"nsz", "arcp", "contract", "afn", "reassoc"}


@njit(cache=True, inline="always", fastmath=_FASTMATH)
def _bspline3(x: float) -> float:
    ax = abs(x)
    if ax < 1.0:
        return 2.0 / 3.0 - ax * ax + 0.5 * ax * ax * ax
    if ax < 2.0:
        t = 2.0 - ax
        return t * t * t / 6.0
    return 0.0


@njit(cache=True, inline="always", fastmath=_FASTMATH)
def _bspline3_deriv(x: float) -> float:
    ax = abs(x)
    if ax < 1.0:
        return -2.0 * x + 1.5 * x * ax
    if ax < 2.0:
        t = 2.0 - ax
        return -0.5 * t * t if x > 0 else 0.5 * t * t
    return 0.0


@njit(cache=True, nogil=True, fastmath=_FASTMATH)
def parzen_joint_histogram(
    us: np.ndarray,
    vs: np.ndarray,
    fbin: np.ndarray,
    mov_bin: np.ndarray,
    gx_bin: np.ndarray,
    gy_bin: np.ndarray,
    angle: float,
    tx: float,
    ty: float,
    scale: float,
    cx: float,
    cy: float,
    hist: np.ndarray,
    dhist: np.ndarray,
    want_grad: bool,
    shift_only: bool = False,
) -> int:
    """Accumulate the joint histogram of fixed samples against the transformed moving image.

    Parameters
    ----------
    us, vs : float64 (N,)
        Fixed sample coordinates (column, row), pixels.
    fbin : int32 (N,)
        Fixed bin index of each sample, in ``[0, nbf)``.
    mov_bin : float32 (H, W)
        Moving image mapped to continuous bin coordinates in ``[2, nbm - 3]``; NaN = no data.
    gx_bin, gy_bin : float32 (H, W)
        Derivatives of ``mov_bin`` along columns and rows (bins per pixel).
    angle, tx, ty, scale, cx, cy : float
        Conformal transform (see :mod:`clearfast_gis.registration.transform`).
    hist : float64 (nbf, nbm)
        Output histogram, overwritten.
    dhist : float64 (nbf, nbm, 4)
        Output derivative of ``hist`` w.r.t. (angle, tx, ty, log scale); overwritten when
        ``want_grad``.
    want_grad : bool
        Accumulate ``dhist``.
    shift_only : bool
        Only the translation derivatives are wanted: ``dhist[..., 0]`` and ``dhist[..., 3]``
        stay zero (a third less work per sample when registering a translation).

    Returns
    -------
    int
        Number of samples that fell on valid moving pixels.
    """
    h, w = mov_bin.shape
    nbm = hist.shape[1]
    hist[:] = 0.0
    if want_grad:
        dhist[:] = 0.0
    cs = math.cos(angle)
    sn = math.sin(angle)
    a00 = scale * cs
    a01 = scale * sn
    a10 = -scale * sn
    a11 = scale * cs
    count = 0
    for k in range(us.shape[0]):
        du = us[k] - cx
        dv = vs[k] - cy
        xm = a00 * du + a01 * dv + cx + tx
        ym = a10 * du + a11 * dv + cy + ty
        if not (xm >= 0.0 and ym >= 0.0 and xm <= w - 1.0 and ym <= h - 1.0):
            continue
        i0 = int(xm)
        j0 = int(ym)
        if i0 > w - 2:
            i0 = w - 2
        if j0 > h - 2:
            j0 = h - 2
        fx = xm - i0
        fy = ym - j0
        m00 = mov_bin[j0, i0]
        m01 = mov_bin[j0, i0 + 1]
        m10 = mov_bin[j0 + 1, i0]
        m11 = mov_bin[j0 + 1, i0 + 1]
        val = (m00 * (1.0 - fx) + m01 * fx) * (1.0 - fy) + (m10 * (1.0 - fx) + m11 * fx) * fy
        if val != val:
            continue
        count += 1
        fb = fbin[k]
        lo = int(val) - 1
        inside = lo >= 0 and lo + 3 < nbm  # always, for values in [2, nbm - 3]
        if inside:
            # the four cubic B-spline weights (and derivatives) of bins lo..lo+3 at once
            f = val - (lo + 1)
            g = 1.0 - f
            f2 = f * f
            g2 = g * g
            hist[fb, lo] += g2 * g / 6.0
            hist[fb, lo + 1] += 2.0 / 3.0 - f2 + 0.5 * f2 * f
            hist[fb, lo + 2] += 2.0 / 3.0 - g2 + 0.5 * g2 * g
            hist[fb, lo + 3] += f2 * f / 6.0
        else:
            for j in range(lo, lo + 4):
                if 0 <= j < nbm:
                    hist[fb, j] += _bspline3(val - j)
        if not want_grad:
            continue
        gx = ((gx_bin[j0, i0] * (1.0 - fx) + gx_bin[j0, i0 + 1] * fx) * (1.0 - fy)
              + (gx_bin[j0 + 1, i0] * (1.0 - fx) + gx_bin[j0 + 1, i0 + 1] * fx) * fy)
        gy = ((gy_bin[j0, i0] * (1.0 - fx) + gy_bin[j0, i0 + 1] * fx) * (1.0 - fy)
              + (gy_bin[j0 + 1, i0] * (1.0 - fx) + gy_bin[j0 + 1, i0 + 1] * fx) * fy)
        # d(bin position)/d(parameter) = grad . d(x_moving)/d(parameter)
        d_angle = 0.0
        d_logs = 0.0
        if not shift_only:
            d_angle = gx * scale * (-sn * du + cs * dv) + gy * scale * (-cs * du - sn * dv)
            d_logs = gx * (xm - cx - tx) + gy * (ym - cy - ty)
        for q in range(4):
            j = lo + q
            if inside:
                if q == 0:
                    dw = -0.5 * g2
                elif q == 1:
                    dw = -2.0 * f + 1.5 * f2
                elif q == 2:
                    dw = 2.0 * g - 1.5 * g2
                else:
                    dw = 0.5 * f2
            elif 0 <= j < nbm:
                dw = _bspline3_deriv(val - j)
            else:
                continue
            dhist[fb, j, 1] += dw * gx
            dhist[fb, j, 2] += dw * gy
            if not shift_only:
                dhist[fb, j, 0] += dw * d_angle
                dhist[fb, j, 3] += dw * d_logs
    return count


@njit(cache=True, nogil=True)
def mi_from_histogram(hist: np.ndarray, dhist: np.ndarray, want_grad: bool,
                      grad: np.ndarray) -> float:
    """Mutual information (nats) of a joint histogram and, optionally, its gradient.

    ``grad`` (4,) receives ``dMI/dparameter`` from ``dhist`` (the fixed marginal is held
    constant, as in Mattes et al.): ``sum_ij dp_ij log(p_ij / p_moving_j)``.
    """
    nbf, nbm = hist.shape
    n = 0.0
    for i in range(nbf):
        for j in range(nbm):
            n += hist[i, j]
    grad[:] = 0.0
    if n <= 0.0:
        return 0.0
    pf = np.zeros(nbf)
    pm = np.zeros(nbm)
    for i in range(nbf):
        for j in range(nbm):
            p = hist[i, j] / n
            pf[i] += p
            pm[j] += p
    mi = 0.0
    for i in range(nbf):
        for j in range(nbm):
            p = hist[i, j] / n
            if p > 1e-300:
                lr = math.log(p / pm[j])
                mi += p * (lr - math.log(pf[i]))
                if want_grad:
                    for q in range(grad.shape[0]):
                        grad[q] += dhist[i, j, q] / n * lr
    return mi


XTOL_FINEST_PX = 0.005
"""Stop refining at the finest level once a step moves the image less than this, pixels."""


POLISH_MAX_EVAL = 8
"""Budget of MI evaluations of the final polish at the finest level."""


@dataclass
class _LevelProblem:
    """Fixed samples and binned moving image of one pyramid level."""

    us: np.ndarray
    vs: np.ndarray
    fbin: np.ndarray
    mov_bin: np.ndarray
    gx_bin: np.ndarray
    gy_bin: np.ndarray
    nbf: int
    nbm: int
    radius_px: float
    factor: float
    complete: bool = False
    """Every valid fixed pixel is a sample (more samples cannot be had at this level)."""
    shift_only: bool = False
    """Only the translation is estimated (the kernel skips the other derivatives)."""

    def __post_init__(self) -> None:
        self.hist = np.zeros((self.nbf, self.nbm))
        self.dhist = np.zeros((self.nbf, self.nbm, N_PARAMS))
        self.grad = np.zeros(N_PARAMS)

    def evaluate(self, t: ConformalTransform, want_grad: bool) -> tuple[float, int, np.ndarray]:
        """MI (nats), overlapping sample count and dMI/d(angle, tx, ty, log s)."""
        n = parzen_joint_histogram(
            self.us, self.vs, self.fbin, self.mov_bin, self.gx_bin, self.gy_bin,
            t.angle_rad, t.tx_px, t.ty_px, t.scale, t.center_px[0], t.center_px[1],
            self.hist, self.dhist, want_grad, self.shift_only)
        mi = mi_from_histogram(self.hist, self.dhist, want_grad, self.grad)
        return mi, n, self.grad.copy()


def _bin_scale(values: np.ndarray) -> tuple[float, float]:
    step = max(1, values.size // 50_000)
    lo, hi = np.percentile(values[::step], [0.05, 99.95])
    lo, hi = float(lo), float(hi)
    if not hi > lo:
        hi = lo + 1.0
    return lo, hi


def _informative_samples(fixed: np.ndarray, valid: np.ndarray,
                         n: int) -> tuple[np.ndarray, np.ndarray]:
    """The ``n`` valid pixels of largest gradient magnitude, in raster order.

    The Cramer-Rao bound of a shift estimate falls with the summed squared gradient of the
    samples, so for a given sample budget the steepest pixels give the most precise
    alignment (on 640 x 512 test pairs: median error 0.0045 px against 0.0057 px for a
    regular grid of the same size, worst case 0.007 against 0.011 px).
    """
    filled = np.where(valid, fixed, np.nanmean(fixed)).astype(np.float32)
    gx = cv2.Sobel(filled, cv2.CV_32F, 1, 0, ksize=3)
    gy = cv2.Sobel(filled, cv2.CV_32F, 0, 1, ksize=3)
    mag = gx * gx + gy * gy
    # next to no-data the Sobel sees the fill value: rank those pixels last among the valid
    core = cv2.erode(valid.astype(np.uint8), np.ones((3, 3), np.uint8),
                     borderType=cv2.BORDER_CONSTANT, borderValue=1).astype(bool)
    mag[valid & ~core] = 0.0
    mag[~valid] = -1.0
    flat = np.argpartition(mag.ravel(), mag.size - n)[mag.size - n:]
    flat.sort()
    return np.divmod(flat, fixed.shape[1])


def _level_problem(
    fixed: np.ndarray, moving: np.ndarray, f_range: tuple[float, float],
    m_range: tuple[float, float], bins: int, max_samples: int, factor: float,
    shift_only: bool = False,
) -> _LevelProblem:
    valid = np.isfinite(fixed)
    n_valid = int(valid.sum())
    if n_valid <= max_samples:
        rows, cols = np.nonzero(valid)
    else:
        rows, cols = _informative_samples(fixed, valid, max_samples)
    fvals = fixed[rows, cols].astype(np.float64)
    nb = int(max(8, min(bins, math.sqrt(rows.size / 10.0))))
    lo, hi = f_range
    fbin = np.clip(((fvals - lo) / (hi - lo) * nb).astype(np.int64), 0, nb - 1).astype(np.int32)
    mlo, mhi = m_range
    k = (nb - 5) / (mhi - mlo)
    mov_bin = np.clip((moving - mlo) * k + 2.0, 2.0, nb - 3.0).astype(np.float32)
    gy, gx = np.gradient(mov_bin)
    h, w = fixed.shape
    return _LevelProblem(
        us=cols.astype(np.float64), vs=rows.astype(np.float64), fbin=fbin,
        mov_bin=mov_bin, gx_bin=np.nan_to_num(gx).astype(np.float32),
        gy_bin=np.nan_to_num(gy).astype(np.float32), nbf=nb, nbm=nb,
        radius_px=0.5 * math.hypot(w, h), factor=factor, complete=n_valid <= max_samples,
        shift_only=shift_only)


class _Bounds:
    """Parameter vector <-> transform, with bounds around a base transform."""

    def __init__(self, base: ConformalTransform, active: list[int], max_angle_rad: float,
                 max_shift_px: float, radius_px: float) -> None:
        self.base = base
        self.active = active
        self.r = radius_px
        base_vec = np.array([base.angle_rad * self.r, base.tx_px, base.ty_px,
                             math.log(base.scale) * self.r])
        half = np.array([max_angle_rad * self.r, max_shift_px, max_shift_px,
                         MAX_LOG_SCALE * self.r])
        self.lo = (base_vec - half)[active]
        self.hi = (base_vec + half)[active]

    def to_vec(self, t: ConformalTransform) -> np.ndarray:
        full = np.array([t.angle_rad * self.r, t.tx_px, t.ty_px, math.log(t.scale) * self.r])
        return np.clip(full[self.active], self.lo, self.hi)

    def to_transform(self, vec: np.ndarray) -> ConformalTransform:
        full = np.array([self.base.angle_rad * self.r, self.base.tx_px, self.base.ty_px,
                         math.log(self.base.scale) * self.r])
        full[self.active] = vec
        return replace(self.base, angle_rad=float(full[0] / self.r), tx_px=float(full[1]),
                       ty_px=float(full[2]), scale=math.exp(full[3] / self.r))

    def grad_vec(self, grad: np.ndarray) -> np.ndarray:
        g = np.array([grad[0] / self.r, grad[1], grad[2], grad[3] / self.r])
        return g[self.active]

    def at_bound(self, vec: np.ndarray, tol: float) -> bool:
        return bool(np.any(vec - self.lo < tol) or np.any(self.hi - vec < tol))


def _refine(problem: _LevelProblem, start: ConformalTransform, bounds: _Bounds,
            xtol_px: float, first_step_px: float, max_eval: int = 60
            ) -> tuple[ConformalTransform, float, int, np.ndarray]:
    def fun(vec: np.ndarray) -> tuple[float, np.ndarray]:
        mi, _n, grad = problem.evaluate(bounds.to_transform(vec), True)
        return mi, bounds.grad_vec(grad)

    vec, _mi, _n_eval = maximize_bfgs(fun, bounds.to_vec(start), bounds.lo, bounds.hi,
                                      first_step=first_step_px, max_step=2.0, xtol=xtol_px,
                                      max_eval=max_eval)
    best = bounds.to_transform(vec)
    mi, n, _ = problem.evaluate(best, False)
    return best, mi, n, vec


def register_conformal(f0: np.ndarray, m0: np.ndarray, base: ConformalTransform, search: bool,
                   scale: bool, max_shift_px: float | None, shift_bound: float,
                   max_angle_rad: float, bins: int, max_samples: int, smooth_px: float,
                   min_overlap: float, min_metric: float, polish_samples: int
                   ) -> ConformalTransform:
    """:func:`register_conformal` on the fast kernels (Parzen Mattes MI, analytic gradient,
    bounded L-BFGS over a pyramid) from the checked, masked images ``f0``, ``m0`` and the
    start ``base``; ``search``: global search at the coarsest level (no ``init``)."""
    levels = min(n_levels_for(f0.shape), n_levels_for(m0.shape))
    fpyr = masked_pyramid(f0, levels)
    mpyr = masked_pyramid(m0, levels)
    f_range = _bin_scale(f0[np.isfinite(f0)])
    m_range = _bin_scale(m0[np.isfinite(m0)])

    active = [1, 2]
    if max_angle_rad > 0:
        active.insert(0, 0)
    if scale:
        active.append(3)
    shift_only = active == [1, 2]

    candidates: list[ConformalTransform] = []
    result = base
    mi = 0.0
    n_overlap = 0
    vec = np.zeros(len(active))
    for level in range(levels - 1, -1, -1):
        factor = 0.5 ** level
        fl = masked_gaussian(fpyr[level], smooth_px)
        ml = masked_gaussian(mpyr[level], smooth_px)
        problem = _level_problem(fl, ml, f_range, m_range, bins, max_samples, factor,
                                 shift_only)
        bounds = _Bounds(base.scaled(factor), active, max_angle_rad,
                         shift_bound * factor, problem.radius_px)
        if level == levels - 1:
            if search:
                candidates = _global_candidates(fl, ml, base.scaled(factor), max_angle_rad,
                                                None if max_shift_px is None
                                                else shift_bound * factor,
                                                problem, min_overlap)
            else:
                candidates = [base.scaled(factor)]
        else:
            candidates = [result.scaled(factor)]
        best = None
        for cand in candidates:
            t, cmi, cn, cvec = _refine(problem, cand, bounds,
                                       xtol_px=XTOL_FINEST_PX if level == 0 else 0.02,
                                       first_step_px=0.5 if level == levels - 1 else 0.2)
            score = cmi - _bias_nats(problem.hist)
            if best is None or score > best[0]:
                best = (score, t, cmi, cn, cvec)
        _score, result, mi, n_overlap, vec = best
        if level == 0 and polish_samples > problem.us.size and not problem.complete:
            # final polish with more samples from the converged point: a few evaluations
            # that halve the noise-driven error of the estimate
            problem = _level_problem(fl, ml, f_range, m_range, bins, polish_samples, factor,
                                     shift_only)
            result, mi, n_overlap, vec = _refine(problem, result, bounds,
                                                 xtol_px=XTOL_FINEST_PX, first_step_px=0.05,
                                                 max_eval=POLISH_MAX_EVAL)
        result = result.scaled(1.0 / factor)

    # levels >= 1, so problem and bounds are those of the finest level here
    # normalised MI and the convergence record at the finest level
    problem.evaluate(result, False)  # histogram of the final transform
    nmi = _normalised_mi(mi, problem.hist)
    tol = 1e-3 * np.maximum(bounds.hi - bounds.lo, 1e-9)
    converged = (
        n_overlap >= max(64, min_overlap * problem.us.size)
        and nmi >= min_metric
        and not bounds.at_bound(vec, float(tol.min()))
    )
    return replace(result, metric=float(mi), n_samples=int(n_overlap),
                   converged=bool(converged))


def _bias_nats(hist: np.ndarray) -> float:
    """Miller-Madow estimate of the upward bias of the plug-in MI of ``hist``, nats.

    Small overlaps inflate MI ((K_joint - K_fixed - K_moving + 1) / 2N with K the occupied
    cells); subtracting it keeps a sliver of overlap from beating the true alignment.
    """
    n = hist.sum()
    if n <= 0:
        return 0.0
    occupied = hist > 1e-6
    k_joint = np.count_nonzero(occupied)
    k_f = np.count_nonzero(occupied.any(axis=1))
    k_m = np.count_nonzero(occupied.any(axis=0))
    return max(k_joint - k_f - k_m + 1, 0) / (2.0 * n)


def _normalised_mi(mi: float, hist: np.ndarray) -> float:
    """Bias-corrected MI over min(H(fixed), H(moving)), in [0, 1]."""
    n = hist.sum()
    if n <= 0:
        return 0.0
    ent = []
    for p in (hist.sum(axis=1) / n, hist.sum(axis=0) / n):
        p = p[p > 0]
        ent.append(float(-(p * np.log(p)).sum()))
    h = min(ent)
    return max(mi - _bias_nats(hist), 0.0) / h if h > 0 else 0.0


def _global_candidates(
    fixed: np.ndarray, moving: np.ndarray, base: ConformalTransform, max_angle_rad: float,
    max_shift_px: float | None, problem: _LevelProblem, min_overlap: float, keep: int = 3,
) -> list[ConformalTransform]:
    """Best ``keep`` starting points at the coarsest level, ranked by MI."""
    if max_angle_rad > 0:
        step = 1.5 / problem.radius_px
        n = int(math.ceil(max_angle_rad / step))
        angles = base.angle_rad + np.linspace(-max_angle_rad, max_angle_rad, 2 * n + 1)
    else:
        angles = np.array([base.angle_rad])
    cands = rotation_candidates(gradient_magnitude(fixed), gradient_magnitude(moving), angles,
                                base.center_px, base, max_shift_px)
    cands.append(base)
    need = max(64, min_overlap * problem.us.size)
    scored = []
    for c in cands:
        if max_shift_px is not None and max(abs(c.tx_px - base.tx_px),
                                            abs(c.ty_px - base.ty_px)) > max_shift_px:
            continue
        mi, n, _ = problem.evaluate(c, False)
        if n >= need:
            scored.append((mi - _bias_nats(problem.hist), c))
    scored.sort(key=lambda s: -s[0])
    out: list[ConformalTransform] = []
    for _mi, c in scored:
        if all(abs(c.angle_rad - o.angle_rad) * problem.radius_px > 2.0
               or math.hypot(c.tx_px - o.tx_px, c.ty_px - o.ty_px) > 2.0 for o in out):
            out.append(c)
        if len(out) == keep:
            break
    return out or [base]
