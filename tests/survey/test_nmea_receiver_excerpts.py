"""Excerpts of real receiver captures kept in the repository (tests/data/nmea, gpsd's logs,
BSD-2-Clause): a MediaTek cold start, a BeiDou receiver, a Quectel L70; against pynmea2."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from clearfast_gis.survey.nmea import read_nmea
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


@pytest.mark.parametrize("name", ["beidou-gb", "quectel-L70"])
def test_more_receivers_agree_with_pynmea2(name):
    log = read_nmea(DATA / f"{name}.log")
    ref = pynmea2_gga_epochs(DATA / f"{name}.log")
    assert len(log) == len(ref) and np.all(np.diff(log.time_s) > 0)
    for k in np.flatnonzero(log.usable):
        (q, lat, lon, _), = ref[round(float(log.time_s[k]) % 86400.0, 3)]
        assert q == log.fix_quality[k] and abs(lat - log.lat_deg[k]) < 1e-12
        assert abs(lon - log.lon_deg[k]) < 1e-12
