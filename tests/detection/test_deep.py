"""Deep mines below the per-scan cut: the stack's matched filter finds them, on open ground
and inside a warm patch, and splits nothing else out of a patch."""

from __future__ import annotations

import numpy as np

from clearfast_gis.detection.deep import (
    MIN_EXPLAINED,
    core_contrast,
    core_polarity,
    deep_cores,
    disc_ring_contrast,
    stack_match,
)
from tests.detection.test_compact import (
    PIXEL_M,
    SHAPE,
    TRANSFORM,
    _detect,
    _disc,
    _diurnal_stack,
    _nearest,
)

N_SCANS = 24
RADIUS_M = 0.052
RADIUS_PX = RADIUS_M / PIXEL_M
LAGS_RAD = (0.4, 0.8, 1.2, 1.6)


def _curve(lag_rad: float) -> np.ndarray:
    """A buried object's contrast over the day, peak 1, late by ``lag_rad`` (N_SCANS,)."""
    return np.cos(2 * np.pi * (np.arange(N_SCANS) / N_SCANS - 0.5) - lag_rad)


TEMPLATES = np.array([_curve(lag) for lag in LAGS_RAD])


def _with(stack: np.ndarray, row: float, col: float, curve: np.ndarray,
          diameter_px: float = 5.2) -> np.ndarray:
    """The stack with a disc whose contrast follows ``curve`` (K per scan) added."""
    out = stack.copy()
    out[:, 0] += curve[:, None, None].astype(np.float32) * _disc(row, col, diameter_px)
    return out


def test_disc_ring_contrast_of_a_disc():
    image = np.full(SHAPE, 20.0, np.float32) + 0.5 * _disc(100.0, 100.0, 11.0)
    c = disc_ring_contrast(image, 5.0)
    assert abs(c[100, 100] - 0.5) < 0.02
    assert abs(c[100, 160]) < 1e-5
    image[:, :50] = np.nan  # no data: NaN where the disc or ring is mostly empty
    assert np.isnan(disc_ring_contrast(image, 5.0)[100, 10])


def test_a_deep_mine_in_a_warm_patch_is_found():
    base, times = _diurnal_stack(N_SCANS, [], dome=1.0)
    # 0.08 K, about 2.5 pixel noise sigmas: below the detector's cut in every scan
    stack = _with(base, 118.0, 100.0, 0.08 * _curve(0.8))
    _, plain = _detect(stack, times)
    assert all(np.hypot(f.row - 118.0, f.col - 100.0) > 3.0 for f in plain)
    match = stack_match(stack, TEMPLATES, RADIUS_PX)
    assert match.score[118, 100] > 8.0
    assert match.explained[118, 100] > MIN_EXPLAINED
    assert LAGS_RAD[int(match.depth_index[118, 100])] == 0.8
    patch = np.zeros(SHAPE, np.int32)
    patch[60:140, 60:140] = 1  # the warm patch, set aside as too large
    labels, cores = deep_cores(patch, match, RADIUS_PX, max_diameter_px=25.0,
                               spacing_px=22.0)
    assert len(cores) == 1
    label, row, col = cores[0]
    assert np.hypot(row - 118.0, col - 100.0) <= 1.0
    assert labels[118, 100] == label and labels[100, 100] == 1
    # the core's own scans: warm by day, cool by night, in most scans (against it at most
    # near the curve's zero crossings)
    pol = core_polarity(core_contrast(stack, cores, RADIUS_PX), match.sigma_k)[:, 0]
    sign = np.sign(_curve(0.8))
    assert np.sum(pol == sign) >= N_SCANS // 2 and np.sum(pol * sign < 0) <= 2
    # through the detector on mosaics: a suspect of its own, with supporting scans
    _, feats = detect_with_templates(stack, times)
    f = _nearest(feats, 118.0, 100.0)
    assert np.hypot(f.row - 118.0, f.col - 100.0) < 1.5
    assert f.n_scans >= N_SCANS // 2


def detect_with_templates(stack: np.ndarray, times: np.ndarray):
    from clearfast_gis.detection.voting import detect_on_mosaics

    return detect_on_mosaics(stack, times, TRANSFORM, PIXEL_M, 0.0, d1_m=0.5, d2_m=0.06,
                             epsilon=0.01, level=None, gamma=None, max_anomalies=50,
                             level_fraction=0.25, gamma_fraction=0.25,
                             deep_templates_k=TEMPLATES, deep_radius_m=RADIUS_M)


