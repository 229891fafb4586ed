"""Band radiance of a blackbody: the Planck integral over a spectral band (paper Eq. 2 and 5).

Wavelengths are in micrometres, temperatures in kelvin, radiances in W m-2 sr-1.

Two evaluations of the same integral are provided:

- :func:`band_radiance_quad` integrates Planck's law by adaptive Simpson quadrature with
  Richardson correction (the paper's method, reference [6] of the paper), one temperature at a
  time, to a relative tolerance;
- :func:`band_radiance` evaluates the integral in closed form for whole arrays with the
  substitution ``x = c2 / (lambda T)``, which turns Eq. 2 into
  ``L = K T^4 [G(x_lo) - G(x_hi)]``, ``K = 2 k^4 / (h^3 c^2)``, with
  ``G(x) = int_x^inf t^3 / (e^t - 1) dt``. ``G`` is summed as the convergent series
  ``sum_n e^{-n x} (x^3/n + 3 x^2/n^2 + 6 x/n^3 + 6/n^4)`` for ``x >= 2`` and through the
  Bernoulli expansion of ``t / (e^t - 1)`` for ``x < 2`` (Widger and Woodall, 1976, Bull. Am.
  Meteorol. Soc. 57, 1217). An infinite band gives ``sigma T^4 / pi``.

Constants are CODATA 2018 (:mod:`scipy.constants`).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike
from scipy import constants as _const
from scipy.special import bernoulli, factorial

from clearfast_gis.errors import InvalidInput

H_J_S = _const.h
"""Planck constant, J s."""
C_M_S = _const.c
"""Speed of light in vacuum, m s-1."""
K_J_K = _const.k
"""Boltzmann constant, J K-1."""
SIGMA_W_M2_K4 = _const.Stefan_Boltzmann
"""Stefan-Boltzmann constant, W m-2 K-4."""

C1L_W_UM4_M2_SR = 2.0 * H_J_S * C_M_S**2 * 1e24
"""First radiation constant for radiance, ``2 h c^2``, in W um4 m-2 sr-1 (so that
``C1L / lambda_um^5`` is spectral radiance in W m-2 sr-1 um-1)."""
C2_UM_K = H_J_S * C_M_S / K_J_K * 1e6
"""Second radiation constant ``h c / k`` in um K."""
K_BAND_W_M2_SR_K4 = 2.0 * K_J_K**4 / (H_J_S**3 * C_M_S**2)
"""``2 k^4 / (h^3 c^2)``: band radiance = ``K T^4 int x^3/(e^x - 1) dx``, W m-2 sr-1 K-4."""

_G0 = math.pi**4 / 15.0
_SMALL_X = 2.0
_N_BERNOULLI = 48
_BERNOULLI_COEF = np.asarray(
    [b / ((k + 3) * factorial(k, exact=True)) for k, b in enumerate(bernoulli(_N_BERNOULLI))],
    dtype=np.float64,
)


def spectral_radiance(lambda_um: ArrayLike, t_k: ArrayLike) -> np.ndarray:
    """Planck's law: blackbody spectral radiance.

    Parameters
    ----------
    lambda_um : array_like
        Wavelength, micrometres (> 0).
    t_k : array_like
        Temperature, kelvin (> 0); broadcast against ``lambda_um``.

    Returns
    -------
    ndarray of float64
        Spectral radiance, W m-2 sr-1 um-1.
    """
    lam = np.asarray(lambda_um, dtype=np.float64)
    t = np.asarray(t_k, dtype=np.float64)
    return C1L_W_UM4_M2_SR / lam**5 / np.expm1(C2_UM_K / (lam * t))


def _x_limits(t: np.ndarray, lambda_min_um: float, lambda_max_um: float):
    with np.errstate(divide="ignore"):
        x_lo = C2_UM_K / (lambda_max_um * t) if np.isfinite(lambda_max_um) else np.zeros_like(t)
        x_hi = C2_UM_K / (lambda_min_um * t) if lambda_min_um > 0 else np.full_like(t, np.inf)
    return x_lo, x_hi


def _check_band(lambda_min_um: float, lambda_max_um: float) -> None:
    if not (lambda_min_um >= 0.0 and lambda_max_um > lambda_min_um):
        raise InvalidInput(
            f"spectral band must satisfy 0 <= lambda_min < lambda_max, got "
            f"[{lambda_min_um}, {lambda_max_um}] um", field="band")


def planck_tail(x: ArrayLike) -> np.ndarray:
    """``G(x) = int_x^inf t^3 / (e^t - 1) dt`` (dimensionless), vectorised.

    Parameters
    ----------
    x : array_like
        Lower limit ``x = c2 / (lambda T) >= 0``; ``inf`` gives 0.

    Returns
    -------
    ndarray of float64
        ``G(x)``, same shape as ``x``; ``G(0) = pi^4 / 15``.
    """
    x = np.asarray(x, dtype=np.float64)
    out = np.zeros_like(x)
    big = np.isfinite(x) & (x >= _SMALL_X)
    if np.any(big):
        xb = x[big]
        n_terms = int(math.ceil(40.0 / max(float(xb.min()), _SMALL_X)))
        acc = np.zeros_like(xb)
        x2, x3 = xb * xb, xb * xb * xb
        for n in range(n_terms, 0, -1):  # smallest terms first
            acc += np.exp(-n * xb) * (x3 / n + 3.0 * x2 / n**2 + 6.0 * xb / n**3 + 6.0 / n**4)
        out[big] = acc
    small = x < _SMALL_X
    if np.any(small):
        xs = x[small]
        # int_0^x t^3/(e^t-1) dt = sum_k B_k x^(k+3) / ((k+3) k!), |x| < 2 pi; Horner in x.
        poly = np.zeros_like(xs)
        for c in _BERNOULLI_COEF[::-1]:
            poly = poly * xs + c
        out[small] = _G0 - poly * xs**3
    return out


def band_radiance(t_k: ArrayLike, lambda_min_um: float, lambda_max_um: float) -> np.ndarray:
    """Blackbody radiance integrated over a band (paper Eq. 2), closed form, vectorised.

    Parameters
    ----------
    t_k : array_like
        Temperature, kelvin (> 0), any shape.
    lambda_min_um, lambda_max_um : float
        Band limits, micrometres; ``0`` and ``inf`` are allowed (``[0, inf]`` gives
        ``sigma T^4 / pi``).

    Returns
    -------
    ndarray of float64
        Band radiance, W m-2 sr-1, shape of ``t_k``. Non-positive or NaN temperatures give NaN.
    """
    _check_band(lambda_min_um, lambda_max_um)
    t = np.asarray(t_k, dtype=np.float64)
    ok = t > 0
    ts = np.where(ok, t, 1.0)
    x_lo, x_hi = _x_limits(ts, lambda_min_um, lambda_max_um)
    rad = K_BAND_W_M2_SR_K4 * ts**4 * (planck_tail(x_lo) - planck_tail(x_hi))
    return np.where(ok, rad, np.nan)


def band_radiance_derivative(
    t_k: ArrayLike, lambda_min_um: float, lambda_max_um: float
) -> np.ndarray:
    """``dL/dT`` of the band radiance, W m-2 sr-1 K-1 (closed form, vectorised).

    With ``f(x) = x^3 / (e^x - 1)`` and ``I = G(x_lo) - G(x_hi)``:
    ``dL/dT = K T^3 [4 I + x_lo f(x_lo) - x_hi f(x_hi)]``.

    Parameters
    ----------
    t_k : array_like
        Temperature, kelvin (> 0).
    lambda_min_um, lambda_max_um : float
        Band limits, micrometres.

    Returns
    -------
    ndarray of float64
        Derivative, shape of ``t_k``.
    """
    _check_band(lambda_min_um, lambda_max_um)
    t = np.asarray(t_k, dtype=np.float64)
    x_lo, x_hi = _x_limits(t, lambda_min_um, lambda_max_um)

    def xf(x: np.ndarray) -> np.ndarray:
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            v = x**4 / np.expm1(x)
        return np.where(np.isfinite(x) & (x > 0), v, 0.0)

    integral = planck_tail(x_lo) - planck_tail(x_hi)
    return K_BAND_W_M2_SR_K4 * t**3 * (4.0 * integral + xf(x_lo) - xf(x_hi))


def band_temperature(
    radiance: ArrayLike,
    lambda_min_um: float,
    lambda_max_um: float,
    t_min_k: float = 150.0,
    t_max_k: float = 500.0,
) -> np.ndarray:
    """Exact inverse of :func:`band_radiance`: the temperature of a blackbody (Eq. 5).

    Safeguarded Newton iteration on the closed-form band radiance, started from a 1 K table;
    converges to ~1e-10 K. Slow compared with :meth:`BandTable.temperature`; used to build the
    tables and as the accuracy reference.

    Parameters
    ----------
    radiance : array_like
        Band radiance, W m-2 sr-1.
    lambda_min_um, lambda_max_um : float
        Band limits, micrometres.
    t_min_k, t_max_k : float
        Bracket of admissible temperatures, kelvin.

    Returns
    -------
    ndarray of float64
        Temperature, kelvin; NaN where the radiance is NaN or outside the bracket.
    """
    rad = np.asarray(radiance, dtype=np.float64)
    t_grid = np.arange(t_min_k, t_max_k + 0.5, 1.0)
    l_grid = band_radiance(t_grid, lambda_min_um, lambda_max_um)
    inside = np.isfinite(rad) & (rad >= l_grid[0]) & (rad <= l_grid[-1])
    r = np.where(inside, rad, l_grid[0])
    t = np.interp(r, l_grid, t_grid)
    for _ in range(30):
        step = (band_radiance(t, lambda_min_um, lambda_max_um) - r) / band_radiance_derivative(
            t, lambda_min_um, lambda_max_um)
        t = np.clip(t - step, t_min_k, t_max_k)
        if np.all(np.abs(step) < 1e-11 * t):
            break
    return np.where(inside, t, np.nan)


def adaptive_simpson(
    f: Callable[[float], float],
    a: float,
    b: float,
    abs_tol: float,
    max_depth: int = 50,
) -> float:
    """Integrate ``f`` over ``[a, b]`` by recursive adaptive Simpson quadrature.

    Each interval is split in two; if the two halves' Simpson sum ``S2`` differs from the
    whole-interval estimate ``S1`` by at most ``15 tol``, the Richardson-corrected value
    ``S2 + (S2 - S1) / 15`` is accepted, otherwise each half is refined with ``tol / 2``
    (Lyness 1969, "Notes on the adaptive Simpson quadrature routine", J. ACM 16, 483).

    Parameters
    ----------
    f : callable
        Scalar integrand.
    a, b : float
        Finite limits.
    abs_tol : float
        Absolute error target for the whole integral (> 0).
    max_depth : int
        Recursion limit; at this depth the corrected estimate is accepted as is.

    Returns
    -------
    float
        The integral.
    """
    if not (math.isfinite(a) and math.isfinite(b)):
        raise InvalidInput("adaptive Simpson needs finite limits", field="limits")
    if abs_tol <= 0:
        raise InvalidInput("tolerance must be positive", field="abs_tol")
    fa, fb = f(a), f(b)
    m = 0.5 * (a + b)
    fm = f(m)
    whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb)
    return _simpson_step(f, a, b, fa, fm, fb, whole, abs_tol, max_depth)


def _simpson_step(
    f: Callable[[float], float], a: float, b: float, fa: float, fm: float, fb: float,
    whole: float, tol: float, depth: int,
) -> float:
    m = 0.5 * (a + b)
    lm, rm = 0.5 * (a + m), 0.5 * (m + b)
    flm, frm = f(lm), f(rm)
    left = (m - a) / 6.0 * (fa + 4.0 * flm + fm)
    right = (b - m) / 6.0 * (fm + 4.0 * frm + fb)
    delta = left + right - whole
    if depth <= 0 or abs(delta) <= 15.0 * tol:
        return left + right + delta / 15.0
    return (_simpson_step(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1)
            + _simpson_step(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1))


def _planck_x_integrand(x: float) -> float:
    if x <= 0.0:
        return 0.0
    if x > 700.0:
        return 0.0
    return x**3 / math.expm1(x)


_X_CUTOFF = 120.0  # int_120^inf x^3/(e^x-1) dx < 1e-45: negligible against any band


def band_radiance_quad(
    t_k: ArrayLike,
    lambda_min_um: float,
    lambda_max_um: float,
    rel_tol: float = 1e-10,
) -> np.ndarray:
    """Band radiance (Eq. 2) by adaptive Simpson quadrature of Planck's law.

    Finite bands are integrated over wavelength as written in Eq. 2. A band reaching 0 or
    infinity is integrated in the dimensionless variable ``x = c2 / (lambda T)`` (the same
    integral, ``L = K T^4 int x^3/(e^x - 1) dx``), truncated at ``x = 120``.

    Parameters
    ----------
    t_k : array_like
        Temperature, kelvin (> 0), any shape; evaluated one value at a time.
    lambda_min_um, lambda_max_um : float
        Band limits, micrometres.
    rel_tol : float
        Relative tolerance of each integral.

    Returns
    -------
    ndarray of float64
        Band radiance, W m-2 sr-1, shape of ``t_k``.
    """
    _check_band(lambda_min_um, lambda_max_um)
    t_arr = np.asarray(t_k, dtype=np.float64)
    out = np.empty(t_arr.shape)
    finite_band = lambda_min_um > 0 and np.isfinite(lambda_max_um)
    for idx, t in np.ndenumerate(t_arr):
        if not t > 0:
            out[idx] = np.nan
            continue
        if finite_band:
            c2_t = C2_UM_K / t

            def f(lam: float, c2_t: float = c2_t) -> float:
                return C1L_W_UM4_M2_SR / lam**5 / math.expm1(c2_t / lam)

            a, b = lambda_min_um, lambda_max_um
            scale = 1.0
        else:
            f = _planck_x_integrand
            a = C2_UM_K / (lambda_max_um * t) if np.isfinite(lambda_max_um) else 0.0
            b = C2_UM_K / (lambda_min_um * t) if lambda_min_um > 0 else _X_CUTOFF
            b = min(b, _X_CUTOFF)
            scale = K_BAND_W_M2_SR_K4 * t**4
            if b <= a:
                out[idx] = 0.0
                continue
        # a rough 16-panel Simpson estimate sets the absolute tolerance
        xs = np.linspace(a, b, 33)
        ys = np.array([f(float(v)) for v in xs])
        rough = abs((b - a) / 96.0 * (ys[0] + 4 * ys[1:-1:2].sum() + 2 * ys[2:-1:2].sum()
                                       + ys[-1]))
        tol = rel_tol * max(rough, 1e-300)
        out[idx] = scale * adaptive_simpson(f, a, b, tol)
    return out
