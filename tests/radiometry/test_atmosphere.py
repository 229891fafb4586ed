"""Atmospheric transmittance, path radiance and Eq. 4 correction."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry import (
    atmospheric_transmittance,
    correct_atmosphere,
    observed_radiance,
    path_radiance,
    surface_leaving_radiance,
    water_vapour_content,
)

LW = (8.0, 12.0)


def test_twenty_metres_humid_mild_air_attenuates_a_few_percent():
    # paper section 3.5: ~20 m path, "in the order of 10 %" with MODTRAN; the camera
    # makers' model gives 3-5 % for humid mild air
    for t_c, rh in ((20.0, 80.0), (25.0, 90.0), (30.0, 90.0)):
        tau = float(atmospheric_transmittance(20.0, t_c + 273.15, rh, 1013.25, *LW))
        assert 0.03 < 1.0 - tau < 0.10
    dry = float(atmospheric_transmittance(20.0, 283.15, 20.0, 1013.25, *LW))
    assert 0.0 < 1.0 - dry < 0.03


def test_published_constants_reference_values():
    # w at 20 C, 100 % RH: FLIR's fit gives ~17.13 (vapour pressure 17.5 mmHg)
    assert float(water_vapour_content(293.15, 100.0)) == pytest.approx(17.13, abs=0.02)
    assert float(atmospheric_transmittance(0.0, 293.15, 50.0, 1013.25, *LW)) == 1.0
    # hand evaluation of the formula at d = 100 m, 20 C, 50 % RH
    w = 0.5 * np.exp(1.5587 + 0.06939 * 20 - 0.00027816 * 400 + 0.00000068455 * 8000)
    ref = (1.9 * np.exp(-10 * (0.006569 - 0.002276 * np.sqrt(w)))
           - 0.9 * np.exp(-10 * (0.01262 - 0.00667 * np.sqrt(w))))
    assert float(atmospheric_transmittance(100.0, 293.15, 50.0, 1013.25, *LW)) == (
        pytest.approx(ref, rel=1e-12))


@settings(max_examples=80, deadline=None)
@given(st.floats(0.0, 900.0), st.floats(1.0, 100.0), st.floats(243.15, 318.15),
       st.floats(0.0, 99.0), st.floats(700.0, 1050.0))
def test_transmittance_monotone_in_path_and_humidity(d, dd, t_k, rh, p_hpa):
    tau = atmospheric_transmittance(d, t_k, rh, p_hpa, *LW)
    assert 0.0 < tau <= 1.0
    assert atmospheric_transmittance(d + dd, t_k, rh, p_hpa, *LW) < tau or d + dd == 0
    if d > 0.01:
        assert atmospheric_transmittance(d, t_k, rh + 1.0, p_hpa, *LW) < tau


def test_vectorised_over_pixels():
    d = np.linspace(10.0, 40.0, 12).reshape(3, 4)
    tau = atmospheric_transmittance(d, 290.0, np.array([[60.0]]), 1000.0, *LW)
    assert tau.shape == (3, 4)
    assert np.all(np.diff(tau.ravel()) < 0)


@pytest.mark.parametrize("kwargs", [
    {"path_m": -1.0}, {"path_m": 5000.0}, {"rh_pct": 120.0}, {"pressure_hpa": 0.0},
    {"lambda_min_um": 3.0, "lambda_max_um": 5.0},
])
def test_invalid_inputs(kwargs):
    args = {"path_m": 20.0, "t_air_k": 290.0, "rh_pct": 60.0, "pressure_hpa": 1000.0,
            "lambda_min_um": 8.0, "lambda_max_um": 12.0} | kwargs
    with pytest.raises(InvalidInput):
        atmospheric_transmittance(**args)


def test_round_trip_forward_then_correct_is_exact(lw_table):
    rng = np.random.default_rng(3)
    surf = lw_table.radiance(rng.uniform(260.0, 320.0, (4, 6, 7)))
    tau = atmospheric_transmittance(rng.uniform(12.0, 35.0, (4, 6, 7)), 291.0, 75.0, 1005.0,
                                    *LW)
    seen = observed_radiance(surf, tau, 291.0, lw_table)
    np.testing.assert_allclose(correct_atmosphere(seen, tau, 291.0, lw_table), surf,
                               rtol=1e-13)
    # float32 in, float32 out
    back32 = correct_atmosphere(seen.astype(np.float32), tau, 291.0, lw_table)
    assert back32.dtype == np.float32
    np.testing.assert_allclose(back32, surf, rtol=1e-6)


def test_path_radiance_and_air_temperature_surface(lw_table):
    # a surface at air temperature looks the same through any path (Kirchhoff)
    b_air = lw_table.radiance(288.0)
    for tau in (1.0, 0.9, 0.5):
        assert observed_radiance(b_air, tau, 288.0, lw_table) == pytest.approx(b_air, rel=1e-14)
    assert path_radiance(0.9, 288.0, lw_table) == pytest.approx(0.1 * b_air, rel=1e-14)


def test_surface_leaving_radiance(lw_table):
    t = np.array([290.0, 300.0])
    sky = lw_table.radiance(250.0)
    np.testing.assert_allclose(surface_leaving_radiance(t, 1.0, sky, lw_table),
                               lw_table.radiance(t))
    grey = surface_leaving_radiance(t, 0.95, sky, lw_table)
    np.testing.assert_allclose(grey, 0.95 * lw_table.radiance(t) + 0.05 * sky)
    t_app = lw_table.temperature(grey, dtype=np.float64)
    assert np.all(t_app < t) and np.all(t_app > t - 5.0)