def test_a_patch_without_a_mine_is_not_split():
    base, times = _diurnal_stack(N_SCANS, [], dome=2.0)
    # a vegetation tuft: 0.6 K cool all day and night, with a small diurnal swing
    stack = _with(base, 80.0, 120.0, -0.6 + 0.1 * _curve(0.0), diameter_px=8.0)
    match = stack_match(stack, TEMPLATES, RADIUS_PX)
    patch = np.zeros(SHAPE, np.int32)
    patch[60:140, 60:140] = 1
    labels, cores = deep_cores(patch, match, RADIUS_PX, max_diameter_px=25.0,
                               spacing_px=22.0)
    assert cores == []
    assert np.array_equal(labels, patch)
    # nor anything added by the detector beyond what it finds without the deep search
    _, plain = _detect(stack, times)
    _, feats = detect_with_templates(stack, times)
    assert len(feats) == len(plain)


def test_a_found_object_is_not_found_twice():
    """A mine the per-scan detector kept (a blob of mine size) gets no deep core."""
    base, times = _diurnal_stack(N_SCANS, [])
    stack = _with(base, 100.0, 100.0, 0.15 * _curve(0.4))
    match = stack_match(stack, TEMPLATES, RADIUS_PX)
    kept = np.zeros(SHAPE, np.int32)
    kept[98:103, 98:103] = 1
    labels, cores = deep_cores(kept, match, RADIUS_PX, max_diameter_px=25.0, spacing_px=22.0)
    assert cores == [] and np.array_equal(labels, kept)
    _, cores = deep_cores(np.zeros(SHAPE, np.int32), match, RADIUS_PX, 25.0, 22.0)
    assert len(cores) == 1


def test_a_curve_seen_over_part_of_the_day_is_no_core():
    """Under a drifting lift a corner of the site is seen by a few scans only: a short piece
    of a diurnal curve is matched by texture as well, so no core is made there."""
    base, _ = _diurnal_stack(N_SCANS, [])
    stack = _with(base, 100.0, 100.0, 0.08 * _curve(0.8))
    seen = stack.copy()
    seen[N_SCANS // 2:, :, 60:140, 60:140] = np.nan  # half the day only
    empty = np.zeros(SHAPE, np.int32)
    assert len(deep_cores(empty, stack_match(stack, TEMPLATES, RADIUS_PX), RADIUS_PX, 25.0,
                          22.0)[1]) == 1
    match = stack_match(seen, TEMPLATES, RADIUS_PX)
    assert match.scans[100, 100] == N_SCANS // 2 and match.score[100, 100] > 6.0
    assert deep_cores(empty, match, RADIUS_PX, 25.0, 22.0)[1] == []


def test_matched_filter_sums_equal_the_numpy_form():
    """``_matchsum.add_scan`` against the sums as numpy wrote them, to the last bit."""
    from clearfast_gis.detection._matchsum import add_scan

    rng = np.random.default_rng(8)
    shape, n_t, n_scans = (23, 31), 5, 7
    templates = rng.normal(size=(n_t, n_scans))
    sums = [np.zeros((n_t, *shape)), np.zeros((n_t, *shape)), np.zeros(shape),
            np.zeros(shape, dtype=np.int32)]
    ref = [a.copy() for a in sums]
    for k in range(n_scans):
        z = (rng.normal(size=shape) * 3.0).astype(np.float32)
        z[rng.random(shape) < 0.2] = np.nan
        z[0, :3] = np.float32(0.0)
        sigma = float(rng.uniform(0.5, 2.0))
        add_scan(z, templates[:, k] / sigma, *sums)
        num, den, energy, scans = ref
        ok = np.isfinite(z)
        zz = np.where(ok, z, 0.0)
        energy += zz.astype(np.float64) ** 2
        scans += ok
        for t in range(n_t):
            u = templates[t, k] / sigma
            num[t] += u * zz
            den[t] += np.where(ok, u * u, 0.0)
    for a, b in zip(sums, ref, strict=True):
        assert a.dtype == b.dtype and a.tobytes() == b.tobytes()
