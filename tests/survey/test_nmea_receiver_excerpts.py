"""Excerpts of real receiver captures kept in the repository (tests/data/nmea, gpsd's logs,
BSD-2-Clause): a MediaTek cold start, a BeiDou receiver, a Quectel L70, a Telit SL869 with
sub-second epochs, a 2 Hz Caterpillar MS352, a B&G chart plotter whose GGA lags its RMC; against
pynmea2. A Meinberg timing receiver that sends only RMC is refused with that cause."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey.nmea import parse_nmea, read_nmea
from clearfast_gis.survey.testing import pynmea2_gga_epochs
from clearfast_gis.timeutil import parse_utc

DATA = Path(__file__).resolve().parents[1] / "data" / "nmea"


def test_mediatek_cold_start_is_dated_by_its_first_valid_rmc():
    """Power-up of a MediaTek MKT-3301: void RMC dated 1980 (2080 by the old reading) before
    the fix; the epochs before midnight belong to the day before the first valid date."""
    log = read_nmea(DATA / "mtk-3301.log")
    assert log.time_s[0] == parse_utc("2008-08-22T23:59:46.005Z")
    assert log.time_s[-1] == parse_utc("2008-08-23T08:14:39Z")
    assert log.no_checksum_lines == (21, 22, 23)  # $POLYN sends none
    assert len(log.void_rmc_lines) == 7 and log.usable.sum() == 4
    ref = pynmea2_gga_epochs(DATA / "mtk-3301.log")
    for k in np.flatnonzero(log.usable):
        (q, lat, lon, _), = ref[round(float(log.time_s[k]) % 86400.0, 3)]
        assert (q, lat, lon) == (log.fix_quality[k], pytest.approx(log.lat_deg[k], abs=1e-12),
                                 pytest.approx(log.lon_deg[k], abs=1e-12))


@pytest.mark.parametrize("name", ["beidou-gb", "quectel-L70", "sl869", "cat-ms352",
                                  "bundg_zeus_9"])
def test_more_receivers_agree_with_pynmea2(name):
    log = read_nmea(DATA / f"{name}.log")
    ref = pynmea2_gga_epochs(DATA / f"{name}.log")
    assert len(log) == len(ref) and np.all(np.diff(log.time_s) > 0)
    for k in np.flatnonzero(log.usable):
        (q, lat, lon, _), = ref[round(float(log.time_s[k]) % 86400.0, 3)]
        assert q == log.fix_quality[k] and abs(lat - log.lat_deg[k]) < 1e-12
        assert abs(lon - log.lon_deg[k]) < 1e-12


def test_sub_second_epochs_and_late_gga_are_dated_by_their_own_rmc():
    sl869 = read_nmea(DATA / "sl869.log")
    assert sl869.no_checksum_lines == (11,)  # $GPTXT without checksum
    k = int(np.flatnonzero(sl869.usable)[1])
    assert sl869.time_s[k] == pytest.approx(parse_utc("2012-11-25T10:21:43.990Z"), abs=1e-6)
    assert sl869.fix_quality[:3].tolist() == [0, 0, 0] and sl869.usable.sum() == 8
    zeus = read_nmea(DATA / "bundg_zeus_9.log")  # GGA 09:47:36 comes before any RMC/ZDA
    assert zeus.time_s[0] == parse_utc("2018-08-20T09:47:36Z")
    assert zeus.alt_m[0] == -4.0 and len(zeus) == 5


def test_rmc_only_receiver_is_refused_with_that_cause():
    """A Meinberg GPS164 timing receiver sends only RMC: no fix quality and no altitude."""
    with pytest.raises(InvalidInput, match=r"no GGA sentence, only RMC \(8 line\(s\), first "
                       r"line 9\).*output GGA"):
        read_nmea(DATA / "meinberg-gps164.log")


def test_comment_lines_quoting_a_sentence_are_not_read():
    """gpsd's captures start with ``#`` lines that may quote a sentence (the SL869's quotes a
    QZGSV); a quoted GGA with a valid checksum must not become an epoch."""
    gga = "$GPGGA,102145.000,3340.8097,S,15117.4692,E,1,05,2.0,077.22,M,22.4,M,,*79"
    text = (DATA / "sl869.log").read_text(encoding="utf-8")
    log = parse_nmea(f"# example: {gga}\n#\t{gga}\n" + text)
    ref = read_nmea(DATA / "sl869.log")
    assert np.array_equal(log.time_s, ref.time_s) and log.n_lines == ref.n_lines
    rmc = "$GPRMC,102145.000,A,3340.8097,S,15117.4692,E,0.3,311.5,251112,0.0,W*6D"
    glued = parse_nmea(f"#{gga}\n{rmc}\n")  # a '#' byte glued to a sentence is binary junk
    assert len(glued) == 1 and glued.prefixed_lines == (1,)
