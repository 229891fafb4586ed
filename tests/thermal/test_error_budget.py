"""The chain's error terms added to an inversion's sigmas."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from clearfast_gis.thermal.error_budget import (
    MAX_REPORTED_DEPTH_SIGMA_M,
    chain_depth_sigma_m,
    with_chain_errors,
)
from clearfast_gis.thermal.inversion import Inversion


def inversion(**kw):
    base = Inversion(0.02, 0.001, 1e-7, 1e-8, 0.04, "ok", 0.05, 0.05, 1.0, 0.1, np.zeros(3))
    return dataclasses.replace(base, **kw)


def test_terms_add_in_quadrature():
    out = with_chain_errors(inversion())
    assert out.depth_sigma_m == pytest.approx(math.hypot(0.001, chain_depth_sigma_m(0.02)))
    assert chain_depth_sigma_m(0.02) == pytest.approx(math.hypot(0.01 * math.sqrt(0.24), 0.002))
    assert out.log10_alpha_sigma == pytest.approx(math.hypot(0.04, 0.1, 0.07))
    assert out.status == "ok"


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
