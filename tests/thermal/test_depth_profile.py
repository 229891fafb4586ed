"""The depth's profile interval: equal to the covariance's sigma on a well-determined fit,
wide on a flat one (a curve that many depths explain)."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.thermal.inversion import depth_profile_sigma
from clearfast_gis.thermal.table import contrast_spline

DEPTHS = np.linspace(0.0, 0.20, 15)
LOG_ALPHA = np.linspace(-7.5, -4.5, 10)
LO, HI = np.array([DEPTHS[0], LOG_ALPHA[0]]), np.array([DEPTHS[-1], LOG_ALPHA[-1]])


def _linear_case(depth_slope: float):
    """A contrast linear in (depth, log10 alpha) over 6 scans: (spline, Jacobian, truth)."""
    a = depth_slope * np.array([1.0, -2.0, 0.5, 3.0, -1.0, 2.0])  # K/m
    b = np.array([0.3, 0.1, -0.2, 0.05, 0.4, -0.1])  # K per decade
    grid = DEPTHS[:, None, None] * a + LOG_ALPHA[None, :, None] * b
    return contrast_spline(DEPTHS, LOG_ALPHA, grid), np.stack([a, b], axis=1), \
        np.array([0.05, -6.5])


def test_profile_interval_equals_the_covariance_sigma_when_linear():
    spline, jac, truth = _linear_case(10.0)
    obs = spline(truth[None, :])[0]
    s2 = 0.02**2
    sigma_cov = float(np.sqrt(np.linalg.inv(jac.T @ jac)[0, 0] * s2))
    got = depth_profile_sigma(spline, obs, LO, HI, 0.0, s2)
    assert got == pytest.approx(sigma_cov, abs=0.001)  # the 1 mm depth samples


def test_a_curved_valley_gives_the_interval_the_covariance_misses():
    """Depth traded for diffusivity along a parabola (the fit's valley at the estimate runs
    along the diffusivity): the covariance's local slope claims 0.2 mm; the profile spans
    the centimetres along the valley where the chi-square stays within 1."""
    a = np.array([1.0, -2.0, 0.5, 3.0, -1.0, 2.0])
    b = np.array([0.3, 0.1, -0.2, 0.05, 0.4, -0.1])
    d, la = DEPTHS[:, None, None], LOG_ALPHA[None, :, None]
    grid = 20.0 * a * (d - 0.03 * (la + 6.0) ** 2) + 0.02 * b * (la + 6.0)
    spline = contrast_spline(DEPTHS, LOG_ALPHA, grid)
    truth = np.array([0.03, -6.0])
    obs = spline(truth[None, :])[0]
    x = truth[None, :]
    jac = np.stack([spline(x, nu=(1, 0))[0], spline(x, nu=(0, 1))[0]], axis=1)
    s2 = 0.02**2
    sigma_cov = float(np.sqrt(np.linalg.inv(jac.T @ jac)[0, 0] * s2))
    got = depth_profile_sigma(spline, obs, LO, HI, 0.0, s2)
    assert sigma_cov < 0.001
    assert got > 0.02


def test_linear_but_weak_depth_is_cut_at_the_table():
    spline, jac, truth = _linear_case(0.01)
    obs = spline(truth[None, :])[0]
    got = depth_profile_sigma(spline, obs, LO, HI, 0.0, 0.02**2)
    assert got == pytest.approx(0.5 * (HI[0] - LO[0]), abs=0.001)
