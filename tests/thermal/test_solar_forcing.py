from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.thermal import (
    clear_sky_emissivity,
    clear_sky_ghi,
    forcing_from_weather,
    solar_position,
    sun_times,
)
from clearfast_gis.thermal.solar import _sun_terms
from clearfast_gis.timeutil import parse_utc

from .conftest import DAY0_S, LAT_DEG, LON_DEG


def test_sun_at_noon_is_due_south_at_the_declination_height():
    _, noon, _ = sun_times(LAT_DEG, LON_DEG, DAY0_S)
    el, az = solar_position(LAT_DEG, LON_DEG, np.array([noon]))
    decl, _ = _sun_terms(np.array([noon]))
    assert el[0] == pytest.approx(90.0 - LAT_DEG + np.degrees(decl[0]), abs=0.01)
    assert az[0] == pytest.approx(180.0, abs=0.1)
    # mid-November declination is about -18.5 deg (astronomical almanac)
    assert np.degrees(decl[0]) == pytest.approx(-18.6, abs=0.3)


def test_nicosia_sunrise_and_sunset_mid_november():
    # published times for Nicosia on 15 November: sunrise ~06:24, sunset ~16:40 (UTC+2)
    rise, _, sets = sun_times(LAT_DEG, LON_DEG, DAY0_S)
    assert (rise - DAY0_S) / 60 == pytest.approx(4 * 60 + 24, abs=5)
    assert (sets - DAY0_S) / 60 == pytest.approx(14 * 60 + 40, abs=5)


def test_equinox_day_is_twelve_hours_plus_refraction():
    rise, _, sets = sun_times(0.0, 0.0, parse_utc("2025-03-20T12:00:00Z"))
    assert (sets - rise) / 3600 == pytest.approx(12.12, abs=0.05)


def test_sun_rises_in_the_east_and_is_below_horizon_at_midnight():
    el, az = solar_position(LAT_DEG, LON_DEG, DAY0_S + np.array([5.0 * 3600, 22.0 * 3600]))
    assert 90 < az[0] < 150 and el[0] > 0
    assert el[1] < -30


def test_clear_sky_day_matches_the_design_figures(forcing):
    assert 560 < forcing.solar_wm2.max() < 620
    assert forcing.air_temp_k.min() - 273.15 == pytest.approx(10.0, abs=0.01)
    assert forcing.air_temp_k.max() - 273.15 == pytest.approx(23.0, abs=0.01)
    assert 0.99 < forcing.wind_ms.min() and forcing.wind_ms.max() < 3.01
    assert 260 < forcing.sky_lw_wm2.min() and forcing.sky_lw_wm2.max() < 370
    assert np.all(forcing.solar_wm2[(forcing.time_s - DAY0_S) < 3 * 3600] == 0)
    # the air is coldest at sunrise
    rise, _, _ = sun_times(LAT_DEG, LON_DEG, DAY0_S)
    assert forcing.time_s[np.argmin(forcing.air_temp_k)] == pytest.approx(rise, abs=120)


def test_haurwitz_value():
    assert clear_sky_ghi(np.array([90.0]))[0] == pytest.approx(1098 * np.exp(-0.059), rel=1e-9)
    assert clear_sky_ghi(np.array([-5.0]))[0] == 0.0


@given(st.floats(250.0, 320.0), st.floats(5.0, 100.0))
def test_sky_emissivity_is_physical(t_k, rh):
    e = clear_sky_emissivity(t_k, rh)
    assert 0.3 < e <= 1.0
    assert clear_sky_emissivity(t_k, min(rh + 5.0, 100.0)) >= e


def test_weather_gaps_are_interpolated_and_sky_estimated():
    t = 1.0e9 + 60.0 * np.arange(10)
    air = np.linspace(10.0, 19.0, 10)
    air[3:5] = np.nan
    log = {"time_s": t, "air_temp_c": air, "rh_pct": np.full(10, 60.0),
           "pressure_hpa": np.full(10, 1000.0), "wind_ms": np.full(10, 2.0),
           "solar_wm2": np.full(10, -2.0), "sky_lw_wm2": np.full(10, np.nan)}
    f = forcing_from_weather(log)
    assert f.air_temp_k[3] - 273.15 == pytest.approx(13.0)
    assert np.all(f.solar_wm2 == 0)
    assert f.sky_lw_wm2[0] == pytest.approx(
        clear_sky_emissivity(283.15, 60.0) * 5.670374419e-8 * 283.15**4)


def test_weather_without_a_required_channel_is_rejected():
    t = 1.0e9 + 60.0 * np.arange(4)
    log = {"time_s": t, "air_temp_c": np.full(4, np.nan), "rh_pct": np.ones(4),
           "wind_ms": np.ones(4), "solar_wm2": np.ones(4)}
    with pytest.raises(InvalidInput, match="air_temp_c"):
        forcing_from_weather(log)
