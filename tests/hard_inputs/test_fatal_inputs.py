"""Inputs ``clearfast process`` cannot work with: one line naming the file, exit 1, nothing
half-written. The survey checks are ``clearfast validate``'s (the same line)."""

from __future__ import annotations

import json

import numpy as np

from clearfast_gis.survey.nmea import gga_sentence, rmc_sentence
from clearfast_gis.survey.tiff import write_tiff_stack
from clearfast_gis.timeutil import parse_utc

from .conftest import assert_fatal, assert_nothing_half_written


def test_truncated_tiff(survey, tmp_path, process):
    p = survey / "frames/scan_001_b0.tif"
    p.write_bytes(p.read_bytes()[:600])
    assert_fatal(process(survey, tmp_path / "out"),
                 "frames/scan_001_b0.tif: corrupt or truncated TIFF")
    assert not (tmp_path / "out").exists()


def test_corrupt_tiff(survey, tmp_path, process):
    p = survey / "frames/scan_000_b0.tif"
    data = bytearray(p.read_bytes())
    data[4:8] = b"\xff\xff\xff\x7f"  # first IFD offset far beyond the end of the file
    p.write_bytes(bytes(data))
    assert_fatal(process(survey, tmp_path / "out"), "frames/scan_000_b0.tif: ")
    assert not (tmp_path / "out").exists()


def test_survey_json_path_escaping_the_folder(survey, tmp_path, process):
    doc = json.loads((survey / "survey.json").read_text())
    doc["files"]["weather"] = "../../etc/weather.dat"
    (survey / "survey.json").write_text(json.dumps(doc))
    assert_fatal(process(survey, tmp_path / "out"), "survey.json: files.weather: expected a "
                 "relative path inside the survey folder")


def test_wrong_dtype(survey, tmp_path, process):
    import tifffile

    tifffile.imwrite(survey / "frames/scan_000_b0.tif", np.zeros((3, 12, 16), np.float32),
                     photometric="minisblack")
    assert_fatal(process(survey, tmp_path / "out"), "frames/scan_000_b0.tif: dtype: expected "
                 "uint16 raw counts, got float32")


def test_wrong_size(survey, tmp_path, process):
    write_tiff_stack(survey / "frames/scan_001_b0.tif", np.zeros((3, 12, 20), np.uint16))
    assert_fatal(process(survey, tmp_path / "out"), "frames/scan_001_b0.tif: size: pages are "
                 "20x12 pixels, survey.json camera.resolution is 16x12")


def test_empty_survey(survey, tmp_path, process):
    (survey / "frames.csv").write_text("scan,position,band,time_utc,pan_deg,tilt_deg,file,"
                                       "page\n")
    assert_fatal(process(survey, tmp_path / "out"), "frames.csv: no frames (empty survey)")
    empty = tmp_path / "empty"
    empty.mkdir()
    assert_fatal(process(empty, tmp_path / "out2"), "survey.json: file not found (empty or "
                 "not a survey folder)")


def test_nmea_without_any_fix(survey, tmp_path, process):
    t0 = parse_utc("2026-11-15T00:00:00Z")
    lines = []
    for k in range(0, 3001, 10):
        lines += [gga_sentence(t0 + k, float("nan"), float("nan"), float("nan"), 0, 3, 9.9),
                  rmc_sentence(t0 + k, float("nan"), float("nan"), valid=False)]
    (survey / "gnss.nmea").write_text("\r\n".join(lines) + "\r\n")
    assert_fatal(process(survey, tmp_path / "out"), "gnss.nmea: GGA: no epoch has a position "
                 "fix (fix quality 1-5)")


def _edit_csv_column(path, column: int, fn) -> None:
    lines = path.read_text().splitlines()
    out = [lines[0]]
    for line in lines[1:]:
        f = line.split(",")
        f[column] = fn(f)
        out.append(",".join(f))
    path.write_text("\n".join(out) + "\n")


def test_degenerate_blackbody_temperatures(survey, tmp_path, process):
    _edit_csv_column(survey / "blackbody/temperatures.csv", 2, lambda f: f[1])  # bb2 = bb1
    assert_fatal(process(survey, tmp_path / "out"), "blackbody/temperatures.csv: degenerate "
                 "blackbody pair at 2026-11-15T00:00:19Z: blackbodies 1 and 2 at 25.00 and "
                 "25.00 C")


def test_degenerate_blackbody_images(survey, tmp_path, process):
    for p in sorted((survey / "blackbody").glob("event_*_b0.tif")):
        write_tiff_stack(p, np.full((20, 12, 16), 8000, np.uint16))
    assert_fatal(process(survey, tmp_path / "out"), "blackbody/frames.csv: degenerate "
                 "blackbody pair at 2026-11-15T00:00:19Z band 0: the images of blackbodies 1 "
                 "and 2 differ by 0.0 counts")


def test_weather_gap_over_a_scan(survey, tmp_path, process):
    p = survey / "weather.dat"
    lines = p.read_text().splitlines()
    # records every minute from line 4: drop 00:10 to 00:41 (scan 1 is at 00:26)
    p.write_text("\n".join(lines[:4 + 10] + lines[4 + 42:]) + "\n")
    assert_fatal(process(survey, tmp_path / "out"), "weather.dat: AirTC_Avg: no valid record "
                 "within 900 s of a requested time")
    assert_nothing_half_written(tmp_path / "out")
