"""Numba kernels: Parzen-windowed joint histogram and its derivative (Mattes et al. 2003).

The fixed image is binned hard (zero-order B-spline), the moving image with a cubic B-spline
Parzen window, so the joint histogram -- and the mutual information computed from it -- is a
smooth function of the transform parameters with an analytic gradient.

Parameter order of the derivatives: ``(angle_rad, tx_px, ty_px, log_scale)``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

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
