"""NMEA logs written by real receivers (gpsd's regression captures, BSD-2-Clause, in
``../shared/data/real-field-files/nmea``): positions and times against pynmea2, and every
field habit of real receivers (one GGA per constellation, ``$$``, binary junk, CR-only lines,
missing or failing checksums, void RMC, cold-start dates, leap seconds, fix qualities 6-8)."""

from __future__ import annotations

import math
import re
from datetime import UTC, datetime

import numpy as np
import pynmea2
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey.nmea import (
    gga_sentence,
    nmea_checksum,
    parse_nmea,
    read_nmea,
    rmc_sentence,
)
from clearfast_gis.survey.nmea_lines import century_year, classify_line, tod_field
from clearfast_gis.survey.testing import pynmea2_gga_epochs
from clearfast_gis.timeutil import parse_utc
from tests.conftest import SHARED

NMEA = SHARED / "data" / "real-field-files" / "nmea"
pytestmark = pytest.mark.skipif(not NMEA.is_dir(), reason="real field files not present")

#: receivers whose logs hold GGA epochs (the others are binary or hold no GGA)
WITH_EPOCHS = ["ais-nmea", "bt451", "furuno_gl_ga", "garmin25lp", "nmea-rtk",
               "quectel-l76k-nmea", "sirfstarv-nmea", "skytraq-dgps", "st-teseo-liv3f",
               "st-teseo-liv4f", "telit-he910", "telit-pls83-w", "ublox-zed-f9p-nmea",
               "unicore-um621"]


def _reference(name: str) -> dict[float, list[tuple[int, float, float, int]]]:
    """pynmea2's reading of every GGA with a time: time of day -> [(quality, lat, lon,
    n_sats)]."""
    return pynmea2_gga_epochs(NMEA / f"{name}.log")


@pytest.mark.parametrize("name", WITH_EPOCHS)
def test_positions_and_times_agree_with_pynmea2(name):
    log = read_nmea(NMEA / f"{name}.log", fallback_date_s=None if name != "ais-nmea" else 0.0)
    ref = _reference(name)
    tods = np.round(np.mod(log.time_s, 86400.0), 3)
    # one epoch per receiver time: as many epochs as distinct GGA times
    assert len(log) == len(ref) or name in ("bt451", "telit-he910")  # times go backwards
    for k in np.flatnonzero(log.usable):
        cands = [c for c in ref[float(tods[k])] if c[0] == log.fix_quality[k]]
        assert any(abs(c[1] - log.lat_deg[k]) < 1e-9 and abs(c[2] - log.lon_deg[k]) < 1e-9
                   for c in cands), (name, k)


def test_one_epoch_per_time_keeps_the_best_fix():
    for name in ("sirfstarv-nmea", "telit-pls83-w"):  # $GPGGA + $GNGGA/$GAGGA each epoch
        log = read_nmea(NMEA / f"{name}.log")
        assert log.merged_epochs == len(log) > 0
        assert np.all(np.diff(log.time_s) > 0)
        ref = _reference(name)
        for k in range(len(log)):
            best = max(ref[float(round(log.time_s[k] % 86400.0, 3))], key=lambda c: c[3])
            assert log.n_sats[k] == best[3]  # same quality: the one with more satellites


def test_rmc_dates_agree_with_pynmea2():
    log = read_nmea(NMEA / "nmea-rtk.log")
    day = datetime.fromtimestamp(float(log.time_s[0]), tz=UTC).date()
    dates = set()
    for line in (NMEA / "nmea-rtk.log").read_text(errors="replace").splitlines():
        if line.startswith("$") and line[3:6] == "RMC":
            msg = pynmea2.parse(line.strip(), check=True)
            if msg.status == "A":
                dates.add(msg.datestamp)
    assert dates == {day}


def test_teseo_double_dollar_and_quectel_binary_junk():
    teseo = read_nmea(NMEA / "st-teseo-liv4f.log")
    assert len(teseo) == len(_reference("st-teseo-liv4f")) == 12
    assert teseo.bad_checksum_lines  # the capture's one GSV with a bad checksum
    quectel = read_nmea(NMEA / "quectel-l76k-nmea.log")
    assert len(quectel) == len(_reference("quectel-l76k-nmea")) == 150


def test_cr_only_line_ends_read_like_crlf():
    text = (NMEA / "nmea-rtk.log").read_text(errors="replace")
    crlf = parse_nmea(text)
    cr = parse_nmea(text.replace("\r\n", "\r").replace("\n", "\r"))
    np.testing.assert_array_equal(cr.time_s, crlf.time_s)
    np.testing.assert_array_equal(cr.lat_deg, crlf.lat_deg)
    assert cr.n_lines == crlf.n_lines


