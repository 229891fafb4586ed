"""Band Planck integral (Eq. 2): quadrature, closed form, limits, inverse."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad
from scipy.optimize import brentq

from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry import (
    adaptive_simpson,
    band_radiance,
    band_radiance_derivative,
    band_radiance_quad,
    band_temperature,
    spectral_radiance,
)
from clearfast_gis.radiometry.planck import SIGMA_W_M2_K4, planck_tail

BANDS = [(8.0, 12.0), (8.0, 9.2), (10.3, 11.3), (3.0, 5.0), (7.5, 14.0)]


def scipy_band(t_k: float, lo: float, hi: float) -> float:
    val, _ = quad(lambda lam: float(spectral_radiance(lam, t_k)), lo, hi,
                  epsabs=0.0, epsrel=1e-12, limit=200)
    return val


@pytest.mark.parametrize("band", BANDS)
@pytest.mark.parametrize("t_k", [200.0, 230.0, 288.15, 350.0, 400.0])
def test_quadrature_matches_scipy_quad(band, t_k):
    ref = scipy_band(t_k, *band)
    assert band_radiance_quad(t_k, *band) == pytest.approx(ref, rel=1e-6)
    assert band_radiance(t_k, *band) == pytest.approx(ref, rel=1e-9)


@pytest.mark.parametrize("t_k", [150.0, 273.15, 300.0, 1000.0, 5772.0])
def test_infinite_band_is_stefan_boltzmann(t_k):
    ref = SIGMA_W_M2_K4 * t_k**4 / np.pi
    assert band_radiance_quad(t_k, 0.0, np.inf) == pytest.approx(ref, rel=1e-6)
    assert band_radiance(t_k, 0.0, np.inf) == pytest.approx(ref, rel=1e-12)


def test_adaptive_simpson_known_integrals():
    assert adaptive_simpson(np.sin, 0.0, np.pi, 1e-12) == pytest.approx(2.0, rel=1e-11)
    assert adaptive_simpson(lambda x: x**4, 0.0, 1.0, 1e-14) == pytest.approx(0.2, rel=1e-13)
    # peaked integrand: adaptivity refines near the peak only
    calls = []

    def peak(x: float) -> float:
        calls.append(x)
        return 1.0 / (1e-4 + (x - 0.3) ** 2)

    exact = (np.arctan(0.7 / 1e-2) + np.arctan(0.3 / 1e-2)) / 1e-2
    assert adaptive_simpson(peak, 0.0, 1.0, 1e-8) == pytest.approx(exact, rel=1e-9)
    xs = np.asarray(calls)
    assert np.sum(np.abs(xs - 0.3) < 0.05) > np.sum(np.abs(xs - 0.8) < 0.05)


def test_wien_displacement_and_limits():
    lam = np.linspace(2.0, 30.0, 28001)
    t_k = 300.0
    peak_um = lam[np.argmax(spectral_radiance(lam, t_k))]
    assert peak_um == pytest.approx(2897.771955 / t_k, abs=1e-3)
    # a band containing almost everything approaches sigma T^4 / pi from below
    full = SIGMA_W_M2_K4 * t_k**4 / np.pi
    wide = band_radiance(t_k, 1.0, 1000.0)
    assert 0.999 * full < wide < full
    # an empty-ish band gives ~0, radiance increases with band width and temperature
    assert band_radiance(t_k, 10.0, 10.0 + 1e-9) == pytest.approx(
        float(spectral_radiance(10.0, t_k)) * 1e-9, rel=1e-6)
    assert band_radiance(t_k, 8.0, 12.0) < band_radiance(t_k, 8.0, 13.0)
    # Wien limit: short wave, cold -> single exponential term
    x = 14387.768775039337 / (1.0 * 200.0)
    assert planck_tail(np.array([x]))[0] == pytest.approx(
        np.exp(-x) * (x**3 + 3 * x**2 + 6 * x + 6), rel=1e-12)
    # Rayleigh-Jeans limit: int_0^x t^2 dt for small x
    assert np.pi**4 / 15 - planck_tail(np.array([1e-4]))[0] == pytest.approx(1e-12 / 3,
                                                                             rel=1e-3)


def test_nan_and_nonpositive_temperature():
    out = band_radiance(np.array([np.nan, -1.0, 0.0, 300.0]), 8.0, 12.0)
    assert np.isnan(out[:3]).all() and np.isfinite(out[3])


def test_bad_band_is_invalid_input():
    with pytest.raises(InvalidInput):
        band_radiance(300.0, 12.0, 8.0)


@settings(max_examples=40, deadline=None)
@given(st.floats(150.0, 600.0), st.sampled_from(BANDS))
def test_derivative_matches_finite_difference(t_k, band):
    h = 1e-3
    fd = (band_radiance(t_k + h, *band) - band_radiance(t_k - h, *band)) / (2 * h)
    assert band_radiance_derivative(t_k, *band) == pytest.approx(fd, rel=1e-7)


@pytest.mark.parametrize("band", BANDS[:3])
def test_exact_inverse_against_brentq_on_quadrature(band):
    for t_true in (231.7, 265.0, 301.3, 349.9):
        r = float(band_radiance_quad(t_true, *band))
        t_ref = brentq(lambda t, r=r: float(band_radiance_quad(t, *band)) - r, 200.0, 400.0,
                       xtol=1e-10)
        assert band_temperature(r, *band) == pytest.approx(t_ref, abs=1e-7)
        assert t_ref == pytest.approx(t_true, abs=1e-6)
