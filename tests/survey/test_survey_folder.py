"""Schemas, manifest, frames tables, TIFF stacks and the Survey object."""

from __future__ import annotations

import json

import jsonschema
import numpy as np
import pytest
import tifffile
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey import (
    load_schema,
    parse_frames_table,
    read_blackbody_frames,
    read_frames_table,
    read_mission,
    read_survey,
    read_tiff_stack,
    schema_errors,
    tiff_info,
    write_frames_table,
    write_mission,
    write_survey_json,
    write_tiff_stack,
)
from clearfast_gis.survey.manifest import is_safe_relpath
from clearfast_gis.survey.testing import minimal_manifest, minimal_mission


@pytest.mark.parametrize("name", ["survey", "mission", "frames", "blackbody_frames"])
def test_schemas_are_valid_draft_2020_12(name, repo_root):
    schema = load_schema(name)
    jsonschema.Draft202012Validator.check_schema(schema)
    on_disk = json.loads((repo_root / "schemas" / f"{name}.schema.json").read_text())
    assert on_disk == schema


def test_contract_example_is_valid_and_errors_are_readable():
    m = minimal_manifest()
    assert schema_errors(m, "survey") == []
    m["camera"]["resolution"] = [160]
    m["camera"]["model"] = "fisheye"
    del m["site"]["name"]
    m["files"]["gnss"] = "../outside.nmea"
    assert schema_errors(m, "survey") == [
        ("camera.model", "expected \"equiangular\" or \"pinhole\", got \"fisheye\""),
        ("camera.resolution", "expected 2 integers"),
        ("files.gnss", "expected a relative path inside the survey folder"),
        ("site.name", "missing"),
    ]
    m = minimal_manifest()
    m["camera"]["resolution"] = [160, "128"]
    assert schema_errors(m, "survey") == [("camera.resolution", "expected 2 integers")]
    m = minimal_manifest()
    m["camera"]["model"] = "pinhole"
    assert schema_errors(m, "survey") == [("camera.intrinsics", "missing")]


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet="ab./\\:C", min_size=1, max_size=12))
def test_relpath_schema_pattern_agrees_with_python_check(rel):
    m = minimal_manifest()
    m["files"]["gnss"] = rel
    by_schema = not any(f == "files.gnss" for f, _ in schema_errors(m, "survey"))
    assert by_schema == is_safe_relpath(rel)


def test_manifest_and_mission_round_trip(tmp_path):
    m = minimal_manifest(n_bands=3)
    write_survey_json(tmp_path / "survey.json", m)
    assert json.loads((tmp_path / "survey.json").read_text()) == m
    mi = minimal_mission(4, 5, 1500.0, 16, 12)
    mi["n_scans"] = np.int64(4)  # numpy scalars are accepted
    write_mission(tmp_path / "mission.json", mi)
    assert read_mission(tmp_path / "mission.json")["n_scans"] == 4
    bad = dict(mi, overlap=1.5)
    with pytest.raises(InvalidInput, match="overlap: expected a fraction"):
        write_mission(tmp_path / "m2.json", bad)
    assert not (tmp_path / "m2.json").exists()


def test_frames_table_round_trip(tmp_path):
    n = 7
    cols = {"scan": np.arange(n) // 3, "position": np.arange(n) % 3, "band": np.zeros(n, int),
            "time_s": 1.8e9 + np.arange(n) * 2.5 + 0.125, "pan_deg": np.linspace(-20, 20, n),
            "tilt_deg": np.full(n, -45.123456), "file": np.array(["frames/a.tif"] * n),
            "page": np.arange(n) % 3}
    write_frames_table(tmp_path / "frames.csv", cols)
    back = read_frames_table(tmp_path / "frames.csv")
    for k, v in cols.items():
        if k == "file":
            assert back.file.tolist() == v.tolist()
        else:
            np.testing.assert_allclose(back[k], v, atol=1e-6)
    assert back.to_records()["page"].tolist() == cols["page"].tolist()
    assert len(back.take(back.scan == 1)) == 3


