"""Raw counts to apparent temperature on a synthetic survey with known truth."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.radiometry import (
    atmospheric_transmittance,
    event_from_frames,
    observed_radiance,
    surface_leaving_radiance,
)
from clearfast_gis.radiometry.stage import AirState, apparent_temperature_frames

H, W, P = 48, 64, 6
BAND = (8.0, 12.0)


def test_scene_apparent_temperature_within_0_15_k(lw_table):
    """Non-uniform drifting detector, 14-bit counts with 0.05 K NETD noise, grey surfaces
    under a cold sky, per-pixel slant ranges through humid air; two calibration events of
    10 noisy frames per blackbody. The chain recovers the truth's apparent temperature."""
    rng = np.random.default_rng(7)
    t0 = 1.7e9
    event_times = np.array([t0, t0 + 1500.0])
    frame_times = t0 + 200.0 + 180.0 * np.arange(P)

    # detector: counts = gain(t) * L + offset(t), per-pixel non-uniformity, slow drift
    g0 = 260.0 * (1.0 + 0.15 * rng.uniform(-1, 1, (H, W)))
    o0 = 1500.0 + 400.0 * rng.uniform(-1, 1, (H, W))

    def detector(rad: np.ndarray, t_s: float) -> np.ndarray:
        frac = (t_s - t0) / 1500.0
        g = g0 * (1.0 + 0.01 * frac)
        o = o0 + 30.0 * frac
        noise_l = 0.05 * float(np.diff(lw_table.radiance([300.0, 301.0]))[0])
        c = g * (rad + rng.normal(0.0, noise_l, rad.shape)) + o
        return np.clip(np.round(c), 0, 2**14 - 1).astype(np.uint16)

    events = []
    for t_e in event_times:
        t_amb = 288.0 + (t_e - t0) / 1500.0
        t1, t2 = t_amb + 10.0, t_amb
        bb1 = np.stack([detector(np.full((H, W), lw_table.radiance(t1)), t_e) for _ in range(10)])
        bb2 = np.stack([detector(np.full((H, W), lw_table.radiance(t2)), t_e) for _ in range(10)])
        events.append(event_from_frames(t_e, 0, bb1, bb2, t1, t2))

    t_kin = rng.uniform(278.0, 310.0, (P, H, W))
    emis = rng.uniform(0.90, 0.98, (P, H, W))
    sky = lw_table.radiance(245.0)
    surf = surface_leaving_radiance(t_kin, emis, sky, lw_table)
    truth_app = lw_table.temperature_exact(surf)

    air = AirState(np.linspace(287.0, 291.0, P), np.full(P, 85.0), np.full(P, 1002.0))
    slant = rng.uniform(12.0, 30.0, (P, H, W))
    tau = atmospheric_transmittance(slant, air.t_air_k[:, None, None], air.rh_pct[:, None, None],
                                    air.pressure_hpa[:, None, None], *BAND)
    at_camera = observed_radiance(surf, tau, air.t_air_k[:, None, None], lw_table)
    raw = np.stack([detector(at_camera[k], frame_times[k]) for k in range(P)])

    t_app = apparent_temperature_frames(raw, frame_times, 0, lw_table, events, air, slant)
    err = t_app.astype(np.float64) - truth_app
    rms = float(np.sqrt(np.mean(err**2)))
    assert t_app.dtype == np.float32 and np.isfinite(t_app).all()
    assert rms < 0.15
    assert abs(float(err.mean())) < 0.05
    # without the atmospheric correction the error is systematic and larger
    no_atm = apparent_temperature_frames(raw, frame_times, 0, lw_table, events, air, slant,
                                         atmosphere=False)
    assert np.sqrt(np.mean((no_atm - truth_app) ** 2)) > 2 * rms
    # nearest-event calibration is worse than interpolation for a drifting detector
    nearest = apparent_temperature_frames(raw, frame_times, 0, lw_table, events, air, slant,
                                          mode="nearest")
    assert np.sqrt(np.mean((nearest - truth_app) ** 2)) > rms
    # in blocks of frames, into a band of a (P, B, H, W) stack, calibration images shared:
    # the same values
    stack = np.full((P, 2, H, W), np.nan, dtype=np.float32)
    gains: dict = {}
    for block in (slice(0, P // 2), slice(P // 2, P)):
        sub = AirState(*(a[block] for a in (air.t_air_k, air.rh_pct, air.pressure_hpa)))
        got = apparent_temperature_frames(raw[block], frame_times[block], 0, lw_table, events,
                                          sub, slant[block], gain_cache=gains,
                                          out=stack[block, 1])
        assert np.shares_memory(got, stack)
    assert len(gains) == len(events)
    np.testing.assert_array_equal(stack[:, 1], t_app)
    assert np.isnan(stack[:, 0]).all()
    # a path per frame (P,) gives each frame one transmittance, as a constant map would
    mean_path = slant.mean(axis=(1, 2))
    per_frame = apparent_temperature_frames(raw, frame_times, 0, lw_table, events, air,
                                            mean_path)
    as_maps = apparent_temperature_frames(raw, frame_times, 0, lw_table, events, air,
                                          np.broadcast_to(mean_path[:, None, None], slant.shape))
    np.testing.assert_allclose(per_frame, as_maps, atol=1e-4)


def test_frames_reject_bad_path_shape(lw_table):
    from clearfast_gis.errors import InvalidInput

    ev = event_from_frames(0.0, 0, np.full((2, 4, 5), 9000), np.full((2, 4, 5), 7000), 300.0,
                           290.0)
    air = AirState(np.full(3, 290.0), np.full(3, 50.0), np.full(3, 1000.0))
    with pytest.raises(InvalidInput):
        apparent_temperature_frames(np.zeros((3, 4, 5), np.uint16), np.zeros(3), 0, lw_table,
                                    [ev], air, np.ones((3, 4, 6)))
