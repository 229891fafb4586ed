"""Two-blackbody calibration (Eq. 1), events, blending, blackbody log interpolation."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry import (
    CalibrationEvent,
    apply_gain_offset,
    blackbody_temperature_at,
    calibrate_two_point,
    event_from_frames,
    gain_offset_at,
    gain_offset_two_point,
    select_events,
)

H, W = 24, 32


def linear_detector(rng: np.random.Generator):
    """Counts = g * radiance + o with +-20 % gain and +-300 count offset non-uniformity."""
    g = 180.0 * (1.0 + 0.2 * rng.uniform(-1, 1, (H, W)))
    o = 2000.0 + 300.0 * rng.uniform(-1, 1, (H, W))
    return g, o


def test_recovers_radiance_exactly_with_nonuniform_detector(lw_table):
    rng = np.random.default_rng(0)
    g, o = linear_detector(rng)
    r1, r2 = lw_table.radiance(np.array([301.0, 291.0]))
    scene = lw_table.radiance(rng.uniform(270.0, 320.0, (5, H, W)))
    raw = g * scene + o  # noise-free, float counts
    rad, valid = calibrate_two_point(raw, g * r1 + o, g * r2 + o, r1, r2)
    assert rad.dtype == np.float32 and rad.shape == (5, H, W)
    assert valid.all()
    np.testing.assert_allclose(rad, scene, rtol=2e-6)
    # the blackbody images themselves map back to the blackbody radiances
    rad_bb, _ = calibrate_two_point(np.stack([g * r1 + o, g * r2 + o]), g * r1 + o,
                                    g * r2 + o, r1, r2)
    np.testing.assert_allclose(rad_bb[0], r1, rtol=2e-6)
    np.testing.assert_allclose(rad_bb[1], r2, rtol=2e-6)


def test_degenerate_pixels_are_flagged_never_divided(lw_table):
    rng = np.random.default_rng(1)
    g, o = linear_detector(rng)
    r1, r2 = lw_table.radiance(np.array([300.0, 290.0]))
    bb1, bb2 = g * r1 + o, g * r2 + o
    bb2[3, 4] = bb1[3, 4]            # dead pixel: identical responses
    bb2[5, 6] = bb1[5, 6] + 1.5      # below the few-count threshold
    bb1[7, 8] = np.nan               # unreadable
    raw = g * lw_table.radiance(np.full((2, H, W), 295.0)) + o
    with np.errstate(all="raise"):
        rad, valid = calibrate_two_point(raw, bb1, bb2, r1, r2, min_contrast_counts=3.0)
    assert not valid[3, 4] and not valid[5, 6] and not valid[7, 8]
    assert valid.sum() == H * W - 3
    assert np.isnan(rad[:, ~valid]).all()
    assert np.isfinite(rad[:, valid]).all()


def test_bad_shapes_are_invalid_input():
    with pytest.raises(InvalidInput):
        gain_offset_two_point(np.zeros((4, 5)), np.zeros((4, 6)), 1.0, 2.0)
    with pytest.raises(InvalidInput):
        event_from_frames(0.0, 0, np.zeros((4, 5)), np.zeros((2, 4, 5)), 300.0, 290.0)


def _events(times, band=0):
    z = np.zeros((2, 2))
    return [CalibrationEvent(t, band, z, z + 10, 300.0, 290.0) for t in times]


def test_select_events_nearest_and_interpolate():
    evs = _events([1000.0, 0.0, 2000.0]) + _events([1500.0], band=1)
    (e, w), = select_events(evs, 1400.0, "nearest", band=0)
    assert e.time_s == 1000.0 and w == 1.0
    pair = select_events(evs, 1250.0, "interpolate", band=0)
    assert [(p.time_s, pytest.approx(q)) for p, q in pair] == [(1000.0, 0.75), (2000.0, 0.25)]
    # outside the events: the nearest one
    assert select_events(evs, -50.0, "interpolate", band=0)[0][0].time_s == 0.0
    assert select_events(evs, 9e9, "interpolate", band=0)[0][0].time_s == 2000.0
    assert select_events(evs, 1000.0, "interpolate", band=0) == [(evs[0], 1.0)]
    assert select_events(evs, 0.0, "nearest", band=1)[0][0].time_s == 1500.0
    with pytest.raises(InvalidInput):
        select_events(evs, 0.0, "nearest", band=2)
    with pytest.raises(InvalidInput):
        select_events(evs, 0.0, "closest")


def test_interpolated_calibration_tracks_a_drifting_detector(lw_table):
    """Calibration (radiance per count, offset) drifting linearly in time is recovered exactly
    between events by interpolation, and only approximately by the nearest event."""
    rng = np.random.default_rng(2)
    gain0 = 1.0 / (180.0 * (1.0 + 0.2 * rng.uniform(-1, 1, (H, W))))
    off0 = -2000.0 * gain0

    def cal_at(t_s: float):
        return gain0 * (1.0 + 2e-5 * t_s), off0 + 1e-4 * t_s

    def counts(rad: np.ndarray, t_s: float) -> np.ndarray:
        g, o = cal_at(t_s)
        return (rad - o) / g

    events = []
    for t_s in (0.0, 1500.0, 3000.0):
        t1, t2 = 300.0 + t_s / 3000.0, 289.0 - t_s / 6000.0
        r1, r2 = lw_table.radiance(np.array([t1, t2]))
        events.append(event_from_frames(t_s, 0, np.repeat(counts(r1, t_s)[None], 10, 0),
                                        np.repeat(counts(r2, t_s)[None], 10, 0), t1, t2))
    scene = lw_table.radiance(rng.uniform(275.0, 315.0, (H, W)))
    t_scan = 2100.0
    raw = counts(scene, t_scan)
    interp = apply_gain_offset(raw, gain_offset_at(events, t_scan, lw_table, "interpolate"))
    nearest = apply_gain_offset(raw, gain_offset_at(events, t_scan, lw_table, "nearest"))
    np.testing.assert_allclose(interp, scene, rtol=3e-6)
    assert np.max(np.abs(nearest - scene) / scene) > 1e-3


def test_event_from_frames_means():
    rng = np.random.default_rng(4)
    f1 = rng.integers(9000, 9100, (12, 3, 4)).astype(np.uint16)
    f2 = rng.integers(7000, 7100, (10, 3, 4)).astype(np.uint16)
    ev = event_from_frames(12.5, 1, f1, f2, 301.0, 291.0)
    np.testing.assert_allclose(ev.bb1_mean, f1.astype(float).mean(0))
    np.testing.assert_allclose(ev.bb2_mean, f2.astype(float).mean(0))
    assert ev.bb1_mean.dtype == np.float64 and ev.band == 1 and ev.time_s == 12.5


def test_blackbody_temperature_interpolation():
    t_log = np.arange(0.0, 600.0, 60.0)
    temp = 290.0 + t_log / 600.0
    temp[3] = np.nan  # a lost record is skipped
    out = blackbody_temperature_at(t_log, temp, np.array([30.0, 170.0, 530.0]))
    np.testing.assert_allclose(out, 290.0 + np.array([30.0, 170.0, 530.0]) / 600.0)
    with pytest.raises(InvalidInput, match="temperatures.csv"):
        blackbody_temperature_at(t_log, temp, 5000.0, source="temperatures.csv")
    with pytest.raises(InvalidInput):
        blackbody_temperature_at(t_log, np.full(t_log.shape, np.nan), 10.0)
