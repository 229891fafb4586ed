"""The detector on a synthetic diurnal stack, features, polarity, class cues."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import ndimage

from clearfast_gis.detection import (
    blob_features,
    detect_anomalies,
    features_table,
    summary_polarity,
)
from clearfast_gis.detection.stretch import stretch_limits, stretch_threshold
from clearfast_gis.solar import local_solar_hour
from clearfast_gis.thermal.solar import solar_position

T0 = 1763164800.0  # 2025-11-15T00:00:00Z
H, W, N = 160, 200, 12
DISCS = [(40.3, 50.7, 5.0), (100.2, 60.1, 6.0), (70.0, 120.4, 5.5), (120.5, 150.2, 5.5)]
SPOT = (20, 170)
PATCH = (slice(100, 150), slice(5, 45))


@pytest.fixture(scope="module")
def diurnal():
    rng = np.random.default_rng(3)
    times = T0 + 3600.0 + np.arange(N) * 7200.0
    hour = local_solar_hour(times, 0.0)
    amp = np.sin(2 * np.pi * (hour - 9.0) / 24.0)  # warm by day, cool by night
    rr, cc = np.mgrid[:H, :W]
    texture = ndimage.gaussian_filter(rng.normal(size=(H, W)), 1.0)
    texture /= texture.std()
    stack = []
    for i in range(N):
        f = 288.0 + 5 * amp[i] + 0.1 * texture * (1 + 0.5 * amp[i])
        for r, c, rad in DISCS:
            f += 1.5 * amp[i] * np.clip(rad + 0.5 - np.hypot(rr - r, cc - c), 0, 1)
        if i == 3:  # a hot spot seen in one scan only
            f += 3.0 * (np.hypot(rr - SPOT[0], cc - SPOT[1]) < 4)
        patch = np.zeros((H, W), bool)
        patch[PATCH] = True
        f += 2.0 * amp[i] * patch  # a warm patch larger than D1
        f += rng.normal(0, 0.05, (H, W))
        stack.append(f.astype(np.float32))
    stack = np.array(stack)
    stack[:, :3, :10] = np.nan  # some no-data
    result = detect_anomalies(stack, d1_px=21, d2_px=4, epsilon=0.01, gamma=6)
    feats = blob_features(result.labels, stack, times, detection=result, longitude_deg=0.0,
                          pixel_size_m=0.03)
    return stack, times, result, feats


def test_all_discs_found_with_position_size_polarity(diurnal):
    _, _, result, feats = diurnal
    best = sorted(feats, key=lambda f: -f.score)[: len(DISCS)]
    for r, c, rad in DISCS:
        match = [f for f in best if abs(f.row - r) < 2 and abs(f.col - c) < 2]
        assert len(match) == 1, (r, c)
        f = match[0]
        assert abs(f.row - r) <= 0.5 and abs(f.col - c) <= 0.5
        assert f.diameter_px == pytest.approx(2 * rad, rel=0.10)
        assert f.polarity == "warm_day_cool_night"
        assert f.circularity > 0.6
        assert f.n_scans >= 10
        assert f.diameter_m == pytest.approx(f.diameter_px * 0.03)
        # contrast series: positive by day, negative by night, ~1.5 K at the peak
        assert f.contrast_k.shape == (N,)
        assert np.max(f.contrast_k) > 1.0 and np.min(f.contrast_k) < -1.0
        np.testing.assert_allclose(f.contrast_k, f.centre_k - f.ring_k)


def test_clutter_rejected(diurnal):
    _, _, result, _ = diurnal
    assert result.labels[SPOT] == 0  # one scan only: fails the vote
    assert not result.mask[110:140, 15:35].any()  # bigger than D1: no top-hat residue
    assert result.votes[SPOT] < result.level


def test_result_shapes_and_nodata(diurnal):
    stack, _, result, _ = diurnal
    assert result.mask_hot.shape == (H, W) and result.labels.dtype == np.int32
    assert result.scan_hot.shape == (N, H, W)
    assert not result.mask[:3, :10].any()
    assert result.level == N / 2
    assert result.covered.dtype == np.int32
    np.testing.assert_array_equal(result.covered, np.isfinite(stack).sum(axis=0))


def test_scan_support_reads_the_packed_maps(diurnal):
    """The per-scan support of a set of pixels, read from the packed L_i, is the OR of the
    unpacked maps over those pixels (columns on and off byte boundaries)."""
    _, _, result, _ = diurnal
    rows, cols = np.nonzero(result.labels == 1)
    assert rows.size and result.scan_hot.any()
    for r, c in ((rows, cols), (rows[:1], cols[:1]), (np.array([5, 9]), np.array([7, 8]))):
        hot, cold = result.support(r, c)
        np.testing.assert_array_equal(hot, result.scan_hot[:, r, c].any(axis=1))
        np.testing.assert_array_equal(cold, result.scan_cold[:, r, c].any(axis=1))
    assert result.support(rows, cols)[0].sum() >= 2


def test_multiband_stack_runs(diurnal):
    stack, _, _, _ = diurnal
    both = np.stack([stack[:4], stack[:4] + 1.0], axis=1)  # (4, 2, H, W)
    res = detect_anomalies(both, 21, 4)
    assert res.scan_hot.shape == (4, H, W) and res.level == 4.0
    feats = blob_features(res.labels, both)
    assert feats and feats[0].contrast_k.shape == (4, 2)


def test_features_table_and_transform(diurnal):
    from affine import Affine

    stack, times, result, _ = diurnal
    tr = Affine(0.05, 0, 500000.0, 0, -0.05, 4000000.0)
    feats = blob_features(result.labels, stack, times, transform=tr, detection=result)
    f = feats[0]
    assert f.x == pytest.approx(500000.0 + (f.col + 0.5) * 0.05)
    assert f.y == pytest.approx(4000000.0 - (f.row + 0.5) * 0.05)
    assert f.area_m2 == pytest.approx(f.area_px * 0.0025)
    table = features_table(feats)
    assert len(table["id"]) == len(feats) and table["score"].dtype.kind == "f"


def test_stretch_limits_and_threshold():
    img = np.arange(100, dtype=np.float32)
    lo, hi = stretch_limits(img, 0.1)
    assert (lo, hi) == (9.0, 89.0)
    g = stretch_threshold(img, 0.1)
    assert g.sum() == np.sum(img > 49.0)
    assert not stretch_threshold(np.zeros((4, 4)), 0.01).any()


@settings(max_examples=200, deadline=None)
@given(st.lists(st.one_of(st.floats(-1e6, 1e6, width=32), st.just(float("nan")),
                          st.sampled_from([float("inf"), float("-inf"), 0.0, 1.0])),
                min_size=1, max_size=300),
       st.floats(0.0, 0.49), st.sampled_from([np.float32, np.float64, np.int32]))
def test_stretch_limits_equal_numpy_inverted_cdf(values, epsilon, dtype):
    """Golden: the rank selection gives numpy's inverted-CDF quantiles of the finite values
    (NaN and +-inf ignored), for any dtype, ties and sizes."""
    img = np.array(values, dtype=np.float64)
    if dtype is np.int32:
        img = np.nan_to_num(img, nan=0.0, posinf=7.0, neginf=-7.0).astype(np.int32)
    else:
        img = img.astype(dtype)
    finite = np.asarray(img, dtype=np.float64)
    finite = finite[np.isfinite(finite)]
    lo, hi = stretch_limits(img, epsilon)
    if finite.size == 0:
        assert np.isnan(lo) and np.isnan(hi)
        return
    want = np.quantile(finite, [epsilon, 1.0 - epsilon], method="inverted_cdf")
    assert (lo, hi) == (float(want[0]), float(want[1]))


def test_solar_time_and_elevation():
    # solar noon at Greenwich on 15 November: ~11:45 UTC (equation of time +15.5 min)
    t = T0 + 12 * 3600.0
    assert local_solar_hour(t, 0.0) == pytest.approx(12.0 + 15.4 / 60, abs=0.05)
    assert local_solar_hour(t, 30.0) == pytest.approx(14.0 + 15.4 / 60, abs=0.05)
    # noon elevation at 35 N in mid-November: 90 - 35 - 18.5 = 36.5 deg
    noon = T0 + (12 - 15.4 / 60 - 33.36 / 15) * 3600.0
    assert solar_position(35.0, 33.36, noon)[0] == pytest.approx(36.5, abs=0.5)
    assert solar_position(35.0, 33.36, T0)[0] < 0  # 02:13 local: night
    # continuous over UTC midnight (up to the day-to-day change of the equation of time)
    hours = local_solar_hour(T0 + np.array([-60.0, 60.0]), 0.0)
    assert hours[1] - hours[0] == pytest.approx(2 / 60, abs=0.01)
    assert np.all((hours >= 0) & (hours < 24))


def test_summary_polarity_rules():
    times = T0 + 3600.0 + np.arange(12) * 7200.0  # 01:00 ... 23:00 UTC at lon 0
    day_warm = np.array([-1, -1, -1, -1, 1, 1, 1, 1, 1, 1, -1, -1])
    assert summary_polarity(day_warm, times, 0.0) == "warm_day_cool_night"
    assert summary_polarity(day_warm) == "mixed"
    assert summary_polarity(np.ones(12), times, 0.0) == "warm"
    assert summary_polarity(-np.ones(12), times, 0.0) == "cool"
    assert summary_polarity(np.zeros(12)) == "none"


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 4), st.integers(1, 40), st.integers(0, 2**32 - 1))
def test_packed_masks_round_trip(h, w, seed):
    from clearfast_gis.detection.detector import unpack_bits

    mask = np.random.default_rng(seed).random((h, w)) < 0.5
    out = unpack_bits(np.packbits(mask, axis=-1), w)
    assert out.dtype == bool and out.shape == (h, w)
    np.testing.assert_array_equal(out, mask)


def test_count_finite_equals_numpy(diurnal):
    from clearfast_gis.detection.detector import count_finite

    stack = diurnal[0].copy()
    stack[2:5, 10:40, 20:90] = np.nan
    np.testing.assert_array_equal(count_finite(stack), np.isfinite(stack).sum(axis=0))
    np.testing.assert_array_equal(count_finite(iter(stack)), np.isfinite(stack).sum(axis=0))


def test_detector_memory_per_image_is_a_fraction_of_a_byte_per_pixel(diurnal, monkeypatch):
    """Beyond its input, the detector keeps the thresholded hats G_i one bit a pixel and the
    per-scan maps L_i (hot, cold): with 4 bands, 2 / 4 + 2 / 8 bytes a pixel per image (the
    boolean stacks of G_i and O_i kept before: 2.5 bytes a pixel per image). Peak measured by
    tracemalloc (numpy reports its buffers), 8 against 24 images."""
    import tracemalloc

    stack = diurnal[0]
    # one thread: scans filtered side by side would each hold the order statistics' fixed
    # scratch (radix histograms, about 2.5 MB whatever the image) at moments that vary
    monkeypatch.setenv("CLEARFAST_THREADS", "1")

    def peak(n: int) -> int:
        multi = np.repeat(stack[:n, None], 4, axis=1)  # (n, 4, H, W)
        tracemalloc.start()
        tracemalloc.reset_peak()
        base = tracemalloc.get_traced_memory()[0]
        detect_anomalies(multi, d1_px=25, d2_px=5)
        used = tracemalloc.get_traced_memory()[1] - base
        tracemalloc.stop()
        return used

    per_image = (peak(6) - peak(2)) / (4 * 4 * H * W)
    assert per_image < 1.0, per_image


def _weak_mine_among_strong_objects(seed: int) -> tuple[np.ndarray, tuple[int, int]]:
    """Six images, 2 cm cells: 0.04 K clutter, four 40 cm 'markers' at +6 K (2.6 % of the
    cells: they fill the top percentile) and a 10 cm disc at +0.3 K (7.5 sigma), the weak
    mine."""
    rng = np.random.default_rng(seed)
    yy, xx = np.mgrid[0:200, 0:240]
    strong = np.zeros(yy.shape, bool)
    for y0, x0 in ((50, 50), (150, 190), (50, 190), (150, 50)):
        strong |= (yy - y0) ** 2 + (xx - x0) ** 2 <= 10 ** 2
    weak = (yy - 100) ** 2 + (xx - 120) ** 2 <= 2.6 ** 2
    clutter = ndimage.gaussian_filter(rng.standard_normal((6, 200, 240)), (0, 1, 1))
    clutter *= 0.04 / clutter.std()
    stack = (20.0 + clutter + 6.0 * strong + 0.3 * weak).astype(np.float32)
    return stack, (100, 120)


def test_ceiling_caps_the_stretch_cut():
    img = np.zeros((50, 50), np.float32)
    img[:10, :10] = 6.0  # 4 % of the cells far above the rest: the cut is 3 K
    img[20:23, 20:23] = 0.5
    plain = stretch_threshold(img, 0.01)
    capped = stretch_threshold(img, 0.01, ceiling=0.2)
    assert not plain[21, 21] and capped[21, 21]
    assert plain[:10, :10].all() and capped[:10, :10].all() and capped.sum() == 100 + 9
    # a ceiling above the stretch's own cut changes nothing
    assert np.array_equal(stretch_threshold(img, 0.01, ceiling=100.0), plain)


def test_weak_mine_among_strong_objects_needs_the_noise_cut():
    """The stretch's cut (half the top percentile, set by the strong objects) lies above a
    0.3 K mine that stands 7 sigma above the clutter: capped at 4 sigma it is voted for."""
    from clearfast_gis.detection.clutter import image_clutter_k

    stack, (r, c) = _weak_mine_among_strong_objects(0)
    plain = detect_anomalies(stack, 25, 3, level=2)
    assert plain.labels[r, c] == 0
    sigma = np.array([image_clutter_k(img, 0.02) for img in stack])
    assert sigma == pytest.approx(0.04, rel=0.25)
    capped = detect_anomalies(stack, 25, 3, level=2, ceiling=4.0 * sigma)
    assert capped.labels[r, c] > 0 and capped.votes[r, c] >= 5
    # the strong objects stay found, and texture does not gather the votes of a mine
    assert capped.labels[50, 50] > 0 and capped.labels[150, 190] > 0
    assert capped.n_anomalies <= 6


def test_no_blob_no_features_and_no_pass_over_the_scans():
    class Unread:
        n_scans, n_bands, shape = 3, 1, (8, 9)

        def scan(self, i):
            raise AssertionError("no scan should be read without a blob")

    assert blob_features(np.zeros((8, 9), dtype=np.int32), Unread()) == []
