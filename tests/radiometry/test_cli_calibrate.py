"""``clearfast calibrate`` on a small survey folder with physically consistent counts."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import tifffile

from clearfast_gis.radiometry import atmospheric_transmittance, observed_radiance
from clearfast_gis.radiometry.stage import band_table, weather_at
from clearfast_gis.survey import read_blackbody_log, read_survey, read_toa5, write_tiff_stack
from clearfast_gis.survey.testing import make_minimal_survey
from clearfast_gis.units import c_to_k


def run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "clearfast_gis.cli.main", *args],
                          capture_output=True, text=True, timeout=300)


@pytest.fixture(scope="module")
def survey_with_truth(tmp_path_factory) -> tuple[Path, dict]:
    """A 2-scan, 3-position, 2-band survey whose counts come from a known scene."""
    root = make_minimal_survey(tmp_path_factory.mktemp("cal") / "survey", n_scans=2,
                               n_positions=3, n_bands=2, width=16, height=12)
    srv = read_survey(root)
    rng = np.random.default_rng(11)
    h, w = 12, 16
    gain = {b: 400.0 * (1 + 0.2 * rng.uniform(-1, 1, (h, w))) for b in range(2)}
    offset = {b: 1000.0 + 300.0 * rng.uniform(-1, 1, (h, w)) for b in range(2)}
    log = read_blackbody_log(srv.path("blackbody_log"))
    weather = read_toa5(srv.path("weather"))
    bbf = srv.blackbody_frames
    truth = {}
    for b, info in enumerate(srv.bands):
        table = band_table(info.lambda_min_um, info.lambda_max_um)
        # blackbody frames: counts of each frame at the logged temperature at its time
        for f in np.unique(bbf.file[bbf.band == b]):
            rows = np.flatnonzero((bbf.file == f) & (bbf.band == b))
            rows = rows[np.argsort(bbf.page[rows])]
            pages = []
            for r in rows:
                col = log.bb1_c if bbf.blackbody[r] == 1 else log.bb2_c
                t_k = float(np.interp(bbf.time_s[r], log.time_s, c_to_k(col)))
                pages.append(gain[b] * table.radiance(t_k) + offset[b])
            write_tiff_stack(root / f, np.round(np.stack(pages)).astype(np.uint16))
        for s in srv.scans:
            rows = srv.scan_rows(s, b)
            t_true = rng.uniform(280.0, 300.0, (rows.size, h, w))
            air = weather_at(weather, srv.frames.time_s[rows])
            tau = atmospheric_transmittance(20.0, air.t_air_k, air.rh_pct, air.pressure_hpa,
                                            info.lambda_min_um, info.lambda_max_um)[:, None, None]
            rad = observed_radiance(table.radiance(t_true), tau, air.t_air_k[:, None, None],
                                    table)
            counts = np.round(gain[b] * rad + offset[b]).astype(np.uint16)
            write_tiff_stack(root / srv.frames.file[rows[0]], counts)
            truth[(int(s), b)] = t_true - 273.15
    return root, truth


def test_cli_writes_apparent_temperature_in_celsius(survey_with_truth, tmp_path):
    root, truth = survey_with_truth
    out = tmp_path / "products"
    r = run("calibrate", str(root), "-o", str(out), "--progress", "json")
    assert r.returncode == 0, r.stderr
    lines = [json.loads(x) for x in r.stdout.splitlines()]
    assert lines[-1]["event"] == "end" and lines[-1]["done"] == lines[-1]["total"] == 12
    for (s, b), t_c in truth.items():
        got = tifffile.imread(out / "apparent_temperature" / f"scan_{s:03d}_b{b}.tif")
        assert got.dtype == np.float32 and got.shape == t_c.shape
        # counts are rounded (~30 counts/K here), in the scene and the blackbody images
        err = got - t_c
        assert np.sqrt(np.mean(err**2)) < 0.015 and np.max(np.abs(err)) < 0.05
    summary = json.loads((out / "apparent_temperature" / "calibration.json").read_text())
    assert [e["n_events"] for e in summary["bands"]] == [2, 2]
    assert all(e["atmospheric_correction"] for e in summary["bands"])
    assert all(sc["invalid_pixels"] == 0 for sc in summary["scans"])

    # resume: nothing to redo; --band selects one band
    r = run("calibrate", str(root), "-o", str(out), "--progress", "json", "--band", "LW2")
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout.splitlines()[-1])["total"] == 0


def test_cli_nearest_mode_and_degenerate_pixels(survey_with_truth, tmp_path):
    root, _ = survey_with_truth
    out = tmp_path / "p"
    r = run("calibrate", str(root), "-o", str(out), "--progress", "none", "--mode", "nearest",
            "--min-contrast-counts", "1e6", "--band", "0")
    assert r.returncode == 0, r.stderr
    got = tifffile.imread(out / "apparent_temperature" / "scan_000_b0.tif")
    assert np.isnan(got).all()
    assert not (out / "apparent_temperature" / "scan_000_b1.tif").exists()


def test_cli_errors_are_one_line(survey_with_truth, tmp_path):
    root, _ = survey_with_truth
    r = run("calibrate", str(root), "-o", str(tmp_path / "x"), "--band", "NOPE")
    assert r.returncode == 1 and "Traceback" not in r.stderr
    assert "camera.bands" in r.stderr and len(r.stderr.strip().splitlines()) == 1
    broken = tmp_path / "broken"
    broken.mkdir()
    (broken / "survey.json").write_text("{}")
    r = run("calibrate", str(broken), "-o", str(tmp_path / "y"))
    assert r.returncode == 1 and "survey.json" in r.stderr and "Traceback" not in r.stderr
    r = run("calibrate", str(root), "-o", str(tmp_path / "z"), "--mode", "best")
    assert r.returncode == 2
