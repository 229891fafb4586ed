"""UTM zones, WGS84 <-> UTM and the platform track from GNSS epochs."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from pyproj.aoi import AreaOfInterest
from pyproj.database import query_utm_crs_info

from clearfast_gis.errors import InvalidInput
from clearfast_gis.geometry import crs_to_lonlat, lonlat_to_crs, platform_track, utm_epsg_for
from clearfast_gis.geometry.gnss import survey_epsg


def snyder_utm(lat_deg: float, lon_deg: float, zone: int) -> tuple[float, float]:
    """Transverse Mercator on WGS84 by Snyder's series (USGS PP 1395, eqs. 8-9 to 8-10)."""
    a, f, k0 = 6378137.0, 1 / 298.257223563, 0.9996
    e2 = f * (2 - f)
    ep2 = e2 / (1 - e2)
    phi, lam = math.radians(lat_deg), math.radians(lon_deg)
    lam0 = math.radians(zone * 6 - 183)
    n = a / math.sqrt(1 - e2 * math.sin(phi) ** 2)
    t = math.tan(phi) ** 2
    c = ep2 * math.cos(phi) ** 2
    aa = (lam - lam0) * math.cos(phi)
    m = a * ((1 - e2 / 4 - 3 * e2**2 / 64 - 5 * e2**3 / 256) * phi
             - (3 * e2 / 8 + 3 * e2**2 / 32 + 45 * e2**3 / 1024) * math.sin(2 * phi)
             + (15 * e2**2 / 256 + 45 * e2**3 / 1024) * math.sin(4 * phi)
             - (35 * e2**3 / 3072) * math.sin(6 * phi))
    x = k0 * n * (aa + (1 - t + c) * aa**3 / 6
                  + (5 - 18 * t + t * t + 72 * c - 58 * ep2) * aa**5 / 120) + 500000.0
    y = k0 * (m + n * math.tan(phi) * (aa * aa / 2 + (5 - t + 9 * c + 4 * c * c) * aa**4 / 24
                                       + (61 - 58 * t + t * t + 600 * c - 330 * ep2)
                                       * aa**6 / 720))
    if lat_deg < 0:
        y += 10_000_000.0
    return x, y


@pytest.mark.parametrize("lat,lon,epsg", [
    (35.17, 33.36, 32636),   # Cyprus, the trial site
    (50.85, 4.35, 32631),    # Brussels
    (-33.92, 18.42, 32734),  # Cape Town
    (60.0, 5.0, 32632),      # Norway exception (would be 31)
    (78.2, 15.6, 32633),     # Svalbard
    (78.2, 8.0, 32631),
    (78.2, 25.0, 32635),
    (78.2, 40.0, 32637),
    (44.8, 20.45, 32634),    # Belgrade
    (0.0, -179.9, 32601),
    (-1.0, 179.9, 32760),
])
def test_utm_epsg_known(lat, lon, epsg):
    assert utm_epsg_for(lat, lon) == epsg


@given(st.floats(-79.9, 83.9), st.floats(-179.99, 179.99))
@settings(max_examples=15, deadline=None)  # each database query takes ~0.2 s
def test_utm_epsg_matches_pyproj_database(lat, lon):
    assume(abs(lon / 6 - round(lon / 6)) > 1e-3 and abs(lat) > 1e-3)  # not on a zone edge
    assume(not (56 <= lat < 64 and 0 <= lon < 12) and not (lat >= 72 and 0 <= lon < 42))
    info = query_utm_crs_info(datum_name="WGS 84",
                              area_of_interest=AreaOfInterest(lon, lat, lon, lat))
    codes = {int(i.code) for i in info}
    assert utm_epsg_for(lat, lon) in codes


def test_utm_out_of_range():
    with pytest.raises(ValueError):
        utm_epsg_for(85.0, 0.0)


@pytest.mark.parametrize("lat,lon", [(35.17, 33.36), (35.5, 31.2), (-33.92, 18.42),
                                     (50.85, 4.35)])
def test_lonlat_to_utm_independent(lat, lon):
    epsg = utm_epsg_for(lat, lon)
    x, y = lonlat_to_crs(lon, lat, epsg)
    xs, ys = snyder_utm(lat, lon, epsg % 100)
    assert float(x) == pytest.approx(xs, abs=0.01)
    assert float(y) == pytest.approx(ys, abs=0.01)
    lon2, lat2 = crs_to_lonlat(x, y, epsg)
    assert (float(lon2), float(lat2)) == pytest.approx((lon, lat), abs=1e-10)


def test_trial_site_value():
    # 33.36 E, 35.17 N in UTM 36N: E 532 782.58, N 3 891 955.01 (Snyder's series, above)
    x, y = lonlat_to_crs(33.36, 35.17, 32636)
    assert (float(x), float(y)) == pytest.approx((532782.58, 3891955.01), abs=0.01)


def _log(t, lat, lon, alt, q):
    return SimpleNamespace(time_s=np.asarray(t, float), lat_deg=np.asarray(lat, float),
                           lon_deg=np.asarray(lon, float), alt_m=np.asarray(alt, float),
                           fix_quality=np.asarray(q))


