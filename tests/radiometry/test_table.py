"""BandTable: forward table, fast inverse and the paper's 0.1 K inversion (Eq. 5)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry import (
    BandTable,
    apparent_temperature_paper,
    band_radiance,
    band_temperature,
)

T_CHECK_K = np.linspace(230.0, 350.0, 120_001)  # 1 mK steps


@pytest.mark.parametrize("name", ["lw_table", "lw1_table"])
def test_forward_table_matches_closed_form(name, request):
    table = request.getfixturevalue(name)
    ref = band_radiance(T_CHECK_K, table.lambda_min_um, table.lambda_max_um)
    np.testing.assert_allclose(table.radiance(T_CHECK_K), ref, rtol=1e-10)
    outside = np.array([150.0, 450.0])
    np.testing.assert_allclose(table.radiance(outside),
                               band_radiance(outside, table.lambda_min_um,
                                             table.lambda_max_um), rtol=1e-12)


@pytest.mark.parametrize("name", ["lw_table", "lw1_table"])
def test_both_inverse_paths_within_5_mk(name, request):
    table = request.getfixturevalue(name)
    rad = band_radiance(T_CHECK_K, table.lambda_min_um, table.lambda_max_um)
    exact = band_temperature(rad, table.lambda_min_um, table.lambda_max_um)
    np.testing.assert_allclose(exact, T_CHECK_K, atol=1e-8)
    fast = table.temperature(rad, dtype=np.float64)
    paper = apparent_temperature_paper(rad, table)
    assert np.max(np.abs(fast - exact)) < 1e-3  # design bound (1 mK), well inside 5 mK
    assert np.max(np.abs(paper - exact)) < 5e-3
    assert table.inverse_error_k < 1e-3
    # float32 in and out, as the pipeline runs it: float32 rounding adds ~20 uK at most
    fast32 = table.temperature(rad.astype(np.float32))
    assert fast32.dtype == np.float32
    assert np.max(np.abs(fast32.astype(np.float64) - exact)) < 5e-3


def test_inverse_nan_and_out_of_range(lw_table):
    lo, hi = lw_table.radiance(np.array([lw_table.t_min_k, lw_table.t_max_k]))
    r = np.array([np.nan, lo * 0.5, hi * 1.5, -1.0, lo, hi])
    fast = lw_table.temperature(r, dtype=np.float64)
    paper = apparent_temperature_paper(r, lw_table)
    assert np.isnan(fast[:4]).all() and np.isnan(paper[:4]).all()
    np.testing.assert_allclose(fast[4:], [lw_table.t_min_k, lw_table.t_max_k], atol=1e-9)
    np.testing.assert_allclose(paper[4:], [lw_table.t_min_k, lw_table.t_max_k], atol=1e-9)


def test_inverse_keeps_shape(lw_table):
    t = np.full((3, 4, 5), 300.0)
    out = lw_table.temperature(lw_table.radiance(t))
    assert out.shape == (3, 4, 5)
    np.testing.assert_allclose(out, 300.0, atol=1e-4)


@settings(max_examples=60, deadline=None)
@given(st.floats(230.0, 350.0))
def test_round_trip_property(lw_table, t_k):
    assert float(lw_table.temperature(lw_table.radiance(t_k), dtype=np.float64)) == (
        pytest.approx(t_k, abs=1e-3))


def test_mid_wave_band_refines_its_inverse():
    table = BandTable(3.0, 5.0, n_inverse=4096)
    assert table.inverse_t_k.size > 4096
    assert table.inverse_error_k < 1e-3
    rad = band_radiance(T_CHECK_K[::50], 3.0, 5.0)
    assert np.max(np.abs(table.temperature(rad, dtype=np.float64) - T_CHECK_K[::50])) < 1e-3


def test_bad_range_is_invalid_input():
    with pytest.raises(InvalidInput):
        BandTable(8.0, 12.0, t_min_k=300.0, t_max_k=250.0)
