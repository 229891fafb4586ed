"""Fuzzing the parsers the survey tests do not fuzz (tests/survey covers the frames table, the
NMEA, TOA5, soil, blackbody-log and marker parsers): TIFF headers, survey.json and
mission.json, the blackbody frames table and the survey-folder path check. Every input is
either accepted or refused with InvalidInput (one line, naming the file); nothing else escapes.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey.manifest import manifest_problems, parse_json, resolve_inside
from clearfast_gis.survey.tables import parse_blackbody_frames_table
from clearfast_gis.survey.testing import minimal_manifest, minimal_mission
from clearfast_gis.survey.tiff import read_tiff_stack, tiff_info, write_tiff_stack

FAST = settings(max_examples=150, deadline=None,
                suppress_health_check=[HealthCheck.function_scoped_fixture])


def _valid_tiff_bytes() -> bytes:
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "t.tif"
        write_tiff_stack(p, np.arange(3 * 6 * 5, dtype=np.uint16).reshape(3, 6, 5))
        return p.read_bytes()


VALID_TIFF = _valid_tiff_bytes()
SCRATCH = Path(tempfile.mkdtemp(prefix="clearfast-fuzz-"))


def _check_tiff(data: bytes) -> None:
    p = SCRATCH / "f.tif"
    p.write_bytes(data)
    try:
        info = tiff_info(p, "frames/f.tif")
    except InvalidInput as exc:
        assert exc.one_line().startswith("frames/f.tif: ")
        assert "\n" not in exc.one_line()
        return
    assert info.n_pages >= 1 and info.data_end <= len(data)
    try:  # a header that passes must give its pages, or a one-line refusal
        stack = read_tiff_stack(p, label="frames/f.tif")
    except InvalidInput as exc:
        assert exc.one_line().startswith("frames/f.tif: ")
        return
    assert stack.shape[0] == info.n_pages


@FAST
@given(st.binary(max_size=600))
def test_fuzz_tiff_random_bytes(data):
    _check_tiff(data)


@FAST
@given(st.lists(st.tuples(st.integers(0, len(VALID_TIFF) - 1), st.integers(0, 255)),
                min_size=1, max_size=6),
       st.integers(8, len(VALID_TIFF)))
def test_fuzz_tiff_mutated_and_truncated(edits, length):
    data = bytearray(VALID_TIFF)
    for i, b in edits:
        data[i] = b
    _check_tiff(bytes(data[:length]))


JSON_LEAF = st.none() | st.booleans() | st.integers(-10**6, 10**6) | \
    st.floats(allow_nan=False) | st.text(max_size=12)
JSON = st.recursive(JSON_LEAF, lambda kids: st.lists(kids, max_size=4)
                    | st.dictionaries(st.text(max_size=8), kids, max_size=4), max_leaves=12)


def _mutate(doc: dict, path: list[str], value) -> dict:
    doc = json.loads(json.dumps(doc))
    node = doc
    for key in path[:-1]:
        node = node[key] if isinstance(node.get(key), dict) else node.setdefault(key, {})
    node[path[-1]] = value
    return doc


SURVEY_KEYS = st.sampled_from([["survey_id"], ["camera", "resolution"], ["camera", "bands"],
                               ["camera", "model"], ["files", "frames"], ["files", "gnss"],
                               ["time", "start_utc"], ["crs", "epsg"], ["site"],
                               ["platform", "antenna_to_camera_m"], ["format_version"]])


@FAST
@given(SURVEY_KEYS, JSON)
def test_fuzz_survey_json_fields(path, value):
    doc = _mutate(minimal_manifest(), path, value)
    problems = manifest_problems(doc, "survey")
    for field, message in problems:
        assert isinstance(field, str) and message and "\n" not in message
    if not problems:  # accepted: the paths it names stay inside the folder
        for key, rel in doc["files"].items():
            resolve_inside(SCRATCH, rel, "survey.json", f"files.{key}")


@FAST
@given(st.sampled_from([["n_scans"], ["positions"], ["camera", "resolution"], ["area"],
                        ["overlap"], ["platform", "height_m"]]), JSON)
def test_fuzz_mission_json_fields(path, value):
    doc = _mutate(minimal_mission(2, 3, 1500.0, 16, 12), path, value)
    for field, message in manifest_problems(doc, "mission"):
        assert isinstance(field, str) and message and "\n" not in message


@FAST
@given(st.text(max_size=200))
def test_fuzz_json_text(text):
    try:
        doc = parse_json(text, "survey.json")
    except InvalidInput as exc:
        assert exc.one_line().startswith("survey.json: ")
        return
    manifest_problems(doc, "survey")


BB_HEADER = "event,blackbody,band,time_utc,file,page"
BB_ROW = st.tuples(st.integers(-2, 3), st.integers(-1, 3), st.integers(-1, 2),
                   st.sampled_from(["2026-11-15T00:00:01Z", "2026-11-15T00:00:01.5Z", "x",
                                    ""]),
                   st.sampled_from(["blackbody/e.tif", "../e.tif", "", "a,b"]),
                   st.integers(-1, 20) | st.text(max_size=3))


@FAST
@given(st.lists(BB_ROW, max_size=8), st.text(max_size=30))
def test_fuzz_blackbody_frames_table(rows, junk):
    text = "\n".join([BB_HEADER, *(",".join(map(str, r)) for r in rows), junk])
    try:
        table = parse_blackbody_frames_table(text, "blackbody/frames.csv")
    except InvalidInput as exc:
        assert exc.one_line().startswith("blackbody/frames.csv: ")
        return
    assert len(table) <= len(rows) + 1
    assert np.all(np.isin(table.blackbody, [1, 2])) and np.all(table.page >= 0)


@FAST
@given(st.text(alphabet="ab./\\~:$", min_size=1, max_size=16))
def test_fuzz_paths_never_leave_the_survey_folder(rel):
    root = SCRATCH / "root"
    root.mkdir(exist_ok=True)
    try:
        full = resolve_inside(root, rel, "survey.json", "files.frames")
    except InvalidInput as exc:
        assert exc.one_line().startswith("survey.json: files.frames: ")
        return
    real = Path(os.path.realpath(root))
    assert full == real or real in full.parents
