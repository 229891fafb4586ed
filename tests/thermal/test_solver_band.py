"""The band Cholesky time stepping (fast kernels) against the sparse LU reference."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg
import scipy.sparse as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis import kernels
from clearfast_gis.thermal import MATERIALS, BuriedObject, solver
from clearfast_gis.thermal import _kernels as banded
from clearfast_gis.thermal.forward import ObjectModel, object_props
from clearfast_gis.thermal.grid import depth_faces, radial_faces
from clearfast_gis.thermal.solver import CellProps, SurfaceDrive, run
from clearfast_gis.thermal.table import object_material

TOL_K = 1e-8


def _random_spd_band(rng: np.random.Generator, n: int, p: int):
    """Random SPD matrix of half-bandwidth p (diagonally dominant): band (n, p+1), dense."""
    dense = np.zeros((n, n))
    for d in range(1, min(p, n - 1) + 1):
        v = rng.normal(size=n - d)
        dense += np.diag(v, -d) + np.diag(v, d)
    dense += np.diag(np.abs(dense).sum(axis=1) + rng.uniform(0.1, 2.0, size=n))
    band = np.zeros((n, p + 1))
    for d in range(min(p, n - 1) + 1):
        band[: n - d, d] = np.diag(dense, -d)
    return band, dense


@given(st.integers(1, 60), st.integers(0, 9), st.integers(0, 2**32 - 1))
@settings(max_examples=60, deadline=None)
def test_band_cholesky_and_solve_match_lapack(n, p, seed):
    rng = np.random.default_rng(seed)
    band, dense = _random_spd_band(rng, n, p)
    low = banded.cholesky(band)
    lapack = scipy.linalg.cholesky_banded(band.T, lower=True).T
    np.testing.assert_allclose(low, lapack, rtol=1e-12, atol=1e-12)
    b = rng.normal(size=n) * 10.0 ** rng.integers(-3, 4)
    x = banded.solve(banded.pack(low), b)
    want = scipy.linalg.solve(dense, b, assume_a="pos")
    np.testing.assert_allclose(x, want, rtol=1e-11, atol=1e-12 * np.abs(want).max())
    np.testing.assert_allclose(dense @ x, b, rtol=1e-10, atol=1e-10 * np.abs(b).max())


def test_band_cholesky_rejects_an_indefinite_matrix():
    band = np.array([[2.0, 3.0], [2.0, 0.0]])  # [[2, 3], [3, 2]]: eigenvalues 5 and -1
    with pytest.raises(ValueError, match="not positive definite"):
        banded.cholesky(band)


def _object_case(depth_m=0.02, log10_alpha=-7.0):
    z = depth_faces(0.5)
    r = radial_faces(0.05, 0.4, 6)
    obj = BuriedObject(0.05, 0.05, depth_m, object_material(10.0**log10_alpha))
    return z, r, object_props(z, r, MATERIALS["moist_sand"], obj)


def test_band_is_the_assembled_matrix():
    """The band the fast path factorises holds exactly the CSR matrix of the reference."""
    z, r, props = _object_case()
    net = solver._network(z, r, props)
    extra = np.linspace(1.0, 2.0, net.diag.size)
    band = solver._band(net, extra)
    nr = r.size - 1
    assert band.shape == (net.diag.size, nr + 1)
    mat = (solver._assemble(z, r, props)[0] + sp.diags(extra)).toarray()
    assert np.count_nonzero(np.triu(mat, nr + 1)) == 0  # half-bandwidth nr
    for d in range(nr + 1):
        np.testing.assert_array_equal(band[: band.shape[0] - d, d], np.diag(mat, -d))
    # and it factorises to the LAPACK factor
    np.testing.assert_allclose(banded.cholesky(band),
                               scipy.linalg.cholesky_banded(band.T, lower=True).T,
                               rtol=1e-12, atol=1e-12)


def _drive(n_steps: int, dt: float, emissivity: float = 0.95):
    """A day of a nonlinear surface drive: sun, cold night sky, wind."""
    t = dt * np.arange(n_steps + 1)
    day = np.clip(np.sin(2 * np.pi * (t / 86400.0 - 0.25)), 0.0, None)
    hc = 5.7 + 3.8 * (2.0 + np.sin(2 * np.pi * t / 86400.0))
    flux = 0.75 * 800.0 * day + emissivity * 300.0 + hc * (288.0 + 6.0 * day)
    bottom = 290.0 + 0.1 * np.sin(t / 86400.0)
    return SurfaceDrive(flux, hc, bottom, emissivity, 4 * emissivity * 5.67e-8 * 290**3 + 10.0)


def _both(*args, **kw):
    fast = run(*args, **kw)
    with kernels.use("reference"):
        ref = run(*args, **kw)
    return fast, ref


def _assert_same(fast, ref):
    assert fast.surface_k.shape == ref.surface_k.shape
    np.testing.assert_allclose(fast.surface_k, ref.surface_k, rtol=0, atol=TOL_K)
    assert sorted(fast.states) == sorted(ref.states)
    for step, state in ref.states.items():
        assert fast.states[step].shape == state.shape
        np.testing.assert_allclose(fast.states[step], state, rtol=0, atol=TOL_K)
    if ref.profiles is None:
        assert fast.profiles is None
    else:
        assert fast.profiles.shape == ref.profiles.shape
        np.testing.assert_allclose(fast.profiles, ref.profiles, rtol=0, atol=TOL_K)


def test_column_agrees_with_the_reference():
    z = depth_faces(0.5)
    nz, n_steps, dt = z.size - 1, 288, 300.0
    ones = np.ones((nz, 1))
    props = CellProps(0.6 * ones, 0.6 * ones, 1.3e6 * ones)
    init = np.linspace(283.0, 290.0, nz)[:, None]
    fast, ref = _both(z, np.array([0.0, 1.0]), props, _drive(n_steps, dt), dt, init,
                      keep_states=(0, 7, n_steps, n_steps + 3, -1), keep_profiles=True)
    _assert_same(fast, ref)
    assert sorted(fast.states) == [0, 7, n_steps]
    assert fast.profiles.shape == (n_steps + 1, nz, 1)
    assert np.ptp(fast.surface_k) > 10.0  # a real diurnal cycle, not a trivial run


def test_object_grid_agrees_with_the_reference_with_history_and_surface_init():
    z, r, props = _object_case(depth_m=0.01, log10_alpha=-5.5)
    nz, nr = z.size - 1, r.size - 1
    n_steps, dt = 161, 600.0
    rng = np.random.default_rng(3)
    init = 288.0 + rng.normal(0.0, 0.5, (nz, nr))
    prev = init - 0.01
    surface = (init[0] + 0.2, init[0] + 0.1)
    fast, ref = _both(z, r, props, _drive(n_steps, dt), dt, init, prev,
                      surface_init_k=surface, keep_states=(1, 80, 161))
    _assert_same(fast, ref)
    assert fast.profiles is None and sorted(fast.states) == [1, 80, 161]
    fast, ref = _both(z, r, props, _drive(n_steps, dt), dt, init, keep_profiles=True)
    _assert_same(fast, ref)
    assert fast.profiles.shape == (n_steps + 1, nz, nr)


@pytest.mark.parametrize(("depth_m", "log10_alpha"), [(0.0, -7.5), (0.02, -7.0), (0.1, -4.5)])
def test_object_model_surface_agrees_with_the_reference(forcing, scans, depth_m, log10_alpha):
    soil = MATERIALS["moist_sand"]
    obj = BuriedObject(0.05, 0.05, depth_m, object_material(10.0**log10_alpha))
    model = ObjectModel(soil, forcing, scans, 0.05)
    with kernels.use("reference"):
        ref_model = ObjectModel(soil, forcing, scans, 0.05)
        ref = ref_model.surface_steps(obj)
    np.testing.assert_allclose(model.column.surface_k, ref_model.column.surface_k,
                               rtol=0, atol=TOL_K)
    fast = model.surface_steps(obj)
    assert fast.shape == ref.shape
    np.testing.assert_allclose(fast, ref, rtol=0, atol=TOL_K)
    contrast = fast[:, 0] - fast[:, -1]
    assert np.abs(contrast).max() > 0.02  # the object shows at the surface


def test_kernel_switch_selects_the_implementation(monkeypatch):
    calls = []
    from clearfast_gis.thermal import _reference

    real_splu = _reference.splu
    monkeypatch.setattr(_reference, "splu", lambda a: calls.append(1) or real_splu(a))
    z, r, props = _object_case()
    init = np.full((z.size - 1, r.size - 1), 288.0)
    run(z, r, props, _drive(3, 600.0), 600.0, init)
    assert calls == []
    with kernels.use("reference"):
        run(z, r, props, _drive(3, 600.0), 600.0, init)
    assert calls == [1]
