"""``clearfast validate``: every kind of broken survey gives its one line and exit status."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest

from clearfast_gis.cli.main import cli
from clearfast_gis.survey import validate_survey
from clearfast_gis.survey.nmea import gga_sentence, rmc_sentence
from clearfast_gis.survey.tiff import write_tiff_stack
from clearfast_gis.timeutil import parse_utc


def run(capsys, *args: str) -> tuple[int, str, str]:
    with pytest.raises(SystemExit) as e:
        cli(["validate", *map(str, args)])
    out, err = capsys.readouterr()
    return e.value.code, out, err


def _edit_json(path, fn) -> None:
    doc = json.loads(path.read_text())
    fn(doc)
    path.write_text(json.dumps(doc))


def _replace_line(path, index: int, new: str | None) -> None:
    lines = path.read_text().splitlines()
    if new is None:
        del lines[index]
    else:
        lines[index] = new
    path.write_text("\n".join(lines) + "\n")


def test_valid_survey_summary(capsys, pristine_survey):
    code, out, err = run(capsys, pristine_survey)
    assert code == 0, out + err
    assert "frames:      12 (2 scans x 3 positions x 2 bands; 0 missing of 12)" in out
    assert "time span:   2026-11-15T00:01:00Z to 2026-11-15T00:26:04Z (UTC)" in out
    assert "RTK fixed 100.0% (q4: 301)" in out
    assert "result:      valid (0 problem(s), 0 warning(s))" in out
    code, out, _ = run(capsys, pristine_survey, "--json")
    rep = json.loads(out)
    assert code == 0 and rep["valid"] and rep["summary"]["rtk_fixed_share"] == 1.0


def test_usage_errors_exit_2(capsys, tmp_path):
    code, _, err = run(capsys, tmp_path / "missing")
    assert code == 2 and "does not exist" in err
    code, _, _ = run(capsys)
    assert code == 2


def _bad_resolution(s):
    _edit_json(s / "survey.json", lambda d: d["camera"].__setitem__("resolution", [16]))


def _escape(s):
    _edit_json(s / "survey.json", lambda d: d["files"].__setitem__("soil", "../soil.csv"))


def _symlink_escape(s):
    (s.parent / "elsewhere.csv").write_text((s / "soil.csv").read_text())
    (s / "soil.csv").unlink()
    (s / "soil.csv").symlink_to(s.parent / "elsewhere.csv")


def _truncated_tiff(s):
    p = s / "frames/scan_001_b0.tif"
    p.write_bytes(p.read_bytes()[:600])


def _corrupt_tiff(s):
    (s / "frames/scan_001_b0.tif").write_bytes(b"this is not a tiff at all")


def _missing_tiff(s):
    (s / "frames/scan_001_b1.tif").unlink()


def _wrong_dtype(s):
    import tifffile

    tifffile.imwrite(s / "frames/scan_000_b0.tif", np.zeros((3, 12, 16), np.float32),
                     photometric="minisblack")


def _wrong_size(s):
    write_tiff_stack(s / "frames/scan_000_b0.tif", np.zeros((3, 10, 16), np.uint16))


def _too_few_pages(s):
    write_tiff_stack(s / "frames/scan_000_b0.tif", np.zeros((2, 12, 16), np.uint16))


def _bad_frame_row(s):
    _replace_line(s / "frames.csv", 3, "0,1,0,2026-11-15T00:01:02Z,-10,-45,frames/x.tif,one")


def _unknown_position(s):
    text = (s / "frames.csv").read_text().replace("\n0,2,0,", "\n0,7,0,")
    (s / "frames.csv").write_text(text)


def _empty_frames(s):
    (s / "frames.csv").write_text("scan,position,band,time_utc,pan_deg,tilt_deg,file,page\n")


def _empty_folder(s):
    shutil.rmtree(s)
    s.mkdir()


def _bad_json(s):
    (s / "survey.json").write_text('{"format": "clearfast-survey",\n "oops"}')


def _no_fix(s):
    t0 = parse_utc("2026-11-15T00:00:00Z")
    lines = []
    for k in range(0, 3001, 10):
        lines += [gga_sentence(t0 + k, float("nan"), float("nan"), float("nan"), 0, 3, 9.9),
                  rmc_sentence(t0 + k, float("nan"), float("nan"), valid=False)]
    (s / "gnss.nmea").write_text("\r\n".join(lines) + "\r\n")


def _gnss_short(s):
    lines = (s / "gnss.nmea").read_text().splitlines()
    (s / "gnss.nmea").write_text("\n".join(lines[:100]) + "\n")


def _fix_gap(s):
    lines = (s / "gnss.nmea").read_text().splitlines()  # GGA + RMC every 10 s
    (s / "gnss.nmea").write_text("\n".join(lines[:180] + lines[480:]) + "\n")  # 900-2400 s


def _weather_units(s):
    p = s / "weather.dat"
    p.write_text(p.read_text().replace('"hPa"', '"kPa"'))


def _weather_all_nan(s):
    p = s / "weather.dat"
    lines = p.read_text().splitlines()
    for i in range(4, len(lines)):
        f = lines[i].split(",")
        f[2] = '"NAN"'
        lines[i] = ",".join(f)
    p.write_text("\n".join(lines) + "\n")


def _missing_bb(s):
    lines = (s / "blackbody/frames.csv").read_text().splitlines()
    keep = [ln for ln in lines if not ln.startswith("1,2,0,")]
    (s / "blackbody/frames.csv").write_text("\n".join(keep) + "\n")


def _blackbody_value(line: int, value: str):
    def breaker(s):
        lines = (s / "blackbody/temperatures.csv").read_text().splitlines()
        cells = lines[line - 1].split(",")
        cells[1] = value
        _replace_line(s / "blackbody/temperatures.csv", line - 1, ",".join(cells))
    return breaker


def _soil_garbage(s):
    _replace_line(s / "soil.csv", 2, "2026-11-15T00:10:00Z,hot,1,2,3,4")


def _soil_hot(s):
    lines = (s / "soil.csv").read_text().splitlines()
    cells = lines[3].split(",")
    cells[3] = "999.0"
    _replace_line(s / "soil.csv", 3, ",".join(cells))


def _mission_mismatch(s):
    _edit_json(s / "mission.json", lambda d: d["camera"].__setitem__("resolution", [32, 24]))


PROBLEMS = {
    "resolution": (_bad_resolution, "survey.json: camera.resolution: expected 2 integers"),
    "escape": (_escape, "survey.json: files.soil: expected a relative path inside the survey "
                        "folder"),
    "symlink": (_symlink_escape, "survey.json: files.soil: 'soil.csv' leaves the survey folder"),
    "truncated": (_truncated_tiff, "frames/scan_001_b0.tif: corrupt or truncated TIFF"),
    "corrupt": (_corrupt_tiff, "frames/scan_001_b0.tif: not a readable TIFF"),
    "missing_tiff": (_missing_tiff, "frames/scan_001_b1.tif: file not found"),
    "dtype": (_wrong_dtype, "frames/scan_000_b0.tif: dtype: expected uint16 raw counts, got "
                            "float32"),
    "size": (_wrong_size, "frames/scan_000_b0.tif: size: pages are 16x10 pixels, survey.json "
                          "camera.resolution is 16x12"),
    "pages": (_too_few_pages, "frames/scan_000_b0.tif: pages: frames.csv refers to page 2 but "
                              "the file has 2 page(s)"),
    "frame_row": (_bad_frame_row, "frames.csv: line 4: page: expected an integer, got 'one'"),
    "position": (_unknown_position, "frames.csv: position: position(s) 7 are not in "
                                    "mission.json"),
    "empty_frames": (_empty_frames, "frames.csv: no frames (empty survey)"),
    "empty_folder": (_empty_folder, "survey.json: file not found (empty or not a survey "
                                    "folder)"),
    "bad_json": (_bad_json, "survey.json: line 2 column 8: not valid JSON: Expecting ':' "
                            "delimiter"),
    "no_fix": (_no_fix, "gnss.nmea: GGA: no epoch has a position fix (fix quality "
                        "1-5)"),
    "gnss_short": (_gnss_short, "gnss.nmea: position fixes from 2026-11-15T00:00:00Z to "
                                "2026-11-15T00:08:10Z does not cover the frames"),
    "fix_gap": (_fix_gap, "gnss.nmea: GGA: 6 frame(s) farther than 600 s from any position "
                          "fix, first at 2026-11-15T00:26:00Z"),
    "weather_units": (_weather_units, "weather.dat: line 5: BP_hPa_Avg (pressure_hpa): 51 "
                      "value(s) outside 924.176..1064.18 hPa at 160 m, first line 5: 10050 "
                      "hPa (wrong column or unit?)"),
    "weather_nan": (_weather_all_nan, "weather.dat: air_temp_c: all values missing (NAN)"),
    "blackbody": (_missing_bb, "blackbody/frames.csv: blackbody: event 1 band 0: no frames of "
                               "blackbody 2"),
    "blackbody_range": (_blackbody_value(3, "522.0"), "blackbody/temperatures.csv: line 3: "
                        "bb1_c: 1 value(s) outside -40..150 deg C, first line 3: 522 deg C "
                        "(wrong column or unit?)"),
    "blackbody_spike": (_blackbody_value(4, "99.0"), "blackbody/temperatures.csv: line 4: "
                        "bb1_c: 1 spike(s) of more than 5 deg C from both neighbours, first "
                        "line 4: 99 deg C"),
    "soil": (_soil_garbage, "soil.csv: line 3: T_0.020m_C: expected a number, got 'hot'"),
    "soil_range": (_soil_hot, "soil.csv: line 4: T_0.100m_C: 1 value(s) outside -40..85 deg C, "
                              "first line 4: 999 deg C (wrong column or unit?)"),
    "mission": (_mission_mismatch, "mission.json: camera.resolution: [32, 24] differs from "
                                   "survey.json camera.resolution [16, 12]"),
}


@pytest.mark.parametrize("kind", sorted(PROBLEMS))
def test_broken_survey_gives_one_line_and_exit_1(kind, survey_copy, capsys):
    breaker, expected = PROBLEMS[kind]
    breaker(survey_copy)
    code, out, err = run(capsys, survey_copy)
    assert code == 1, out + err
    assert "Traceback" not in out + err
    first = out.splitlines()
    assert any(line.startswith(expected) for line in first), out
    assert "result:      INVALID" in out


def _bad_checksum(s):
    _replace_line(s / "gnss.nmea", 6, (s / "gnss.nmea").read_text().splitlines()[6][:-2] + "00")


def _gnss_gap(s):
    lines = (s / "gnss.nmea").read_text().splitlines()
    (s / "gnss.nmea").write_text("\n".join(lines[:40] + lines[70:]) + "\n")


def _rtk_float(s):
    p = s / "gnss.nmea"
    lines = p.read_text().splitlines()
    t0 = parse_utc("2026-11-15T00:00:00Z")
    lines[0] = gga_sentence(t0, 35.17, 33.36, 170.0, 5, 14, 0.7)
    p.write_text("\n".join(lines) + "\n")


def _weather_gap(s):
    lines = (s / "weather.dat").read_text().splitlines()
    (s / "weather.dat").write_text("\n".join(lines[:20] + lines[26:]) + "\n")


def _missing_frame_row(s):
    _replace_line(s / "frames.csv", 2, None)


WARNINGS = {
    "checksum": (_bad_checksum, "warning: gnss.nmea: line 7: 1 line(s) with a wrong checksum"),
    "gnss_gap": (_gnss_gap, "warning: gnss.nmea: time: 1 gap(s) longer than 10 s, longest "
                            "160 s at 2026-11-15T00:03:10Z"),
    "rtk_float": (_rtk_float, "warning: gnss.nmea: GGA: 1 RTK float epoch(s)"),
    "weather_gap": (_weather_gap, "warning: weather.dat: TIMESTAMP: 1 gap(s) longer than 180 s, "
                                  "longest 420 s"),
    "missing_frame": (_missing_frame_row, "warning: frames.csv: 1 of 12 frame(s) missing "
                                          "(scans 0 incomplete)"),
}


@pytest.mark.parametrize("kind", sorted(WARNINGS))
def test_warnings_keep_exit_0(kind, survey_copy, capsys):
    breaker, expected = WARNINGS[kind]
    breaker(survey_copy)
    code, out, err = run(capsys, survey_copy)
    assert code == 0, out + err
    assert any(line.startswith(expected) for line in out.splitlines()), out


def test_all_problems_are_collected(survey_copy):
    _bad_resolution(survey_copy)
    _missing_tiff(survey_copy)
    _soil_garbage(survey_copy)
    _weather_units(survey_copy)
    rep = validate_survey(survey_copy)
    files = sorted({p.file for p in rep.problems})
    assert files == ["frames/scan_001_b1.tif", "soil.csv", "survey.json", "weather.dat"]
    assert not rep.valid and rep.summary["frames"] == 12
