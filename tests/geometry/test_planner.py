"""Scan-mission planner: coverage, overlap, counts, pixel sizes, schema, command line."""

from __future__ import annotations

import json
import math
import subprocess
import sys

import jsonschema
import numpy as np
import pytest
import shapely
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st
from shapely.geometry import box

from clearfast_gis.errors import InvalidInput
from clearfast_gis.geometry import build_plan, default_platform_xy, frame_footprint, plan_mission
from clearfast_gis.geometry.planner import azimuth_interval, clock_interval_minutes

AREA = (0.0, 0.0, 30.0, 20.0)


@pytest.fixture(scope="module")
def paper_plan():
    """The paper's case: 20 m x 30 m, platform 13.5 m high 3 m off the long side, 320x240."""
    return build_plan(13.5, 8.0, (320, 240), AREA, overlap=0.3)


def _union_covers(plan, samples=96):
    foot = [frame_footprint(plan.camera, p, samples_per_edge=samples) for p in plan.poses()]
    missing = box(*plan.mission["area"]).difference(shapely.unary_union(foot))
    return missing.area


def test_paper_case_counts(paper_plan):
    m = paper_plan.mission
    assert 200 <= m["images_per_scan"] <= 400  # the paper: 261
    assert m["n_scans"] == 48 and m["scan_interval_s"] == 1800.0  # paper: 48 scans in 24 h
    assert m["images_total"] == 48 * m["images_per_scan"]
    assert [p["index"] for p in m["positions"]] == list(range(m["images_per_scan"]))
    assert paper_plan.coverage_fraction == pytest.approx(1.0, abs=1e-9)
    assert _union_covers(paper_plan) < 1e-6


def test_wide_aperture_needs_few_frames():
    m = plan_mission(13.5, 24.0, (320, 240), AREA)
    assert m["images_per_scan"] < 60


@pytest.mark.parametrize("model,platform", [
    ("equiangular", (15.0, -3.0)), ("equiangular", (-6.0, 25.0)), ("equiangular", (40.0, 10.0)),
    ("equiangular", (12.0, 21.0)), ("pinhole", (15.0, -3.0)), ("pinhole", (-6.0, 25.0)),
    ("pinhole", (40.0, 10.0)),
])
def test_union_covers_area(model, platform):
    plan = build_plan(12.0, 14.0, (160, 128), AREA, platform, overlap=0.2, camera_model=model)
    assert plan.coverage_fraction == pytest.approx(1.0, abs=1e-9)
    assert _union_covers(plan) < 1e-6


def test_pinhole_too_close_to_nadir():
    with pytest.raises(InvalidInput) as exc:
        plan_mission(12.0, 14.0, (160, 128), AREA, (12.0, 21.0), camera_model="pinhole")
    assert exc.value.field == "platform"


def test_overlap_along_and_across(paper_plan):
    rows = paper_plan.rows
    for a, b in zip(rows, rows[1:], strict=False):
        overlap = (a.box.bottom_deg - b.box.top_deg) / b.box.height_deg
        assert -overlap >= 0.3 - 1e-6  # next row's top is above this row's bottom
    assert rows[0].box.top_deg == pytest.approx(-math.degrees(math.atan2(13.5, math.hypot(
        15, 23))), abs=1e-3)
    assert rows[-1].box.bottom_deg == pytest.approx(-math.degrees(math.atan2(13.5, 3.0)),
                                                    abs=1e-3)
    for r in rows:
        steps = np.abs(np.diff(r.pans_deg))
        if steps.size:
            assert np.all(steps <= 2 * r.box.half_az_deg * 0.7 + 1e-3)
        lo, hi = r.azimuth_range_deg
        assert min(r.pans_deg) - r.box.half_az_deg <= lo + 1e-3
        assert max(r.pans_deg) + r.box.half_az_deg >= hi - 1e-3


def test_serpentine_order(paper_plan):
    signs = [np.sign(np.diff(r.pans_deg)).mean() for r in paper_plan.rows if len(r.pans_deg) > 1]
    assert all(s == 1.0 for s in signs[::2]) and all(s == -1.0 for s in signs[1::2])
    tilts = [p["tilt_deg"] for p in paper_plan.mission["positions"]]
    assert np.all(np.diff(tilts) <= 0)  # far rows first, each row at one tilt


def test_ground_resolution_equiangular_formula(paper_plan):
    """Across = chord of one ifov at the range, along = range step of one ifov in depression."""
    h, ifov = 13.5, math.radians(8.0) / 319
    r_min, r_max = 3.0, math.hypot(15.0, 23.0)
    def along(r):
        d = math.atan2(h, r)
        return h / math.tan(d - ifov) - r
    res = paper_plan.mission["ground_resolution_m"]
    assert res["across_min"] == pytest.approx(2 * math.hypot(r_min, 0) * math.sin(ifov / 2),
                                              rel=0.02)
    assert res["across_max"] == pytest.approx(r_max * ifov, rel=0.02)
    assert res["along_min"] == pytest.approx(along(r_min), rel=0.03)
    assert res["along_max"] == pytest.approx(along(r_max), rel=0.03)


def test_mission_follows_schema(paper_plan):
    from clearfast_gis.survey.schema import load_schema

    jsonschema.validate(paper_plan.mission, load_schema("mission"))
    text = json.dumps(paper_plan.mission)
    assert json.loads(text) == paper_plan.mission


