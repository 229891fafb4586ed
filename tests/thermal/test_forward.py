from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.errors import InvalidInput
from clearfast_gis.thermal import MATERIALS, BuriedObject, simulate_background, simulate_object
from clearfast_gis.thermal.grid import centres, depth_faces
from clearfast_gis.thermal.solver import CellProps, SurfaceDrive, run

OMEGA = 2 * np.pi / 86400.0


def _periodic_column(alpha_k=0.3, rho_c=1.28e6, h=20.0, amp=10.0, dt=300.0, days=6):
    """Linear Robin surface: q = h (T_e - T_s), T_e = 290 + amp sin(omega t)."""
    z = depth_faces(1.0)
    nz = z.size - 1
    n = int(days * 86400 / dt)
    t = dt * np.arange(n + 1)
    te = 290.0 + amp * np.sin(OMEGA * t)
    drive = SurfaceDrive(h * te, np.full(n + 1, h), np.full(n + 1, 290.0), 0.0, h)
    ones = np.ones((nz, 1))
    props = CellProps(alpha_k * ones, alpha_k * ones, rho_c * ones)
    res = run(z, np.array([0.0, 1.0]), props, drive, dt, np.full((nz, 1), 290.0),
              keep_profiles=True)
    return z, t, res


def _harmonic(t, y):
    """Complex amplitude of exp(i omega t) in y (least squares over whole periods)."""
    a = np.column_stack([np.ones_like(t), np.cos(OMEGA * t), np.sin(OMEGA * t)])
    c = np.linalg.lstsq(a, y, rcond=None)[0]
    return c[2] + 1j * c[1]  # y = Im(A exp(i w t)) = Re(A) sin + Im(A) cos


def test_periodic_solution_amplitude_and_phase_at_depth():
    k, rho_c, h, amp = 0.3, 1.28e6, 20.0, 10.0
    z, t, res = _periodic_column(k, rho_c, h, amp)
    alpha = k / rho_c
    damp = np.sqrt(2 * alpha / OMEGA)
    lam = (1 + 1j) / damp
    surface_amp = h * amp / (h + k * lam)  # complex amplitude of T_s
    last = t >= t[-1] - 86400.0
    zc = centres(z)
    for depth in (0.02, 0.05, 0.10):
        i = int(np.argmin(np.abs(zc - depth)))
        want = surface_amp * np.exp(-lam * zc[i])
        got = _harmonic(t[last], res.profiles[last, i, 0])
        assert abs(got) == pytest.approx(abs(want), rel=0.02)
        assert np.angle(got) == pytest.approx(np.angle(want), abs=0.02 * zc[i] / damp + 0.005)
    got_s = _harmonic(t[last], res.surface_k[last, 0])
    assert abs(got_s) == pytest.approx(abs(surface_amp), rel=0.02)


def test_background_converges_against_twice_finer_reference(forcing, scans):
    soil = MATERIALS["dry_sand"]
    a = simulate_background(soil, forcing, scans)
    b = simulate_background(soil, forcing, scans, refine=1)
    assert np.max(np.abs(a.surface_k - b.surface_k)) <= 0.02


def test_object_contrast_converges_against_twice_finer_reference(forcing, scans):
    soil = MATERIALS["moist_sand"]
    obj = BuriedObject(0.052, 0.05, 0.02, MATERIALS["tnt"])
    a = simulate_object(soil, obj, forcing, scans)
    b = simulate_object(soil, obj, forcing, scans, refine=1)
    ca = a.surface_k[:, 0] - a.background_k
    cb = b.surface_k[:, 0] - b.background_k
    assert np.max(np.abs(ca - cb)) <= 0.02
    assert np.max(np.abs(a.surface_k[:, 0] - b.surface_k[:, 0])) <= 0.02


def test_design_guide_contrasts_of_a_10_cm_tnt_mine_in_moist_sand(forcing, scans):
    soil = MATERIALS["moist_sand"]
    peaks, times = [], []
    for depth, lo, hi in ((0.01, 1.8, 2.8), (0.05, 0.33, 0.6), (0.10, 0.05, 0.15)):
        run_ = simulate_object(soil, BuriedObject(0.05, 0.05, depth, MATERIALS["tnt"]),
                               forcing, scans, radii_m=(0.0, 0.1, 0.45))
        c = run_.surface_k[:, 0] - run_.background_k
        assert lo < c.max() < hi
        peaks.append(c.max())
        times.append(scans[np.argmax(c)])
        # far from the object the surface is the undisturbed one
        assert np.max(np.abs(run_.surface_k[:, 2] - run_.background_k)) < 0.01
        # the contrast fades with distance from the axis
        assert np.max(np.abs(run_.surface_k[:, 1] - run_.background_k)) < c.max()
    assert times[0] < times[1] < times[2]


def test_contrast_is_smooth_in_depth(forcing, scans):
    soil = MATERIALS["moist_sand"]
    peaks = []
    for depth in np.arange(0.0, 0.0301, 0.002):
        r = simulate_object(soil, BuriedObject(0.05, 0.05, depth, MATERIALS["tnt"]), forcing,
                            scans[::4])
        peaks.append(np.max(r.surface_k[:, 0] - r.background_k))
    steps = np.diff(peaks)
    assert np.all(steps < 0)  # deeper is weaker
    assert np.max(np.abs(np.diff(steps))) < 0.05  # no jumps when a face is crossed


def test_profile_follows_bottom_and_surface(forcing, scans):
    bottom = 288.0
    run_ = simulate_background(MATERIALS["moist_sand"], forcing, scans,
                               depths_m=(0.0, 0.02, 0.5), bottom=bottom)
    assert np.allclose(run_.profile_k[:, 2], bottom)
    assert np.allclose(run_.profile_k[:, 0], run_.surface_k)
    amp = np.ptp(run_.profile_k, axis=0)
    assert amp[0] > amp[1] > amp[2]


def test_times_outside_the_forcing_are_rejected(forcing, scans):
    with pytest.raises(InvalidInput, match="out_time_s"):
        simulate_background(MATERIALS["dry_sand"], forcing, scans + 3 * 86400.0)
