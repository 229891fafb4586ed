"""The simulated folder follows the survey format and its logs parse with the project readers."""

from __future__ import annotations

import csv
from dataclasses import replace

import numpy as np
import rasterio

from clearfast_gis.simulate import simulate_survey
from clearfast_gis.survey import (
    read_blackbody_log,
    read_markers,
    read_nmea,
    read_soil_log,
    read_survey,
    read_toa5,
)
from clearfast_gis.survey.validate import validate_survey
from clearfast_gis.timeutil import parse_utc


def test_validate_accepts_demo(demo_survey):
    report = validate_survey(demo_survey.root)
    assert report.problems == []
    assert report.summary["frames"] == demo_survey.n_frames == 6 * demo_survey.n_positions * 2
    assert 15 <= demo_survey.n_positions <= 30


def test_validate_accepts_pinhole_variant(tmp_path, small_config):
    cfg = replace(small_config, camera_model="pinhole", n_scans=2)
    res = simulate_survey(tmp_path / "pin", cfg, seed=2)
    report = validate_survey(res.root)
    assert report.problems == []
    sv = read_survey(res.root)
    assert sv.manifest["camera"]["model"] == "pinhole"
    assert len(sv.manifest["camera"]["intrinsics"]["distortion"]) == 5


def test_logs_parse_with_survey_readers(demo_survey):
    sv = read_survey(demo_survey.root)
    gnss = read_nmea(sv.path("gnss"))
    counts = gnss.fix_counts()
    assert gnss.n_bad_checksum == 0 and gnss.n_unparseable == 0
    assert counts[4] > 0.95 * len(gnss) and counts.get(5, 0) > 0 and counts.get(0, 0) > 0
    fixed = gnss.fix_quality == 4
    # antenna altitude: ground 160 m + 8 m camera + 0.4 m mount, with cm noise
    assert abs(np.median(gnss.alt_m[fixed]) - 168.4) < 0.01
    assert np.all(np.isnan(gnss.lat_deg[gnss.fix_quality == 0]))
    wx = read_toa5(sv.path("weather"))
    assert len(wx) == 24 * 60 + 1
    assert 9.0 < np.nanmin(wx.air_temp_c) < 11.5 and 21.5 < np.nanmax(wx.air_temp_c) < 24.0
    assert 500.0 < np.nanmax(wx.solar_wm2) < 700.0
    assert 960.0 < np.nanmean(wx.pressure_hpa) < 1000.0
    soil = read_soil_log(sv.path("soil"))
    np.testing.assert_allclose(soil.depth_m, [0.02, 0.05, 0.10, 0.20, 0.50])
    amplitude = soil.temp_c.max(axis=0) - soil.temp_c.min(axis=0)
    assert np.all(np.diff(amplitude) < 0)  # the diurnal wave damps with depth
    bb = read_blackbody_log(sv.path("blackbody_log"))
    assert abs(np.median(bb.bb1_c - bb.bb2_c) - 10.0) < 0.5
    markers = read_markers(sv.path("markers"))
    assert len(markers) == 3


def test_truth_files(demo_survey):
    root = demo_survey.root
    with open(root / "truth" / "objects.csv") as fh:
        rows = list(csv.DictReader(fh))
    for col in ("id", "kind", "x", "y", "depth_m", "diameter_m", "diffusivity_m2s"):
        assert col in rows[0]
    kinds = {r["kind"] for r in rows}
    assert {"at_mine", "ap_mine", "marker"} <= kinds
    at = [r for r in rows if r["kind"] == "at_mine"]
    assert all(abs(float(r["diameter_m"]) - 0.337) < 1e-9 for r in at)
    tifs = sorted((root / "truth" / "apparent_temperature").glob("scan_*.tif"))
    assert [t.name for t in tifs] == [f"scan_{s:03d}.tif" for s in range(6)]
    sv = read_survey(root)
    with rasterio.open(tifs[0]) as src:
        assert src.crs.to_epsg() == sv.manifest["crs"]["epsg"] == 32636
        x0, y0 = src.transform.c, src.transform.f
        xs = [float(r["x"]) for r in rows]
        ys = [float(r["y"]) for r in rows]
        assert x0 <= min(xs) and max(xs) <= x0 + src.width * src.transform.a
        assert y0 - src.height * abs(src.transform.e) <= min(ys) and max(ys) <= y0
        night = src.read(1)
    with rasterio.open(tifs[2]) as src:
        day = src.read(1)
    # warm by day, cool by night (scans at 03:00 and 11:00 local time)
    assert np.median(day) > np.median(night) + 10.0
    with open(root / "truth" / "poses.csv") as fh:
        poses = list(csv.DictReader(fh))
    assert len(poses) == demo_survey.n_frames
    frames = sv.frames
    np.testing.assert_allclose(np.array([parse_utc(p["time_utc"]) for p in poses]),
                               np.sort(frames.time_s), atol=1e-3)


def test_cli_refuses_foreign_folder_and_bad_scenario(tmp_path):
    from click.testing import CliRunner

    from clearfast_gis.cli.main import group

    other = tmp_path / "notes"
    other.mkdir()
    (other / "keep.txt").write_text("x")
    runner = CliRunner()
    res = runner.invoke(group, ["simulate", str(other), "--overwrite", "--progress", "none"])
    assert res.exit_code == 1 and (other / "keep.txt").exists()
    assert "not a simulated survey" in res.output and len(res.output.strip().splitlines()) == 1
    bad = tmp_path / "s.json"
    bad.write_text('{"format": "clearfast-scenario", "format_version": 1, "n_scans": -1}')
    res = runner.invoke(group, ["simulate", str(tmp_path / "o"), "--scenario", str(bad)])
    assert res.exit_code == 1 and "n_scans" in res.output
    assert res.output.startswith("clearfast: error: ")


def test_cli_error_is_one_line(tmp_path):
    import subprocess
    import sys

    bad = tmp_path / "scenario.json"
    bad.write_text('{"format": "clearfast-scenario", "format_version": 1, '
                   '"objects": [{"kind": "bomb", "x_m": 1, "y_m": 1}]}')
    proc = subprocess.run([sys.executable, "-m", "clearfast_gis.cli.main", "simulate",
                           str(tmp_path / "out"), "--scenario", str(bad)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 1
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("clearfast: error: ") and "objects.0.kind: expected" in lines[0]
