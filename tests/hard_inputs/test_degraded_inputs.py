"""Inputs ``clearfast process`` works through: the survey is processed (exit 0), and the
problem is reported as one line in ``products.json`` (``warnings``) and in the report."""

from __future__ import annotations

import html

from clearfast_gis.survey.nmea import gga_sentence, rmc_sentence
from clearfast_gis.timeutil import parse_utc

from .conftest import assert_nothing_half_written, products_warnings

T0 = parse_utc("2026-11-15T00:00:00Z")


def _processed_with(process, survey, products, expected: str) -> list[str]:
    code, out, err = process(survey, products)
    assert code == 0, out + err
    assert "Traceback" not in out + err
    warnings = products_warnings(products)
    hits = [w for w in warnings if w.startswith(expected)]
    assert hits, warnings
    assert html.escape(hits[0]) in (products / "report.html").read_text()
    assert_nothing_half_written(products)
    return warnings


def test_missing_frames_are_processed_and_reported(survey, tmp_path, process):
    lines = (survey / "frames.csv").read_text().splitlines()
    del lines[2]  # scan 0, position 1
    (survey / "frames.csv").write_text("\n".join(lines) + "\n")
    _processed_with(process, survey, tmp_path / "out",
                    "frames.csv: 1 of 6 frame(s) missing (scans 0 incomplete)")
    assert len(list((tmp_path / "out" / "mosaics").glob("scan_*.tif"))) == 2


def _nmea(path, quality: int, keep=lambda k: True, corrupt=()) -> None:
    lines = []
    for k in range(0, 3001, 10):
        if keep(k):
            lines += [gga_sentence(T0 + k, 35.17, 33.36, 170.0, quality, 12, 0.8),
                      rmc_sentence(T0 + k, 35.17, 33.36, valid=True)]
    for i in corrupt:  # a flipped checksum digit
        lines[i] = lines[i][:-1] + ("0" if lines[i][-1] != "0" else "1")
    path.write_text("\r\n".join(lines) + "\r\n")


def test_nmea_bad_checksums_are_skipped_and_reported(survey, tmp_path, process):
    _nmea(survey / "gnss.nmea", 4, corrupt=(10, 11, 40))
    _processed_with(process, survey, tmp_path / "out",
                    "gnss.nmea: line 11: 3 line(s) with a wrong checksum skipped")


def test_nmea_without_rtk_fix_is_processed_as_degraded(survey, tmp_path, process):
    _nmea(survey / "gnss.nmea", 2)
    warnings = _processed_with(process, survey, tmp_path / "out",
                               "gnss.nmea: GGA: no RTK-fixed epoch (fix quality 4)")
    assert "RTK-DGPS not fixed (quality != 4) for 100.0 % of the frames: positions there are " \
           "degraded" in warnings
    import json

    fixq = json.loads((tmp_path / "out" / "products.json").read_text())["fix_quality"]
    assert fixq["degraded"] and fixq["rtk_fixed_share"] == 0.0


def test_nmea_time_gap_is_bridged_and_reported(survey, tmp_path, process):
    _nmea(survey / "gnss.nmea", 4, keep=lambda k: not 600 <= k < 1200)
    _processed_with(process, survey, tmp_path / "out",
                    "gnss.nmea: time: 1 gap(s) longer than 10 s, longest 610 s at "
                    "2026-11-15T00:09:50Z")


def test_weather_gap_is_bridged_and_reported(survey, tmp_path, process):
    p = survey / "weather.dat"
    lines = p.read_text().splitlines()
    p.write_text("\n".join(lines[:4 + 20] + lines[4 + 26:]) + "\n")  # 00:20 to 00:25 missing
    _processed_with(process, survey, tmp_path / "out",
                    "weather.dat: TIMESTAMP: 1 gap(s) longer than 180 s, longest 420 s at "
                    "2026-11-15T00:19:00Z")
