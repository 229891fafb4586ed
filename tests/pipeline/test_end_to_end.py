"""The whole chain on the simulated demo survey, checked against its ground truth."""

from __future__ import annotations

import json
import warnings

import numpy as np
import pytest
import rasterio
from rasterio.warp import Resampling, reproject

from clearfast_gis.evaluation.truth import read_truth_objects, score_against_truth


def truth_on_mosaic_grid(survey, products, scan: int):
    name = f"scan_{scan:03d}.tif"
    with rasterio.open(products / "mosaics" / name) as m, \
            rasterio.open(survey / "truth" / "apparent_temperature" / name) as t:
        mosaic = m.read(1)
        truth = np.full(mosaic.shape, np.nan, np.float32)
        reproject(t.read(1), truth, src_transform=t.transform, src_crs=t.crs,
                  dst_transform=m.transform, dst_crs=m.crs, resampling=Resampling.average,
                  src_nodata=np.nan, dst_nodata=np.nan)
    return mosaic, truth


def block_mean(a: np.ndarray, k: int) -> np.ndarray:
    h, w = (a.shape[0] // k) * k, (a.shape[1] // k) * k
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return np.nanmean(a[:h, :w].reshape(h // k, k, w // k, k), axis=(1, 3))


def test_products_layout(demo_products):
    manifest = json.loads((demo_products / "products.json").read_text())
    assert manifest["crs"]["epsg"] == 32636
    assert len(manifest["scans"]) == 6
    for s in manifest["scans"]:
        assert (demo_products / s["file"]).is_file()
    assert (demo_products / "anomalies.gpkg").is_file()
    assert (demo_products / "report.html").is_file()
    assert (demo_products / "figures" / "overview.png").is_file()
    assert set(manifest["timings_s"]) >= {"mosaics", "detection", "characterisation", "total"}
    import pyogrio

    fp = pyogrio.read_dataframe(demo_products / "footprint.geojson")
    assert fp.crs.to_epsg() == 32636 and len(fp) == 1
    assert fp.geometry.iloc[0].area > 30.0  # m2
    for s in manifest["scans"]:
        assert len(s["attitude"]["attitude_rpy_deg"]) == 3


def test_mosaics_are_valid_cogs_in_degrees_c(demo_products):
    from osgeo_utils.samples.validate_cloud_optimized_geotiff import validate

    for path in sorted((demo_products / "mosaics").glob("scan_*.tif")):
        warnings_, errors, _ = validate(str(path), full_check=True)
        assert errors == [], (path.name, errors)
        with rasterio.open(path) as ds:
            assert ds.crs.to_epsg() == 32636
            assert ds.dtypes == ("float32", "float32")
            assert all("um" in d for d in ds.descriptions)
            assert ds.tags().get("CLEARFAST_SCAN_TIME_UTC", "").endswith("Z")
            values = ds.read(1)
            ok = np.isfinite(values)
            assert ok.mean() > 0.5
            assert -10 < np.median(values[ok]) < 45  # degrees C, not kelvin


def test_mosaics_match_true_apparent_temperature(demo_survey, demo_products):
    """Issue #6: the mosaic of every scan agrees with the truth over the footprint."""
    assert_mosaics_match_truth(demo_survey, demo_products, 6)


def assert_mosaics_match_truth(truth_folder, products, n_scans: int) -> None:
    """The demo's accuracy targets for the mosaics of ``products`` against the apparent
    temperature in ``truth_folder/truth``."""
    for scan in range(n_scans):
        mosaic, truth = truth_on_mosaic_grid(truth_folder, products, scan)
        ok = np.isfinite(mosaic) & np.isfinite(truth)
        assert ok.sum() > 0.5 * ok.size
        err = mosaic[ok] - truth[ok]
        assert abs(err.mean()) < 0.05, scan
        # at the mosaic's own 1.4 cm cells the truth is sharper than the 160x128 camera sees:
        assert np.sqrt(np.mean(err**2)) < 0.4, scan
        # at the camera's ground resolution (~5 cm) the agreement is within 0.3 K
        mb = block_mean(np.where(ok, mosaic, np.nan), 4)
        tb = block_mean(np.where(ok, truth, np.nan), 4)
        both = np.isfinite(mb) & np.isfinite(tb)
        assert np.sqrt(np.mean((mb[both] - tb[both]) ** 2)) < 0.3, scan


def test_markers_found_at_their_surveyed_positions(demo_products):
    manifest = json.loads((demo_products / "products.json").read_text())
    # the hot and the cold plate of the demo stand out at least at midday
    assert manifest["markers"]["found"] >= 1
    assert manifest["markers"]["rms_offset_m"] < 0.03


def test_scan_to_scan_residual(demo_products):
    manifest = json.loads((demo_products / "products.json").read_text())
    residuals = [s["residual_px"] for s in manifest["scans"][1:]
                 if s["residual_px"] is not None]
    assert residuals, "no residual could be measured"
    assert max(residuals) <= 0.5


def test_mines_found_and_characterised(demo_survey, demo_products):
    import geopandas as gpd

    score = score_against_truth(demo_survey, demo_products)
    # demo: 6 scans only; the accuracy over many trial-size surveys is in BENCHMARKS.md
    assert score.n_detected >= 4, score.summary()
    assert np.sqrt(np.mean(np.square(score.centre_errors_m))) < 0.05, score.summary()
    sus = gpd.read_file(demo_products / "anomalies.gpkg", layer="suspects")
    truth = read_truth_objects(demo_survey)
    for at in [t for t in truth if t["kind"] == "at_mine" and t["depth_m"] == 0.0]:
        d = np.hypot(sus["x"] - at["x"], sus["y"] - at["y"])
        j = int(np.argmin(d))
        assert d[j] < 0.05
        # surface-laid AT mines come out at depth 0 (the paper's chain failed here)
        assert sus["depth_m"].iloc[j] == pytest.approx(0.0, abs=0.01)
        assert sus["class_cue"].iloc[j] == "at_mine"
        assert abs(sus["diameter_m"].iloc[j] / at["diameter_m"] - 1) < 0.25


def test_geopackage_layers_and_styles(demo_products):
    import sqlite3

    import pyogrio

    layers = {name for name, _ in pyogrio.list_layers(demo_products / "anomalies.gpkg")}
    assert {"anomalies", "suspects", "markers", "footprint"} <= layers
    with sqlite3.connect(demo_products / "anomalies.gpkg") as db:
        styled = {r[0] for r in db.execute("SELECT f_table_name FROM layer_styles "
                                           "WHERE useAsDefault")}
    assert {"anomalies", "suspects", "markers", "footprint"} <= styled


def test_resume_recomputes_nothing(demo_survey, demo_products, tmp_path):
    import shutil

    from clearfast_gis.pipeline import process_survey

    copy = tmp_path / "products"
    shutil.copytree(demo_products, copy)
    before = {p.name: p.stat().st_mtime_ns for p in (copy / "mosaics").glob("*.tif")}
    manifest = process_survey(demo_survey, copy)
    after = {p.name: p.stat().st_mtime_ns for p in (copy / "mosaics").glob("*.tif")}
    assert before == after
    assert manifest["timings_s"]["mosaics"] < 2.0


def test_drifting_lift_is_followed(demo_drift_mosaics):
    """Issue #6 / paper §6: the lift sinks 2 m and tilts by degrees over 24 h; the attitude
    fitted per scan from MI ties and markers puts every mosaic back on the ground truth."""
    survey, products = demo_drift_mosaics
    state = json.loads((products / ".clearfast" / "state.json").read_text())
    truth = {}
    import csv

    with open(survey / "truth" / "poses.csv") as fh:
        for row in csv.DictReader(fh):
            truth.setdefault(int(row["scan"]), []).append(
                [float(row[k]) for k in ("roll_deg", "pitch_deg", "yaw_deg")])
    for scan in range(6):
        unit = state["units"][f"mosaics/scan_{scan:03d}"]
        fitted = np.array(unit["attitude"]["attitude_rpy_deg"])
        true = np.mean(truth[scan], axis=0)
        # roll and yaw trade off a little against each other over a narrow view (a few
        # tenths of a degree); the mosaics below are the real check of the placement
        assert np.all(np.abs(fitted - true) < 0.5), (scan, fitted, true)
    # the drift of the last scan is degrees: without the fit the mosaic would be metres off
    assert np.max(np.abs(np.mean(truth[5], axis=0))) > 2.0
    rms = []
    for scan in range(6):
        mosaic, tru = truth_on_mosaic_grid(survey, products, scan)
        ok = np.isfinite(mosaic) & np.isfinite(tru)
        mb = block_mean(np.where(ok, mosaic, np.nan), 4)
        tb = block_mean(np.where(ok, tru, np.nan), 4)
        both = np.isfinite(mb) & np.isfinite(tb)
        rms.append(np.sqrt(np.mean((mb[both] - tb[both]) ** 2)))
    # the first night scans see one marker only and are placed from their successors: the
    # demo's 4-hour steps leave them a little worse than the rest (the 48-scan trial is not)
    assert max(rms) < 0.4, rms
    assert np.median(rms) < 0.2, rms


def test_resources_per_stage(demo_products):
    """products.json records wall time, CPU time and peak memory of every stage."""
    res = json.loads((demo_products / "products.json").read_text())["resources"]
    assert res["kernels"] == "fast"
    for st in ("read_and_validate", "band_coregistration", "mosaics", "detection",
               "characterisation", "products"):
        r = res["stages"][st]
        assert r["wall_s"] > 0 and r["cpu_s"] > 0, st
        assert 50 < r["peak_rss_mb"] < 4096, st  # MiB
    walls = sum(r["wall_s"] for r in res["stages"].values())
    assert walls <= res["total"]["wall_s"] * 1.001
    assert res["total"]["peak_rss_mb"] == max(r["peak_rss_mb"] for r in res["stages"].values())


def test_suspects_ranked_and_candidates_set_aside(demo_survey, demo_products):
    """Issue #21: suspects in priority order by p_mine, what cannot be a mine set aside with
    its reason, the expected operating curve in products.json, no shallow mine set aside."""
    import geopandas as gpd

    from clearfast_gis.detection.likelihood import load_model
    from clearfast_gis.evaluation.ranked import score_ranked

    gpkg = demo_products / "anomalies.gpkg"
    sus = gpd.read_file(gpkg, layer="suspects")
    cand = gpd.read_file(gpkg, layer="candidates")
    assert sus["priority"].tolist() == list(range(1, len(sus) + 1))
    p = sus["p_mine"].to_numpy(float)
    assert np.all((p >= 0) & (p <= 1)) and np.all(np.diff(p) <= 0)
    assert sus["set_aside_reason"].isna().all()
    assert len(cand) > 0 and cand["p_mine"].isna().all() and cand["priority"].isna().all()
    assert all(isinstance(r, str) and r for r in cand["set_aside_reason"])
    curve = json.loads((demo_products / "products.json").read_text())["suspects"]
    assert curve["n_suspects"] == len(sus) and curve["n_candidates"] == len(cand)
    oc = curve["operating_curve"]
    assert oc["priority"] == list(range(1, len(sus) + 1))
    assert oc["expected_mines"][-1] == pytest.approx(p.sum(), abs=0.01)
    score = score_ranked(demo_survey, demo_products)
    assert score.n_candidate_mines == 0
    # screened and ranked again from the anomalies layer under the same model: the same list
    again = score_ranked(demo_survey, demo_products, load_model())
    assert np.array_equal(again.p_mine, score.p_mine)
    assert np.array_equal(again.is_mine, score.is_mine) and again.n_candidates == len(cand)
    # the mines come first: every detected mine <= 5 cm before the list's expected false
    # alarms reach a handful (demo: 48 m2, 6 scans)
    assert score.pd_at(0.1) >= score.pd[-1] - 1e-9
    html = (demo_products / "report.html").read_text()
    assert "Operating curve" in html and "figures/operating_curve.png" in html
    assert (demo_products / "figures" / "operating_curve.png").is_file()


def test_p_mine_is_calibrated_on_a_survey_it_was_not_fitted_on(demo_survey, demo_products):
    """The demo survey (seed 0) is not among the model's ``fitted_on`` surveys: the expected
    number of mines (sum of p_mine) agrees with the true count within 3 sigma of the
    Poisson-binomial spread, and p_mine predicts better than the base rate (Brier score)."""
    from clearfast_gis.detection.likelihood import load_model
    from clearfast_gis.evaluation.ranked import score_ranked

    assert not any(t.startswith("demo-s0") for t in load_model()["fitted_on"])
    s = score_ranked(demo_survey, demo_products)
    p, y = s.p_mine, s.is_mine.astype(float)
    assert y.sum() >= 4
    assert abs(p.sum() - y.sum()) <= 3 * np.sqrt(np.sum(p * (1 - p))), (p.sum(), y.sum())
    assert np.mean((p - y) ** 2) < 0.75 * np.mean((y.mean() - y) ** 2)
    # every mine at most 5 cm deep is found before the list's third false alarm
    assert s.pd_at(3 / s.footprint_m2) == 1.0
