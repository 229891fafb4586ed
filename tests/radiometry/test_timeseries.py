"""Interpolation in instrument logs; weather at frame times."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry.stage import weather_at
from clearfast_gis.radiometry.timeseries import interpolate_log
from clearfast_gis.survey import WeatherLog


@settings(max_examples=50, deadline=None)
@given(st.lists(st.floats(0.0, 1e5), min_size=2, max_size=30, unique=True),
       st.floats(-3.0, 3.0), st.floats(-100.0, 100.0), st.floats(0.0, 1.0))
def test_linear_quantity_is_recovered_exactly(times, slope, icpt, frac):
    t = np.array(times)
    rng = np.random.default_rng(0)
    perm = rng.permutation(t.size)  # order of records does not matter
    q = t.min() + frac * (t.max() - t.min())
    got = interpolate_log(t[perm], (icpt + slope * t)[perm], q, max_gap_s=1e6)
    assert got == pytest.approx(icpt + slope * q, abs=1e-6 * (1 + abs(slope) * 1e5))


def test_gaps_and_nan_records():
    t = np.array([0.0, 60.0, 120.0, 180.0])
    v = np.array([1.0, np.nan, 3.0, 4.0])
    np.testing.assert_allclose(interpolate_log(t, v, [30.0, 60.0, 200.0], 60.0),
                               [1.5, 2.0, 4.0])
    with pytest.raises(InvalidInput, match=r"weather.dat: RH_Avg"):
        interpolate_log(t, v, [400.0], 60.0, "weather.dat", "RH_Avg")
    with pytest.raises(InvalidInput):
        interpolate_log(t, np.full(4, np.nan), [10.0], 60.0)


def test_weather_at_frame_times():
    t = np.arange(0.0, 600.0, 60.0)
    n = t.size
    log = WeatherLog(time_s=t, air_temp_c=10.0 + t / 60.0, rh_pct=np.full(n, 101.0),
                     pressure_hpa=np.full(n, 1000.0), wind_ms=np.zeros(n),
                     solar_wm2=np.zeros(n), sky_lw_wm2=np.full(n, np.nan),
                     rain_mm=np.full(n, np.nan))
    air = weather_at(log, [90.0, 300.0])
    np.testing.assert_allclose(air.t_air_k, [284.65, 288.15])
    np.testing.assert_allclose(air.rh_pct, 100.0)  # sensor overshoot clipped
    with pytest.raises(InvalidInput, match="AirTC_Avg"):
        weather_at(log, [1e5], source="weather.dat")
