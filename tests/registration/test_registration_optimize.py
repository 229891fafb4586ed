"""The bounded BFGS maximiser against scipy's L-BFGS-B."""

from __future__ import annotations

import numpy as np
from scipy.optimize import minimize

from clearfast_gis.registration.optimize import maximize_bfgs


def _neg_rosenbrock(x: np.ndarray) -> tuple[float, np.ndarray]:
    a, b = x
    f = (1 - a) ** 2 + 10 * (b - a * a) ** 2
    g = np.array([-2 * (1 - a) - 40 * a * (b - a * a), 20 * (b - a * a)])
    return -f, -g


def test_unconstrained_optimum() -> None:
    x, f, n = maximize_bfgs(_neg_rosenbrock, np.array([-1.0, 1.5]), np.full(2, -5.0),
                            np.full(2, 5.0), first_step=0.2, max_step=1.0, xtol=1e-8,
                            max_eval=500)
    np.testing.assert_allclose(x, [1.0, 1.0], atol=1e-4)
    assert f > -1e-8 and n < 500


def test_bounded_optimum_matches_lbfgsb() -> None:
    lo, hi = np.array([-2.0, -2.0]), np.array([0.5, 2.0])
    x, _f, _n = maximize_bfgs(_neg_rosenbrock, np.array([-1.0, 1.5]), lo, hi, first_step=0.2,
                              xtol=1e-9, max_eval=500)
    ref = minimize(lambda v: tuple(-np.asarray(t) for t in _neg_rosenbrock(v)),
                   np.array([-1.0, 1.5]), jac=True, method="L-BFGS-B",
                   bounds=list(zip(lo, hi, strict=True)))
    np.testing.assert_allclose(x, ref.x, atol=1e-4)
    assert x[0] == 0.5


def test_quadratic_in_few_evaluations() -> None:
    h = np.diag([1.0, 4.0, 0.5])

    def fun(x: np.ndarray) -> tuple[float, np.ndarray]:
        d = x - np.array([0.3, -0.2, 0.7])
        return -0.5 * d @ h @ d, -h @ d

    x, _f, n = maximize_bfgs(fun, np.zeros(3), np.full(3, -5.0), np.full(3, 5.0), xtol=1e-6)
    np.testing.assert_allclose(x, [0.3, -0.2, 0.7], atol=1e-5)
    assert n <= 20