def test_scans_and_interval():
    assert clock_interval_minutes(25) == 30.0
    assert clock_interval_minutes(9.5) == 10.0
    assert clock_interval_minutes(70) == 120.0
    m = plan_mission(13.5, 24.0, (320, 240), AREA, scan_minutes=25, hours=12,
                     interval_minutes=25)
    assert m["n_scans"] == 28 and m["scan_interval_s"] == 1500.0 and m["duration_h"] == 12.0


def test_default_platform():
    assert default_platform_xy((0, 0, 30, 20)) == (15.0, -3.0)
    assert default_platform_xy((0, 0, 20, 30)) == (-3.0, 15.0)


@pytest.mark.parametrize("kwargs,field", [
    ({"platform_xy": (5.0, 5.0)}, "platform"),
    ({"overlap": 0.95}, "overlap"),
    ({"height_m": -1.0}, "height"),
    ({"aperture_deg": 200.0}, "aperture"),
    ({"area": (0, 0, -1, 5)}, "area"),
    ({"resolution": (320,)}, "resolution"),
    ({"scan_minutes": 40.0, "interval_minutes": 30.0}, "interval-minutes"),
])
def test_invalid_parameters(kwargs, field):
    args = {"height_m": 13.5, "aperture_deg": 20.0, "resolution": (320, 240), "area": AREA,
            **kwargs}
    with pytest.raises(InvalidInput) as exc:
        plan_mission(**args)
    assert exc.value.field == field


rects = st.tuples(st.floats(-50, 50), st.floats(-50, 50), st.floats(1, 40), st.floats(1, 40))


@given(rects, st.floats(0, 2 * math.pi), st.floats(0.5, 20), st.floats(0, 60),
       st.floats(0.5, 60))
@settings(max_examples=60, deadline=None)
@example((1.9, 0.0, 15.0, 1.0), 0.0, 1.0, 0.0, 9.0)
def test_azimuth_interval_bounds_every_point(rect, ang, gap, r0, dr):
    """Every area point in the annulus lies within the interval, whose ends are attained."""
    x0, y0, w, h = rect
    area = (x0, y0, x0 + w, y0 + h)
    cx, cy = x0 + w / 2, y0 + h / 2
    reach = math.hypot(w, h) / 2 + gap
    xy = (cx + reach * math.sin(ang), cy + reach * math.cos(ang))
    assume(not (area[0] <= xy[0] <= area[2] and area[1] <= xy[1] <= area[3]))
    got = azimuth_interval(area, xy, r0, r0 + dr)
    gx, gy = np.meshgrid(np.linspace(area[0], area[2], 120), np.linspace(area[1], area[3], 120))
    rho = np.hypot(gx - xy[0], gy - xy[1])
    inside = (rho >= r0) & (rho <= r0 + dr)
    if got is None:
        assert not inside.any()
        return
    centre = math.degrees(math.atan2(cx - xy[0], cy - xy[1]))
    # straight south the centre direction is +-180 deg depending on rounding: same interval
    turn = 360.0 * round((centre - 0.5 * (got[0] + got[1])) / 360.0)
    got = (got[0] + turn, got[1] + turn)
    az = np.degrees(np.arctan2(gx[inside] - xy[0], gy[inside] - xy[1]))
    az = centre + (az - centre + 180.0) % 360.0 - 180.0
    if az.size:
        assert az.min() >= got[0] - 1e-6 and az.max() <= got[1] + 1e-6
        step = math.degrees(math.hypot(w, h) / 119 / max(r0, 1e-3))
        assert az.min() <= got[0] + step + 1e-6 and az.max() >= got[1] - step - 1e-6


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "clearfast_gis.cli.main", "plan", *args],
                          capture_output=True, text=True, timeout=120)


def test_cli_writes_mission(tmp_path):
    out = tmp_path / "mission.json"
    r = _cli("--height", "13.5", "--aperture", "24", "--resolution", "320x240", "--area",
             "0,0,30,20", "--overlap", "0.3", "--scan-minutes", "25", "--hours", "24",
             "--json", "-o", str(out))
    assert r.returncode == 0, r.stderr
    summary = json.loads(r.stdout)
    mission = json.loads(out.read_text())
    assert summary["images_per_scan"] == mission["images_per_scan"] == len(mission["positions"])
    assert summary["n_scans"] == 48 and summary["coverage_fraction"] == 1.0
    r = _cli("--height", "13.5", "--aperture", "24", "--resolution", "320x240", "--area",
             "0,0,30,20", "--platform", "15,-5", "-o", str(out))
    assert r.returncode == 0 and "images per scan" in r.stdout
    assert json.loads(out.read_text())["platform"] == {"x_m": 15.0, "y_m": -5.0,
                                                       "height_m": 13.5}


@pytest.mark.parametrize("args,code,text", [
    (("--resolution", "320x24x0"), 2, "expected 2 integers WxH"),
    (("--area", "0,0,30"), 2, "XMIN,YMIN,XMAX,YMAX"),
    (("--overlap", "1.5"), 2, "--overlap"),
    (("--platform", "5,5"), 1, "clearfast: error: --platform: the platform must stand outside"),
])
def test_cli_errors(tmp_path, args, code, text):
    base = {"--height": "13.5", "--aperture": "24", "--resolution": "320x240",
            "--area": "0,0,30,20"}
    base.update(dict(zip(args[::2], args[1::2], strict=True)))
    flat = [x for kv in base.items() for x in kv]
    r = _cli(*flat, "-o", str(tmp_path / "m.json"))
    assert r.returncode == code
    assert text in r.stderr and "Traceback" not in r.stderr
    if code == 1:
        assert len(r.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "m.json").exists()
