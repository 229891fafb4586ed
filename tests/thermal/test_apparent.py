"""The apparent contrast's gain against known answers (8-9.2 um, a soil of emissivity 0.85)."""

from __future__ import annotations

import numpy as np

from clearfast_gis.radiometry.planck import band_radiance, band_temperature
from clearfast_gis.thermal.apparent import apparent_gain

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