@pytest.mark.parametrize(("text", "line"), [
    ("scan,position,band\n", "frames.csv: line 1: missing column(s) time_utc, pan_deg, tilt_deg, "
                             "file, page; expected header scan,position,band,time_utc,pan_deg,"
                             "tilt_deg,file,page"),
    ("scan,position,band,time_utc,pan_deg,tilt_deg,file,page\n0,1,-1,2026-11-15T00:00:00Z,0,0,"
     "f.tif,0\n", "frames.csv: line 2: band: expected an integer >= 0, got -1"),
    ("scan,position,band,time_utc,pan_deg,tilt_deg,file,page\n0,1,0,2026-11-15T00:00:00Z,nan,0,"
     "f.tif,0\n", "frames.csv: line 2: pan_deg: expected a finite number, got 'nan'"),
    ("scan,position,band,time_utc,pan_deg,tilt_deg,file,page\n0,1,0\n",
     "frames.csv: line 2: row has 3 fields, column 'time_utc' missing"),
])
def test_frames_table_errors(text, line):
    with pytest.raises(InvalidInput) as e:
        parse_frames_table(text)
    assert e.value.one_line() == line


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.text(max_size=300))
def test_fuzz_frames_table(text):
    head = "scan,position,band,time_utc,pan_deg,tilt_deg,file,page\n"
    for candidate in (text, head + text):
        try:
            parse_frames_table(candidate)
        except InvalidInput:
            pass


def test_tiff_stack_round_trip_memmap_and_header(tmp_path):
    stack = np.random.default_rng(0).integers(0, 2**14, (5, 12, 16), dtype=np.uint16)
    write_tiff_stack(tmp_path / "s.tif", stack)
    got = read_tiff_stack(tmp_path / "s.tif")
    assert isinstance(got, np.memmap)
    np.testing.assert_array_equal(got, stack)
    np.testing.assert_array_equal(read_tiff_stack(tmp_path / "s.tif", [4, 0]), stack[[4, 0]])
    info = tiff_info(tmp_path / "s.tif")
    assert (info.n_pages, info.shape, info.dtype) == (5, (12, 16), np.uint16)
    tifffile.imwrite(tmp_path / "z.tif", stack, compression="zlib")
    np.testing.assert_array_equal(read_tiff_stack(tmp_path / "z.tif", [1, 2]), stack[1:3])
    with pytest.raises(ValueError, match="uint16"):
        write_tiff_stack(tmp_path / "f.tif", stack.astype(np.float32))


def test_truncated_and_corrupt_tiffs(tmp_path):
    stack = np.ones((4, 12, 16), dtype=np.uint16)
    write_tiff_stack(tmp_path / "s.tif", stack)
    data = (tmp_path / "s.tif").read_bytes()
    (tmp_path / "t.tif").write_bytes(data[: len(data) // 2])
    with pytest.raises(InvalidInput, match="t.tif: (corrupt or truncated|truncated) TIFF"):
        tiff_info(tmp_path / "t.tif")
    (tmp_path / "c.tif").write_bytes(b"II*\x00" + b"\xff" * 50)
    with pytest.raises(InvalidInput, match="c.tif: (not a readable TIFF|TIFF has no page)"):
        tiff_info(tmp_path / "c.tif")
    with pytest.raises(InvalidInput, match="file not found"):
        tiff_info(tmp_path / "none.tif")


def test_survey_object(pristine_survey):
    s = read_survey(pristine_survey)
    assert [b.name for b in s.bands] == ["LW1", "LW2"]
    assert s.scans.tolist() == [0, 1] and s.positions.tolist() == [0, 1, 2]
    scan = s.read_scan(1, "LW2")
    truth = tifffile.imread(pristine_survey / "frames/scan_001_b1.tif")
    np.testing.assert_array_equal(scan, truth)
    np.testing.assert_array_equal(s.read_frame(1, 2, 1), truth[2])
    assert s.scan_positions(1, 1).tolist() == [0, 1, 2]
    assert s.path("gnss") == (pristine_survey / "gnss.nmea").resolve()
    assert s.mission["n_scans"] == 2
    with pytest.raises(InvalidInput, match="no band named"):
        s.read_scan(0, "MW")


def test_blackbody_means(pristine_survey):
    s = read_survey(pristine_survey)
    events = read_blackbody_frames(s)
    assert [(e.event, e.band) for e in events] == [(0, 0), (0, 1), (1, 0), (1, 1)]
    stack = tifffile.imread(pristine_survey / "blackbody/event_001_b0.tif").astype(float)
    e = events[2]
    np.testing.assert_allclose(e.bb1_mean, stack[:10].mean(axis=0))
    np.testing.assert_allclose(e.bb2_mean, stack[10:].mean(axis=0))
    assert e.n_bb1 == e.n_bb2 == 10 and e.bb1_time_s < e.bb2_time_s


def test_read_survey_errors(tmp_path, survey_copy):
    with pytest.raises(InvalidInput, match="survey folder not found"):
        read_survey(tmp_path / "nope")
    m = json.loads((survey_copy / "survey.json").read_text())
    m["camera"]["resolution"] = [16]
    (survey_copy / "survey.json").write_text(json.dumps(m))
    with pytest.raises(InvalidInput) as e:
        read_survey(survey_copy)
    assert e.value.one_line() == "survey.json: camera.resolution: expected 2 integers"
