"""The chain's error terms added to an inversion's sigmas."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from clearfast_gis.thermal.error_budget import (
    DEPTH_RELATIVE,
    DEPTH_TERMS_M,
    GAIN_TERM,
    LOG10_ALPHA_TERMS,
    MAX_REPORTED_DEPTH_SIGMA_M,
    OFFSET_TERM_K,
    chain_sigmas,
    curve_term_shifts,
    with_chain_errors,
)
from clearfast_gis.thermal.inversion import Inversion


def inversion(**kw):
    base = Inversion(0.02, 0.001, 1e-7, 1e-8, 0.04, "ok", 0.05, 0.05, 1.0, 0.1, np.zeros(3))
    return dataclasses.replace(base, **kw)


def curve(scale=1.0, n=6):
    """A diurnal-like contrast curve (K) and its Jacobian (K/m, K) over ``n`` scans."""
    t = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    model = scale * (0.5 * np.sin(t) + 0.1)
    jac = scale * np.stack([-20.0 * np.sin(t) - 3.0, 0.3 * np.cos(t) + 0.05], axis=1)
    return model, jac


def test_without_jacobian_only_the_model_terms_add_in_quadrature():
    out = with_chain_errors(inversion())
    const = math.sqrt(sum(v * v for v in DEPTH_TERMS_M.values()))
    assert const == pytest.approx(math.sqrt(0.001**2 + 0.0005**2 + 0.002**2))
    assert out.depth_sigma_m == pytest.approx(math.hypot(0.001, const, DEPTH_RELATIVE * 0.02))
    assert out.log10_alpha_sigma == pytest.approx(math.hypot(0.04, 0.04, 0.05))
    assert math.hypot(*LOG10_ALPHA_TERMS.values()) == pytest.approx(math.hypot(0.04, 0.05))
    assert out.status == "ok"


def test_curve_terms_are_the_least_squares_shifts_of_the_estimates():
    model, jac = curve()
    shifts = curve_term_shifts(jac, model)
    gain = np.linalg.lstsq(jac, GAIN_TERM * model, rcond=None)[0]
    offset = np.linalg.lstsq(jac, np.full(6, OFFSET_TERM_K), rcond=None)[0]
    np.testing.assert_allclose(shifts, [gain, offset], rtol=1e-9)
    d, la = chain_sigmas(inversion(model_contrast_k=model, jacobian=jac))
    const = sum(v * v for v in DEPTH_TERMS_M.values()) + (0.05 * 0.02) ** 2
    assert d == pytest.approx(math.sqrt(const + gain[0] ** 2 + offset[0] ** 2))
    assert la == pytest.approx(math.sqrt(0.04**2 + 0.05**2 + gain[1] ** 2 + offset[1] ** 2))


def test_a_weak_curve_gets_a_larger_offset_term_and_the_same_gain_term():
    strong = curve_term_shifts(*reversed(curve(1.0)))
    weak = curve_term_shifts(*reversed(curve(0.1)))
    np.testing.assert_allclose(weak[0], strong[0], rtol=1e-9)  # relative: scale-free
    np.testing.assert_allclose(weak[1], 10 * strong[1], rtol=1e-9)  # absolute K


def test_the_terms_depend_on_when_the_scans_sample_the_day():
    model, jac = curve(n=48)
    day = slice(0, 24)  # the scans of the first half of the cycle only
    whole = curve_term_shifts(jac, model)[1, 0]
    half = curve_term_shifts(jac[day], model[day])[1, 0]
    assert abs(half - whole) > 0.2 * abs(whole)


def test_a_singular_jacobian_is_an_undetermined_estimate():
    model, jac = curve()
    jac[:, 1] = 2 * jac[:, 0]
    assert np.all(np.isinf(curve_term_shifts(jac, model)))
    out = with_chain_errors(inversion(model_contrast_k=model, jacobian=jac))
    assert out.depth_sigma_m == MAX_REPORTED_DEPTH_SIGMA_M
    assert out.status == "not_characterised"


def test_too_uncertain_is_not_characterised_and_sigma_capped():
    out = with_chain_errors(inversion(depth_sigma_m=26.8, status="weak_contrast"))
    assert out.depth_sigma_m == MAX_REPORTED_DEPTH_SIGMA_M == 0.20
    assert out.status == "weak_contrast"
    assert with_chain_errors(inversion(depth_sigma_m=0.03)).status == "not_characterised"
    assert with_chain_errors(inversion(depth_sigma_m=math.inf)).depth_sigma_m == 0.20


def test_disc_weights_are_the_area_shares_of_the_disc():
    from clearfast_gis.thermal.grid import radial_faces
    from clearfast_gis.thermal.table import disc_weights

    faces = radial_faces(0.05, 0.4, 6)
    w = disc_weights(faces, 0.05)
    assert w.sum() == pytest.approx(1.0)
    assert np.all(w[6:] == 0) and np.all(np.diff(w[:6]) > 0)  # annuli grow with radius
    assert w[0] == pytest.approx((0.05 / 6) ** 2 / 0.05 ** 2)
    axis = disc_weights(faces, 0.0)
    assert axis[0] == 1.0 and axis[1:].sum() == 0.0