def test_missing_and_failing_checksums_name_the_cause():
    with pytest.raises(InvalidInput, match=r"no sentence has a checksum \(13 line\(s\), first "
                       r"line 9\).*\"checksums\": \"optional\""):
        read_nmea(NMEA / "hp58534a.log")
    log = read_nmea(NMEA / "hp58534a.log", checksums="optional")
    ref = pynmea2.parse("$GPGGA,222449,3349.0337,S,01843.9282,E,1,07,02.31,000115.4,M,0033.3,"
                        "M,,")
    assert log.time_s[0] == parse_utc("2010-10-25T22:24:49Z")  # dated by its ZDA
    assert log.lat_deg[0] == pytest.approx(ref.latitude, abs=1e-12)
    assert log.lon_deg[0] == pytest.approx(ref.longitude, abs=1e-12)
    with pytest.raises(InvalidInput, match=r"every GGA sentence fails its checksum \(23 "
                       r"line\(s\), first line 6"):
        read_nmea(NMEA / "firefly-II.log")


def test_binary_captures_are_named_as_such():
    for name in ("navcom", "ublox-zed-f9p-rtk", "trimble-res720", "rtcm3.2"):
        with pytest.raises(InvalidInput, match="binary data"):
            read_nmea(NMEA / f"{name}.log")


def test_cold_start_void_rmc_and_rollover_dates_never_date_epochs():
    path = NMEA / "gp-320fw-2019-04-07-coldboot.log"
    log = read_nmea(path)
    assert len(log.void_rmc_lines) == 15
    # the receiver's own dates: its spoofed 2019-04-07, then its week-0 date 1999-08-22
    assert parse_utc("2019-04-07T00:03:43.03Z") == pytest.approx(log.time_s[0])
    # with the survey's date known, the 1999 dates are refused and the day rolls on
    survey = read_nmea(path, fallback_date_s=parse_utc("2019-04-07T00:00:00Z"))
    assert survey.implausible_date_lines
    assert np.all(np.abs(survey.time_s - parse_utc("2019-04-07T00:04:00Z")) < 3600)


def test_fix_qualities_6_to_8_are_not_fixes():
    # a Garmin GPSmap 76S in simulator mode: quality 8 and void RMC throughout
    with pytest.raises(InvalidInput, match=r"no valid RMC or ZDA.*12 void RMC"):
        read_nmea(NMEA / "GPSmap-76S.log")
    log = read_nmea(NMEA / "GPSmap-76S.log", fallback_date_s=parse_utc("2011-10-24T12:00:00Z"))
    assert set(log.fix_quality.tolist()) == {8}
    assert not log.usable.any() and np.isnan(log.lat_deg).all()


def test_gga_without_time_is_counted_not_junk():
    log = read_nmea(NMEA / "hemi.log")
    assert len(log.untimed_gga_lines) == 194 and len(log) == 21


# -- synthetic cases of the same habits -----------------------------------------------------

T0 = parse_utc("2016-12-31T23:59:58Z")


def test_leap_second_gets_its_own_time():
    lines = []
    for hhmmss in ("235958", "235959", "235960", "000000", "000001"):
        body = f"GPGGA,{hhmmss}.00,3500.0,N,03300.0,E,4,12,0.8,100.0,M,0.0,M,,"
        lines.append(f"${body}*{nmea_checksum(body)}")
    log = parse_nmea("\n".join(lines), fallback_date_s=T0)
    assert np.all(np.diff(log.time_s) > 0)
    assert log.time_s[2] == pytest.approx(parse_utc("2017-01-01T00:00:00Z") - 0.001)
    assert log.time_s[3] == parse_utc("2017-01-01T00:00:00Z")
    with pytest.raises(ValueError):
        tod_field("120060")  # a leap second is 23:59:60


def test_two_digit_years_pivot_on_the_survey_year():
    assert century_year(80, None) == 2080
    assert century_year(80, 2026) == 2080 - 100
    assert century_year(26, 2026) == 2026
    assert century_year(99, 2001) == 1999 and century_year(1, 2099) == 2101
    t = parse_utc("2026-11-15T10:00:00Z")
    void = rmc_sentence(parse_utc("2080-01-05T10:00:00Z"), 35.0, 33.0, valid=False)
    text = "\n".join([gga_sentence(t, 35.0, 33.0, 1.0, 4, 9, 1.0), void,
                      gga_sentence(t + 1, 35.0, 33.0, 1.0, 4, 9, 1.0),
                      rmc_sentence(t + 1, 35.0, 33.0)])
    log = parse_nmea(text, fallback_date_s=t)
    assert log.time_s.tolist() == [t, t + 1] and log.void_rmc_lines == (2,)


