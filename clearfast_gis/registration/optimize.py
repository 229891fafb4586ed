"""A small bounded quasi-Newton maximiser for a handful of well-scaled parameters.

Registration has 2-4 parameters, all scaled to pixels of displacement, and a smooth objective
with an analytic gradient that costs far more than the linear algebra: BFGS with an Armijo
backtracking line search and box projection, with none of the per-call overhead of a general
library optimiser (which dominated the run time on small pyramid levels).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np


def maximize_bfgs(
    fun: Callable[[np.ndarray], tuple[float, np.ndarray]],
    x0: np.ndarray,
    lower: np.ndarray,
    upper: np.ndarray,
    first_step: float = 0.5,
    max_step: float = 2.0,
    xtol: float = 1e-3,
    max_eval: int = 60,
) -> tuple[np.ndarray, float, int]:
    """Maximise ``fun`` inside the box ``[lower, upper]``.

    Parameters
    ----------
    fun : callable
        ``fun(x) -> (value, gradient)``; ``x`` and the gradient have shape (n,).
    x0 : ndarray (n,)
        Start (projected into the box).
    lower, upper : ndarray (n,)
        Bounds.
    first_step : float
        Length (max-norm, parameter units) of the first steepest-ascent step.
    max_step : float
        Largest step per iteration (max-norm).
    xtol : float
        Stop when an accepted step is shorter than this (max-norm).
    max_eval : int
        Budget of ``fun`` evaluations.

    Returns
    -------
    x : ndarray (n,)
        Best point found.
    value : float
        ``fun`` there.
    n_eval : int
        Evaluations used.
    """
    x = np.clip(np.asarray(x0, dtype=np.float64), lower, upper)
    f, g = fun(x)
    n_eval = 1
    n = x.size
    hinv: np.ndarray | None = None
    while n_eval < max_eval:
        gmax = float(np.max(np.abs(g)))
        if gmax == 0.0 or not np.isfinite(gmax):
            break
        if hinv is None:
            hinv = np.eye(n) * (first_step / gmax)
        d = hinv @ g
        if float(g @ d) <= 0.0:  # not an ascent direction: restart from steepest ascent
            hinv = np.eye(n) * (first_step / gmax)
            d = hinv @ g
        dmax = float(np.max(np.abs(d)))
        if dmax > max_step:
            d *= max_step / dmax
        alpha = 1.0
        accepted = False
        while n_eval < max_eval:
            x_new = np.clip(x + alpha * d, lower, upper)
            s = x_new - x
            if float(np.max(np.abs(s))) < 0.1 * xtol:
                break
            f_new, g_new = fun(x_new)
            n_eval += 1
            if f_new >= f + 1e-4 * float(g @ s):
                accepted = True
                break
            alpha *= 0.3
        if not accepted:
            if np.allclose(hinv, np.eye(n) * (first_step / gmax)):
                break
            hinv = None  # retry once from steepest ascent
            continue
        y = g - g_new  # gradient of the function being minimised (-fun) changes by -y
        sy = float(s @ y)
        if sy > 1e-12:
            rho = 1.0 / sy
            v = np.eye(n) - rho * np.outer(s, y)
            hinv = v @ hinv @ v.T + rho * np.outer(s, s)
        x, f, g = x_new, f_new, g_new
        if float(np.max(np.abs(s))) < xtol:
            break
    return x, f, n_eval
