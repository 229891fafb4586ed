"""Weather and ground physics against known answers: clouds, vapour, evaporation, dew, soils,
solar geometry in the tropics and the southern hemisphere."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from clearfast_gis import kernels
from clearfast_gis.thermal import clear_sky_emissivity, simulate_background, solar_position
from clearfast_gis.thermal.clouds import cloud_solar_factor, cloudy_sky_emissivity
from clearfast_gis.thermal.forcing import Forcing, forcing_from_weather, rain_rate_mm_h
from clearfast_gis.thermal.materials import get_soil
from clearfast_gis.thermal.moisture import (
    LATENT_HEAT_JKG,
    SurfaceWater,
    dew_point_k,
    latent_heat_flux_wm2,
    psychrometric_hpa_k,
    saturation_slope_hpa_k,
    saturation_vapour_pressure_hpa,
    wetness_factor,
)
from clearfast_gis.thermal.soils import SOIL_TYPES, soil_of_type
from clearfast_gis.thermal.solar import sun_times
from clearfast_gis.timeutil import parse_utc
from clearfast_gis.units import STEFAN_BOLTZMANN

from .conftest import DAY0_S


def test_kasten_czeplak_limits():
    assert cloud_solar_factor(0.0) == pytest.approx(1.0)
    assert cloud_solar_factor(1.0) == pytest.approx(0.25)
    # N = 0.5: 1 - 0.75 * 0.5^3.4 = 1 - 0.75 * 0.09473 = 0.92895 (Kasten & Czeplak 1980)
    assert cloud_solar_factor(0.5) == pytest.approx(0.92895, abs=1e-4)
    n = np.linspace(0, 1, 11)
    assert np.all(np.diff(cloud_solar_factor(n)) < 0)


def test_cloudy_sky_emissivity_limits():
    t, rh = np.array([283.15, 300.0]), np.array([70.0, 40.0])
    np.testing.assert_allclose(cloudy_sky_emissivity(t, rh, 0.0), clear_sky_emissivity(t, rh))
    np.testing.assert_allclose(cloudy_sky_emissivity(t, rh, 1.0),
                               np.minimum(1.22 * clear_sky_emissivity(t, rh), 1.0))
    # a full overcast over humid air radiates nearly as a blackbody at air temperature
    # (measured overcast emissivities 0.93-1, e.g. Iziomon et al. 2003)
    assert cloudy_sky_emissivity(283.15, 90.0, 1.0) > 0.93


def test_magnus_saturation_pressure_against_tables():
    # WMO / Smithsonian tables over water: 6.112 hPa at 0 C, 23.39 at 20 C, 42.47 at 30 C
    np.testing.assert_allclose(saturation_vapour_pressure_hpa([273.15, 293.15, 303.15]),
                               [6.1094, 23.39, 42.47], rtol=3e-3)
    # slope: numerical derivative
    t = np.array([280.0, 295.0, 310.0])
    num = (saturation_vapour_pressure_hpa(t + 1e-3) - saturation_vapour_pressure_hpa(t - 1e-3))
    np.testing.assert_allclose(saturation_slope_hpa_k(t), num / 2e-3, rtol=1e-6)


def test_dew_point_known_values_and_round_trip():
    # 20 C at 50 % -> 9.3 C; 30 C at 70 % -> 23.9 C (psychrometric tables)
    assert dew_point_k(293.15, 50.0) - 273.15 == pytest.approx(9.26, abs=0.1)
    assert dew_point_k(303.15, 70.0) - 273.15 == pytest.approx(23.9, abs=0.15)
    assert dew_point_k(290.0, 100.0) == pytest.approx(290.0, abs=1e-9)


@given(st.floats(250.0, 320.0), st.floats(5.0, 100.0))
def test_dew_point_is_where_air_saturates(t_k, rh):
    td = dew_point_k(t_k, rh)
    assert td <= t_k + 1e-9
    assert saturation_vapour_pressure_hpa(td) == pytest.approx(
        rh / 100 * saturation_vapour_pressure_hpa(t_k), rel=1e-9)


def test_psychrometric_constant_at_sea_level():
    assert psychrometric_hpa_k() == pytest.approx(0.668, abs=0.005)


def test_wetness_factor_lee_pielke():
    assert wetness_factor(0.0, 0.2) == 0.0
    assert wetness_factor(0.2, 0.2) == pytest.approx(1.0)
    assert wetness_factor(0.3, 0.2) == pytest.approx(1.0)
    assert wetness_factor(0.1, 0.2) == pytest.approx(0.25)


def test_latent_flux_signs_evaporation_and_dew():
    hc = 10.0
    # a warm wet surface evaporates at the Penman-type bulk rate
    le = latent_heat_flux_wm2(300.0, 293.15, 50.0, hc, 1.0)
    expect = hc / psychrometric_hpa_k() * (saturation_vapour_pressure_hpa(300.0)
                                          - 0.5 * saturation_vapour_pressure_hpa(293.15))
    assert le == pytest.approx(expect)
    assert le > 0
    # a surface below the dew point takes dew even when dry (beta ignored)
    td = dew_point_k(288.15, 90.0)
    assert latent_heat_flux_wm2(td - 2.0, 288.15, 90.0, hc, 0.0) < 0
    assert latent_heat_flux_wm2(td, 288.15, 90.0, hc, 0.0) == pytest.approx(0.0, abs=1e-9)


def _steady_forcing(n=2 * 24 * 12 + 1, solar=0.0, sky=None, air=293.15, rh=50.0, wind=2.0,
                    rain=0.0):
    t = DAY0_S + 300.0 * np.arange(n)
    one = np.ones(n)
    sky = STEFAN_BOLTZMANN * air**4 * 0.8 if sky is None else sky
    return Forcing(t, solar * one, sky * one, air * one, wind * one, rh * one, rain * one)


def test_evaporation_energy_balance_of_a_wet_column():
    """Constant weather, wet soil held at field capacity: the column reaches the steady surface
    temperature where net radiation + sensible heat = latent heat (conduction to the bottom,
    held at that temperature, vanishes)."""
    from scipy.optimize import brentq

    soil = dataclasses.replace(get_soil("moist_sand"), water=SurfaceWater(0.3, 0.15, 0.4))
    f = _steady_forcing(solar=300.0)
    hc = 5.7 + 3.8 * 2.0

    def balance(ts):
        net = ((1 - soil.albedo) * 300.0 + soil.emissivity * f.sky_lw_wm2[0]
               - soil.emissivity * STEFAN_BOLTZMANN * ts**4 + hc * (293.15 - ts))
        return net - latent_heat_flux_wm2(ts, 293.15, 50.0, hc, 1.0)

    ts_eq = brentq(balance, 250.0, 330.0)
    run = simulate_background(soil, f, f.time_s[-3:], spinup_days=3.0, bottom=ts_eq)
    assert run.surface_k[-1] == pytest.approx(ts_eq, abs=0.02)
    # the same dry surface is much warmer
    dry = simulate_background(get_soil("moist_sand"), f, f.time_s[-3:], spinup_days=3.0)
    assert dry.surface_k[-1] > run.surface_k[-1] + 5.0


def test_surface_water_dries_rains_and_takes_dew():
    from clearfast_gis.thermal.forward import _Setup
    from clearfast_gis.thermal.solver import run

    def surface_water(f, theta0):
        soil = dataclasses.replace(get_soil("moist_sand"),
                                   water=SurfaceWater(0.05, 0.15, 0.4, theta_start=theta0))
        setup = _Setup(soil, f, f.time_s[[0, -1]], 0.0, 300.0, None, 0.5, 0)
        nz = setup.z_faces.size - 1
        from clearfast_gis.thermal.solver import CellProps
        props = CellProps(*(np.full((nz, 1), v) for v in (soil.k_wmk, soil.k_wmk,
                                                           soil.rho_c_jm3k)))
        res = run(setup.z_faces, np.array([0.0, 1.0]), props, setup.drive, setup.dt,
                  np.full((nz, 1), 293.15))
        return res.theta[:, 0]

    # a sunny dry day: the wet surface dries towards the deep moisture
    theta = surface_water(_steady_forcing(n=289, solar=400.0, rh=30.0), 0.3)  # one day
    assert theta[-1] < 0.2 and np.all(np.diff(theta) <= 1e-12)
    # 10 mm of rain in an hour wets it up (to saturation at most)
    f = _steady_forcing(n=289, rh=95.0, rain=10.0)
    theta = surface_water(f, 0.05)
    assert theta[12] > 0.09 and theta.max() <= 0.4
    # a clear calm night with humid air: the surface cools below the dew point and gains water
    night = _steady_forcing(n=289, sky=260.0, air=283.15, rh=95.0, wind=0.5)
    theta = surface_water(night, 0.0)
    assert theta[-1] > 0.0


def test_water_per_step_balances_the_latent_energy():
    """Over a run with no restoring term, the water lost equals the latent energy / L_v."""
    from clearfast_gis.thermal import moisture

    f = _steady_forcing(n=145, solar=500.0, rh=20.0)
    soil = dataclasses.replace(get_soil("moist_sand"), water=SurfaceWater(0.3, 0.5, 0.5))
    run = simulate_background(soil, f, f.time_s[-3:], spinup_days=0.0)
    hc = 5.7 + 3.8 * 2.0
    le = latent_heat_flux_wm2(run.surface_k[-1], 293.15, 20.0, hc,
                              wetness_factor(0.3, 0.5))
    # evaporation of 1 mm of water takes L_v / 1000 J m-2 per mm: order of a sunny day's LE
    assert 50.0 < le < 600.0
    assert moisture.LATENT_HEAT_JKG == LATENT_HEAT_JKG


def test_band_and_reference_kernels_agree_with_latent_heat(forcing, scans):
    soil = soil_of_type("loam", 0.5)
    f = dataclasses.replace(forcing, rain_mm_h=np.where(
        (forcing.time_s - DAY0_S > 6 * 3600) & (forcing.time_s - DAY0_S < 7 * 3600), 5.0, 0.0))
    fast = simulate_background(soil, f, scans)
    with kernels.use("reference"):
        ref = simulate_background(soil, f, scans)
    np.testing.assert_allclose(fast.surface_k, ref.surface_k, atol=1e-8)


def test_dry_soil_without_water_is_unchanged_by_rain(forcing, scans):
    soil = get_soil("dry_sand")
    wet = dataclasses.replace(forcing, rain_mm_h=np.full(forcing.time_s.size, 3.0))
    a = simulate_background(soil, forcing, scans).surface_k
    b = simulate_background(soil, wet, scans).surface_k
    np.testing.assert_array_equal(a, b)


def test_rain_cools_an_evaporating_soil(forcing, scans):
    soil = soil_of_type("sand", 0.05)
    rain = (forcing.time_s - DAY0_S >= 5 * 3600) & (forcing.time_s - DAY0_S < 6 * 3600)
    wet = dataclasses.replace(forcing, rain_mm_h=np.where(rain, 8.0, 0.0))
    a = simulate_background(soil, forcing, scans).surface_k
    b = simulate_background(soil, wet, scans).surface_k
    noon = np.argmin(np.abs(scans - (DAY0_S + 10 * 3600)))
    assert a[noon] - b[noon] > 2.0


@pytest.mark.parametrize("name", list(SOIL_TYPES))
def test_soil_properties_span_the_literature(name):
    dry, wet = soil_of_type(name, 0.0), soil_of_type(name, 1.0)
    # Campbell & Norman (1998) Fig. 8.4 / Farouki (1981): dry 0.15-0.6, saturated 1.2-2.8 W/m/K
    assert 0.15 <= dry.k_wmk <= 0.6
    assert 1.2 <= wet.k_wmk <= 2.8
    assert dry.rho_c_jm3k < wet.rho_c_jm3k
    assert wet.albedo < dry.albedo
    s = np.linspace(0, 1, 11)
    k = [soil_of_type(name, v).k_wmk for v in s]
    assert np.all(np.diff(k) >= 0)


def test_sand_at_field_capacity_matches_de_vries():
    # de Vries (1963): sand at theta 0.2 (porosity 0.4): k ~1.8-2.2, rho c ~2.0e6
    s = soil_of_type("sand", 0.5)
    assert s.k_wmk == pytest.approx(2.0, abs=0.3)
    assert s.rho_c_jm3k == pytest.approx(1.99e6, rel=0.02)


def test_soil_type_errors_name_the_field():
    from clearfast_gis.errors import InvalidInput

    with pytest.raises(InvalidInput, match="loamy_sand"):
        soil_of_type("peat", 0.5)
    with pytest.raises(InvalidInput):
        soil_of_type("sand", 1.5)


def test_rain_totals_become_rates_in_the_forcing():
    t = DAY0_S + 60.0 * np.arange(5)
    log = {"time_s": t, "air_temp_c": np.full(5, 10.0), "rh_pct": np.full(5, 90.0),
           "wind_ms": np.ones(5), "solar_wm2": np.zeros(5),
           "rain_mm": np.array([0.0, 0.1, np.nan, 0.2, 0.0])}
    f = forcing_from_weather(log)
    np.testing.assert_allclose(f.rain_mm_h, [0.0, 6.0, 0.0, 12.0, 0.0])
    np.testing.assert_allclose(rain_rate_mm_h(t, [0.1] * 5), 6.0)


@pytest.mark.parametrize("lat, day, decl_deg", [
    (-33.9, "2026-12-21", -23.44),   # Cape Town, southern summer solstice
    (-33.9, "2026-06-21", 23.44),    # southern winter
    (9.0, "2026-03-20", 0.0),        # tropics at the equinox
    (9.0, "2026-06-21", 23.44),      # sun north of the zenith at 9 N
])
def test_noon_sun_anywhere(lat, day, decl_deg):
    lon = 18.4
    _, noon, _ = sun_times(lat, lon, parse_utc(f"{day}T12:00:00Z"))
    el, az = solar_position(lat, lon, np.array([noon]))
    assert el[0] == pytest.approx(90.0 - abs(lat - decl_deg), abs=0.3)
    # the noon sun stands north of a site south of the sub-solar point, else south
    assert az[0] == pytest.approx(0.0 if lat < decl_deg else 180.0, abs=0.5) or \
        az[0] == pytest.approx(360.0, abs=0.5)


def test_southern_summer_days_are_long():
    rise, _, sets = sun_times(-33.9, 18.4, parse_utc("2026-12-21T12:00:00Z"))
    # Cape Town, 21 December: about 14 h 26 min of daylight
    assert (sets - rise) / 3600 == pytest.approx(14.43, abs=0.1)