def test_track_interpolates_and_skips_no_fix():
    t = np.arange(0.0, 10.0)
    lat = 35.17 + 1e-6 * t
    lon = np.full(10, 33.36)
    alt = 172.0 + 0.1 * t
    q = np.array([4, 4, 0, 4, 4, 5, 4, 4, 4, 4])
    lat[2] = 0.0  # garbage in an epoch without fix must be ignored
    track = platform_track(_log(t, lat, lon, alt, q), 32636, 160.0)
    x, y = lonlat_to_crs(lon, lat, 32636)
    p = track.at([1.0, 2.0, 2.5, 9.0])
    assert p[0] == pytest.approx([x[1], y[1], 12.1])
    assert p[1] == pytest.approx([(x[1] + x[3]) / 2, (y[1] + y[3]) / 2, 12.2])
    assert p[2, 2] == pytest.approx(12.25)
    # one time at a time (a frame's pose) as in one call: the usable epochs are selected once
    one = np.concatenate([track.at([t1]) for t1 in (1.0, 2.0, 2.5, 9.0)])
    np.testing.assert_array_equal(one, p)
    assert track.usable_time_s.tolist() == [0, 1, 3, 4, 5, 6, 7, 8, 9]
    assert track.fix_quality_at([2.1, 5.2, 5.6]).tolist() == [0, 5, 4]
    assert track.degraded_at([2.0, 5.0, 6.0]).tolist() == [True, True, False]


def test_track_gaps_and_far_times():
    t = np.array([0.0, 1.0, 2.0, 30.0, 31.0])
    track = platform_track(_log(t, [35.17] * 5, [33.36] * 5, [170.0] * 5, [4, 4, 4, 4, 4]),
                           32636, 160.0, max_gap_s=5.0)
    assert track.gaps() == [(2.0, 30.0)]
    assert track.covered([1.5, 6.9, 7.1, 25.0, 36.0, 36.5]).tolist() == \
        [True, True, False, True, True, False]
    with pytest.raises(InvalidInput) as exc:
        track.at([1.0, 15.0])
    assert exc.value.one_line().startswith("gnss.nmea: fix_quality: 1 time(s) farther than 5 s")
    p = track.at([1.0, 15.0], strict=False)
    assert np.isfinite(p[0]).all() and np.isnan(p[1]).all()


def test_track_without_fix_is_invalid():
    with pytest.raises(InvalidInput, match="no usable fix"):
        platform_track(_log([0, 1], [np.nan] * 2, [np.nan] * 2, [np.nan] * 2, [0, 0]),
                       32636, 0.0)


def _survey(crs=None):
    manifest = {} if crs is None else {"crs": crs}
    return SimpleNamespace(manifest=manifest, label=lambda key: f"survey/{key}.nmea")


def test_survey_epsg_stated_crs_wins_over_the_fixes():
    gnss = SimpleNamespace(usable=np.array([True]), lat_deg=np.array([50.85]),
                           lon_deg=np.array([4.35]))
    assert survey_epsg(_survey({"epsg": 32636}), gnss) == 32636


def test_survey_epsg_from_the_first_usable_fix():
    gnss = SimpleNamespace(usable=np.array([False, True, True]),
                           lat_deg=np.array([-33.92, 35.17, 50.85]),
                           lon_deg=np.array([18.42, 33.36, 4.35]))
    assert survey_epsg(_survey(), gnss) == 32636  # Cyprus, not Cape Town's nor Brussels'


def test_survey_epsg_without_a_usable_fix_names_the_log():
    gnss = SimpleNamespace(usable=np.array([False]), lat_deg=np.array([35.17]),
                           lon_deg=np.array([33.36]))
    with pytest.raises(InvalidInput, match="no GNSS fix to choose the UTM zone") as exc:
        survey_epsg(_survey(), gnss)
    assert "survey/gnss.nmea" in exc.value.one_line()


@given(st.lists(st.tuples(st.floats(-0.001, 0.001), st.floats(-0.001, 0.001),
                          st.floats(0.0, 30.0), st.sampled_from([0, 1, 2, 4, 5])),
                min_size=2, max_size=30))
@settings(max_examples=40, deadline=None)
def test_nmea_text_to_track(epochs):
    """GGA/RMC text written and parsed by the survey package gives the same UTM positions."""
    nmea = pytest.importorskip("clearfast_gis.survey.nmea")
    t0 = 1_763_164_800.0  # 2025-11-15T00:00:00Z
    lines, truth = [], []
    for i, (dlat, dlon, h, q) in enumerate(epochs):
        lat, lon = 35.17 + dlat, 33.36 + dlon
        tt = t0 + i
        lines.append(nmea.gga_sentence(tt, lat if q else math.nan, lon if q else math.nan,
                                       160.0 + h if q else math.nan, q, 12, 0.8))
        lines.append(nmea.rmc_sentence(tt, lat, lon))
        truth.append((tt, lat, lon, h, q))
    assume(any(e[4] > 0 for e in truth))
    log = nmea.parse_nmea("\n".join(lines) + "\n")
    track = platform_track(log, 32636, 160.0, max_gap_s=1e9)
    tt, lat, lon, h, q = (np.array(c) for c in zip(*truth, strict=True))
    np.testing.assert_array_equal(track.fix_quality, q)
    x, y = lonlat_to_crs(lon, lat, 32636)
    p = track.at(tt[q > 0])
    # GGA carries 1e-7 arc-minutes (~0.2 mm) and millimetres of altitude
    np.testing.assert_allclose(p[:, 0], x[q > 0], atol=2e-3)
    np.testing.assert_allclose(p[:, 1], y[q > 0], atol=2e-3)
    np.testing.assert_allclose(p[:, 2], h[q > 0], atol=1e-3)
