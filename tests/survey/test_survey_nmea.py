"""NMEA: checksums against real receiver sentences, builders, dating, fuzzing."""

from __future__ import annotations

import math

import numpy as np
import pynmea2
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey.nmea import (
    GnssLog,
    gga_sentence,
    nmea_checksum,
    parse_nmea,
    read_nmea,
    rmc_sentence,
    write_nmea,
)
from clearfast_gis.timeutil import parse_utc

REAL = [
    "$GPGGA,092750.000,5321.6802,N,00630.3372,W,1,8,1.03,61.7,M,55.2,M,,*76",
    "$GPGSA,A,3,10,07,05,02,29,04,08,13,,,,,1.72,1.03,1.38*0A",
    "$GPRMC,092750.000,A,5321.6802,N,00630.3372,W,0.02,31.66,280511,,,A*43",
    "$GPGGA,092751.000,5321.6802,N,00630.3371,W,1,8,1.03,61.7,M,55.3,M,,*75",
    "$GPRMC,092751.000,A,5321.6802,N,00630.3371,W,0.06,31.66,280511,,,A*45",
]


@pytest.mark.parametrize("sentence", REAL)
def test_checksum_matches_real_sentences(sentence):
    body, cs = sentence[1:].split("*")
    assert nmea_checksum(body) == cs


def test_real_log_values():
    log = parse_nmea("\n".join(REAL))
    assert len(log) == 2
    assert log.time_s[0] == parse_utc("2011-05-28T09:27:50Z")
    assert log.time_s[1] - log.time_s[0] == 1.0
    assert log.lat_deg[0] == pytest.approx(53 + 21.6802 / 60, abs=1e-12)
    assert log.lon_deg[0] == pytest.approx(-(6 + 30.3372 / 60), abs=1e-12)
    assert log.alt_m.tolist() == [61.7, 61.7]
    assert log.fix_quality.tolist() == [1, 1]
    assert log.n_sats.tolist() == [8, 8]
    assert log.hdop[0] == 1.03
    assert log.unparseable_lines == ()  # GSA is valid NMEA, ignored silently


def test_builders_parse_with_pynmea2_and_round_trip():
    t = parse_utc("2026-11-15T23:59:59.250Z")
    gga = gga_sentence(t, -35.123456789, -33.987654321, 160.123, 4, 14, 0.7)
    rmc = rmc_sentence(t, -35.123456789, -33.987654321)
    g = pynmea2.parse(gga, check=True)
    r = pynmea2.parse(rmc, check=True)
    assert g.gps_qual == 4 and int(g.num_sats) == 14
    assert r.datestamp.isoformat() == "2026-11-15"
    log = parse_nmea(gga + "\r\n" + rmc + "\r\n")
    assert log.time_s[0] == pytest.approx(t, abs=1e-6)
    assert log.lat_deg[0] == pytest.approx(-35.123456789, abs=2e-9)  # 0.2 mm
    assert log.lon_deg[0] == pytest.approx(-33.987654321, abs=2e-9)
    assert log.alt_m[0] == pytest.approx(160.123)


def test_write_read_round_trip_across_midnight(tmp_path):
    t = parse_utc("2026-11-15T23:59:50Z") + np.arange(20.0)
    q = np.array([4] * 10 + [5] * 5 + [0] * 5, dtype=np.int8)
    lat = np.where(q > 0, 35.17, np.nan)
    log = GnssLog(t, lat, lat * 0 + 33.36, lat * 0 + 170.5, q, np.full(20, 12, np.int16),
                  np.full(20, 0.8))
    write_nmea(tmp_path / "g.nmea", log)
    back = read_nmea(tmp_path / "g.nmea")
    np.testing.assert_allclose(back.time_s, t, atol=1e-6)
    np.testing.assert_array_equal(back.fix_quality, q)
    assert np.isnan(back.lat_deg[15:]).all() and np.isfinite(back.lat_deg[:15]).all()
    assert back.fix_counts() == {0: 5, 4: 10, 5: 5}


def test_dates_without_rmc_use_fallback_and_roll_over():
    t0 = parse_utc("2026-11-15T23:59:58Z")
    text = "\n".join(gga_sentence(t0 + k, 35.0, 33.0, 1.0, 4, 9, 1.0) for k in range(4))
    log = parse_nmea(text, fallback_date_s=parse_utc("2026-11-15T12:00:00Z"))
    np.testing.assert_allclose(log.time_s, t0 + np.arange(4.0))
    with pytest.raises(InvalidInput, match="no valid RMC"):
        parse_nmea(text)


