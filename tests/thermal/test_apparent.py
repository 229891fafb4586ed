"""The apparent contrast's gain against known answers (8-9.2 um, a soil of emissivity 0.85)."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.radiometry.planck import band_radiance, band_temperature
from clearfast_gis.thermal.apparent import (
    apparent_gain,
    band_emissivity_estimate,
    sky_band_radiance,
)
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.units import STEFAN_BOLTZMANN

BAND = (8.0, 9.2)
EPS = 0.85


def apparent_k(t_k, eps=EPS, sky_k=None):
    """Apparent temperature of a grey surface at ``t_k`` reflecting a sky at ``sky_k``."""
    sky = 0.0 if sky_k is None else band_radiance(sky_k, *BAND)
    return band_temperature(eps * band_radiance(t_k, *BAND) + (1 - eps) * sky, *BAND)


def test_without_sky_the_gain_is_the_derivative_of_the_apparent_temperature():
    t = np.array([283.0, 290.0, 300.0, 310.0])
    gain = apparent_gain(apparent_k(t), t, *BAND)
    numeric = (apparent_k(t + 0.01) - apparent_k(t - 0.01)) / 0.02
    np.testing.assert_allclose(gain, numeric, rtol=1e-4)
    assert np.all(gain < EPS + 0.1) and np.all(gain > EPS)  # B'(T) / B'(T_a) > 1


def test_a_cold_sky_makes_it_an_over_estimate_by_its_reflected_share():
    t = np.full(6, 295.0)
    gain = apparent_gain(apparent_k(t, sky_k=245.0), t, *BAND)
    exact = (apparent_k(t + 0.01, sky_k=245.0) - apparent_k(t - 0.01, sky_k=245.0)) / 0.02
    assert np.all(gain > exact)
    assert np.all(gain - exact < 0.06)


def test_unknown_scans_keep_the_model_contrast():
    t = np.array([290.0, 291.0, 292.0])
    gain = apparent_gain(np.array([np.nan, np.nan, np.nan]), t, *BAND)
    np.testing.assert_array_equal(gain, 1.0)


def test_with_the_sky_the_emissivity_and_gain_are_exact():
    """The reflected sky's band radiance given: the emissivity and the gain are the grey
    surface's own, scan by scan, whatever the sky's temperature."""
    t = np.array([284.0, 290.0, 298.0, 305.0, 300.0, 288.0])
    sky_k = np.array([240.0, 245.0, 250.0, 255.0, 250.0, 242.0])
    sky = band_radiance(sky_k, *BAND)
    ta = apparent_k(t, sky_k=sky_k)
    assert band_emissivity_estimate(ta, t, sky, *BAND) == pytest.approx(EPS, abs=1e-6)
    gain = apparent_gain(ta, t, *BAND, sky_radiance=sky)
    exact = (apparent_k(t + 0.01, sky_k=sky_k) - apparent_k(t - 0.01, sky_k=sky_k)) / 0.02
    np.testing.assert_allclose(gain, exact, rtol=1e-4)
    # without the sky the same data over-state the gain by its reflected share
    assert np.all(apparent_gain(ta, t, *BAND) - exact > 0.03)


def test_scans_with_ground_near_the_sky_brightness_are_left_out():
    t = np.array([290.0, 292.0, 250.5])
    sky_k = np.array([245.0, 246.0, 250.0])
    sky = band_radiance(sky_k, *BAND)
    ta = apparent_k(t, sky_k=sky_k)
    ta[2] += 3.0  # 0 / 0 there: would give a wild ratio
    assert band_emissivity_estimate(ta, t, sky, *BAND) == pytest.approx(EPS, abs=1e-6)
    assert np.isnan(band_emissivity_estimate(ta[2:], t[2:], sky[2:], *BAND))


def test_the_sky_from_the_weather_log_is_a_window_share_of_the_air():
    """Clear sky (broadband emissivity 0.78): the window's band emissivity is 1 - 2.5 * 0.22
    = 0.45 of the air's band radiance; overcast (emissivity 1): the air's own."""
    air = np.array([290.0, 290.0])
    sky_lw = np.array([0.78, 1.0]) * STEFAN_BOLTZMANN * air**4
    times = np.array([0.0, 3600.0])
    forcing = Forcing(times, np.zeros(2), sky_lw, air, np.ones(2), np.full(2, 50.0))
    got = sky_band_radiance(forcing, times, *BAND)
    np.testing.assert_allclose(got, np.array([0.45, 1.0]) * band_radiance(air, *BAND),
                               rtol=1e-9)