@settings(max_examples=150, deadline=None)
@given(st.binary(max_size=40), st.sampled_from(["$", "$$", ""]),
       st.sampled_from(["\r\n", "\n", "\r"]), st.floats(0, 86399.0))
def test_property_junk_prefix_and_line_ends(junk, dollars, eol, tod):
    """Bytes before the sentence (without ``$`` or line ends), a ``$$`` start and any line
    end never change the epoch read."""
    t = parse_utc("2026-11-15T00:00:00Z") + round(tod, 2)
    prefix = junk.decode("latin-1").replace("$", "").replace("\r", "").replace("\n", "")
    if re.match(r"\s*#(\s|$)", prefix):  # a comment line (see nmea_lines), not junk
        prefix = "\x00" + prefix
    gga = gga_sentence(t, -12.5, 44.25, 10.0, 4, 9, 1.0)
    rmc = rmc_sentence(t, -12.5, 44.25)
    text = prefix + dollars + gga[1:] if dollars else prefix + gga
    log = parse_nmea(text + eol + rmc + eol)
    assert len(log) == 1 and log.time_s[0] == pytest.approx(t, abs=1e-6)
    assert log.lat_deg[0] == pytest.approx(-12.5, abs=1e-9)
    assert classify_line(text).prefixed == bool(prefix.strip())


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["GP", "GL", "GA", "GB", "GN"]),
                          st.sampled_from([0, 1, 2, 4, 5, 6]), st.integers(0, 30)),
                min_size=1, max_size=5))
def test_property_one_epoch_per_time_whatever_the_talkers(talkers):
    t = parse_utc("2026-11-15T12:00:00Z")
    lines = [gga_sentence(t, 35.0 + 1e-5 * i, 33.0, 1.0, q, n, 1.0, talker=tk)
             for i, (tk, q, n) in enumerate(talkers)] + [rmc_sentence(t, 35.0, 33.0)]
    log = parse_nmea("\r\n".join(lines))
    assert len(log) == 1 and log.merged_epochs == len(talkers) - 1
    rank = {4: 0, 5: 1, 2: 2, 1: 4}
    best = min(range(len(talkers)), key=lambda i: (rank.get(talkers[i][1], 9), -talkers[i][2]))
    assert log.n_sats[0] == talkers[best][2]
    if talkers[best][1] in (1, 2, 4, 5):
        assert log.lat_deg[0] == pytest.approx(35.0 + 1e-5 * best, abs=1e-9)
    else:
        assert math.isnan(log.lat_deg[0])


@pytest.mark.parametrize("name", ["gp-320fw-2019-04-07-coldboot", "garmin25lp", "telit-he910",
                                  "quectel-l76k-nmea", "st-teseo-liv4f"])
def test_acquire_clock_replaying_real_receivers_never_jumps(name, tmp_path):
    """Every line of a real capture through the acquisition's GNSS logger: the survey clock
    follows the receiver's valid time and never takes a void or cold-start date."""
    import serial

    from clearfast_gis.acquire import GnssLogger
    from clearfast_gis.acquire.clock import GnssClock

    mono = [1000.0]
    clock = GnssClock(mono=lambda: mono[0])
    host = float(read_nmea(NMEA / f"{name}.log").time_s[0]) + 3600.0  # a laptop an hour off
    g = GnssLogger(serial.serial_for_url("loop://", timeout=0.05), tmp_path / "g.nmea",
                   clock=lambda: host, on_time=clock.observe, mono=lambda: mono[0])
    readings = []
    for raw in (NMEA / f"{name}.log").read_bytes().split(b"\n"):
        mono[0] += 0.01
        g.feed(raw + b"\n")
        if clock.ready:
            readings.append(clock.now())
    g.log.close()
    if name.startswith("gp-320fw"):
        # one valid 2019 time before the reboot (no lock), then its week-0 1999 dates: refused
        assert g.n_refused_times > 0
        assert all(r > parse_utc("2019-04-06T00:00:00Z") for r in readings)
        return
    log = read_nmea(NMEA / f"{name}.log")
    valid_days = {float(np.floor(t / 86400.0)) for t in log.time_s}
    assert readings, name
    assert np.all(np.diff(readings) >= 0.0)
    # the clock stays on the receiver's own valid dates (within a day of its epochs)
    assert min(abs(np.floor(readings[-1] / 86400.0) - d) for d in valid_days) <= 1