def test_bad_checksum_and_junk_are_counted_and_skipped():
    good = [gga_sentence(1.8e9 + k, 35.0, 33.0, 1.0, 4, 9, 1.0) for k in range(3)]
    bad = good[1][:-2] + ("00" if good[1][-2:] != "00" else "11")
    text = "\n".join([good[0], bad, "garbage line", "$GPGGA,broken", good[2],
                      rmc_sentence(1.8e9 + 2, 35.0, 33.0)])
    log = parse_nmea(text)
    assert len(log) == 2
    assert log.bad_checksum_lines == (2,)
    assert log.no_checksum_lines == (4,)  # a missing checksum is reported as such
    assert log.unparseable_lines == (3,)


def test_no_gga_is_invalid(tmp_path):
    with pytest.raises(InvalidInput, match="no GGA"):
        parse_nmea(REAL[1])
    with pytest.raises(InvalidInput, match="file not found"):
        read_nmea(tmp_path / "missing.nmea")


VALID_LOG = "\r\n".join(s for k in range(5) for s in (
    gga_sentence(1.8e9 + k, 35.17, 33.36, 170.0, 4, 12, 0.7),
    rmc_sentence(1.8e9 + k, 35.17, 33.36)))

FUZZ = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _clean_or_invalid(fn, *args):
    try:
        return fn(*args)
    except InvalidInput:
        return None


@FUZZ
@given(st.text(alphabet=st.characters(codec="utf-8"), max_size=400))
def test_fuzz_random_text(text):
    log = _clean_or_invalid(parse_nmea, text)
    if log is not None:
        assert np.all(np.isin(log.fix_quality, range(10)))


@FUZZ
@given(st.lists(st.tuples(st.integers(0, len(VALID_LOG) - 1),
                          st.sampled_from(list("0123456789,.*$NSEWAM-\n ")) | st.just("")),
                min_size=1, max_size=12))
def test_fuzz_mutated_valid_log(edits):
    chars = list(VALID_LOG)
    for pos, ch in edits:
        chars[pos % len(chars)] = ch
    log = _clean_or_invalid(parse_nmea, "".join(chars))
    if log is not None:
        ok = np.isfinite(log.lat_deg)
        assert np.all(np.abs(log.lat_deg[ok]) <= 90) and np.all(np.isfinite(log.time_s))


@FUZZ
@given(st.floats(-89.999, 89.999), st.floats(-179.999, 179.999),
       st.floats(0, 86399.998), st.integers(0, 9))
def test_property_gga_round_trip(lat, lon, tod, q):
    t = parse_utc("2026-11-15T00:00:00Z") + round(tod, 3)
    log = parse_nmea(gga_sentence(t, lat, lon, 100.0, q, 10, 1.0) + "\n" +
                     rmc_sentence(t, lat, lon))
    assert log.time_s[0] == pytest.approx(t, abs=1e-6)
    assert log.fix_quality[0] == q
    if q not in (1, 2, 3, 4, 5):  # 6-8 dead reckoning, manual, simulator: not fixes
        assert math.isnan(log.lat_deg[0]) and not log.usable[0]
    else:
        assert log.lat_deg[0] == pytest.approx(lat, abs=2e-9)
        assert log.lon_deg[0] == pytest.approx(lon, abs=2e-9)


@FUZZ
@given(st.floats(-89.99, 89.99), st.floats(-179.99, 179.99), st.floats(0, 86399.9),
       st.integers(1, 5), st.integers(0, 40), st.floats(-100, 9000))
def test_field_parsing_agrees_with_pynmea2(lat, lon, tod, q, ns, alt):
    t = parse_utc("2026-11-15T00:00:00Z") + round(tod, 3)
    gga = gga_sentence(t, lat, lon, alt, q, ns, 1.25)
    ref = pynmea2.parse(gga, check=True)
    log = parse_nmea(gga + "\n" + rmc_sentence(t, lat, lon))
    assert log.lat_deg[0] == pytest.approx(ref.latitude, abs=1e-12)
    assert log.lon_deg[0] == pytest.approx(ref.longitude, abs=1e-12)
    assert log.alt_m[0] == pytest.approx(float(ref.altitude), abs=1e-9)
    ts = ref.timestamp
    ref_tod = ts.hour * 3600 + ts.minute * 60 + ts.second + ts.microsecond * 1e-6
    assert log.time_s[0] % 86400.0 == pytest.approx(ref_tod, abs=1e-6)
    assert (int(log.fix_quality[0]), int(log.n_sats[0])) == (ref.gps_qual, int(ref.num_sats))
