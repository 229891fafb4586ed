"""Mine-action export: stable ids, fields, WGS84 GeoPackage + CSV, command line."""

from __future__ import annotations

import csv
import io
import subprocess
import sys

import numpy as np
import pyogrio
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pyproj import Transformer

from clearfast_gis.errors import InvalidInput
from clearfast_gis.export import MINE_ACTION_FIELDS, export_mine_action, stable_ids
from clearfast_gis.export.mine_action import fix_label, survey_code


def test_stable_ids_order_by_position():
    ids = stable_ids("demo-seed0", [10.0, 5.0, 20.0, 5.004], [100.0, 100.0, 90.0, 100.0])
    # north first; on one northing west first; 5.004 rounds to the same cm as 5.0 -> tiebreak
    assert ids == ["CF-DEMO-SEED0-0003", "CF-DEMO-SEED0-0001", "CF-DEMO-SEED0-0004",
                   "CF-DEMO-SEED0-0002"]
    assert survey_code("  Site 4 / day_2 ") == "SITE-4-DAY-2"
    with pytest.raises(ValueError):
        survey_code("--")


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.floats(0, 1e6, allow_nan=False), st.floats(0, 1e7, allow_nan=False)),
                min_size=1, max_size=30, unique=True), st.randoms(use_true_random=False))
def test_stable_ids_independent_of_input_order(points, rnd):
    tags = [f"A{i:03d}" for i in range(len(points))]
    ids = dict(zip(tags, stable_ids("s", *zip(*points, strict=True), tiebreak=tags),
                   strict=True))
    order = list(range(len(points)))
    rnd.shuffle(order)
    shuffled = [points[i] for i in order]
    again = stable_ids("s", *zip(*shuffled, strict=True), tiebreak=[tags[i] for i in order])
    assert {tags[i]: again[k] for k, i in enumerate(order)} == ids
    assert sorted(ids.values()) == [f"CF-S-{k:04d}" for k in range(1, len(points) + 1)]


def test_fix_labels():
    assert fix_label(4) == "RTK fixed"
    assert fix_label(5) == "RTK float (degraded)"
    assert fix_label(None) == "unknown (degraded)"


def read_csv(path):
    return list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))


def test_export_fields_and_values(demo_products, tmp_path):
    from osgeo_utils.samples import validate_gpkg

    res = export_mine_action(demo_products.root, tmp_path / "ma", include_all=True)
    assert res.count == demo_products.n_suspects
    rows = read_csv(res.csv)
    assert list(rows[0]) == list(MINE_ACTION_FIELDS)
    suspects = pyogrio.read_dataframe(demo_products.root / "anomalies.gpkg", layer="suspects")
    by_src = {r["source_anomaly_id"]: r for r in rows}
    to_ll = Transformer.from_crs(32636, 4326, always_xy=True)
    for s in suspects.itertuples():
        r = by_src[s.anomaly_id]
        lon, lat = to_ll.transform(s.x, s.y)
        assert float(r["latitude_deg"]) == pytest.approx(lat, abs=1e-8)
        assert float(r["longitude_deg"]) == pytest.approx(lon, abs=1e-8)
        assert float(r["utm_easting_m"]) == pytest.approx(s.x, abs=1e-3)
        assert r["utm_epsg"] == "32636"
        assert (r["method"], r["evidence"], r["land_class"]) == (
            "stand-off thermal IR", "indirect", "indication")
        assert r["survey_date_utc"] == "2026-11-15T00:00:00Z"
        assert r["class_cue"] == s.class_cue and r["status"] == s.status
        if np.isnan(s.depth_m):
            assert r["depth_m"] == "" and r["depth_sigma_m"] == ""
        else:
            assert float(r["depth_m"]) == pytest.approx(s.depth_m, abs=1e-4)
        assert r["imsma_id"].startswith("CF-DEMO-SEED0-") and r["imsma_links"] == ""
        assert r["mine_indication"] == ("yes" if s.class_cue in ("at_mine", "ap_mine") else "no")
        assert r["cue_confidence"] == f"{s.cue_confidence:.3f}"
    assert by_src["A004"]["gnss_fix"] == "RTK float (degraded)"
    validate_gpkg.check(str(res.gpkg))
    frame = pyogrio.read_dataframe(res.gpkg, layer="indications")
    assert frame.crs.to_epsg() == 4326 and len(frame) == res.count
    np.testing.assert_allclose(frame.geometry.y, frame["latitude_deg"], atol=1e-12)
    from clearfast_gis.export import read_layer_styles

    assert "imsma_id" in read_layer_styles(res.gpkg)["indications"]


def test_export_is_reproducible(demo_products, tmp_path):
    export_mine_action(demo_products.root, tmp_path / "a")
    export_mine_action(demo_products.root, tmp_path / "b")
    for name in ("mine_action.csv", "hazard_proposals.csv", "surveyed_area.csv",
                 "mine_action.gpkg", "mine_action.xlsx"):
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes()


def test_export_errors(tmp_path, demo_products):
    with pytest.raises(InvalidInput, match="not a products folder"):
        export_mine_action(tmp_path)
    (tmp_path / "products.json").write_bytes(
        (demo_products.root / "products.json").read_bytes())
    with pytest.raises(InvalidInput, match="no anomalies.gpkg"):
        export_mine_action(tmp_path)


def cli(*args):
    return subprocess.run([sys.executable, "-m", "clearfast_gis.cli.main", *args],
                          capture_output=True, text=True, timeout=120)


def test_cli_export(demo_products, tmp_path):
    out = tmp_path / "out"
    r = cli("export", str(demo_products.root), "--mine-action", "-o", str(out),
            "--progress", "none")
    assert r.returncode == 0, r.stderr
    assert "4 indications, 1 hazard polygon proposals" in r.stdout
    assert (out / "mine_action.csv").is_file() and (out / "mine_action.gpkg").is_file()
    r = cli("export", str(demo_products.root), "-o", str(out))
    assert r.returncode == 2 and "--mine-action" in r.stderr
    r = cli("export", str(tmp_path / "out"), "--mine-action")
    assert r.returncode == 1 and "Traceback" not in r.stderr
    assert r.stderr.strip().endswith("products.json: missing: not a products folder")
    assert len(r.stderr.strip().splitlines()) == 1


def test_survey_date_normalised_and_checked(demo_products, tmp_path):
    import json
    import shutil

    folder = tmp_path / "p"
    shutil.copytree(demo_products.root, folder)
    doc = json.loads((folder / "products.json").read_text())
    doc["time"]["start_utc"] = "2026-11-15T00:00:00.000Z"
    (folder / "products.json").write_text(json.dumps(doc))
    res = export_mine_action(folder)
    assert res.csv == folder / "mine_action" / "mine_action.csv"
    assert {r["survey_date_utc"] for r in read_csv(res.csv)} == {"2026-11-15T00:00:00Z"}
    doc["time"]["start_utc"] = "noon"
    (folder / "products.json").write_text(json.dumps(doc))
    with pytest.raises(InvalidInput) as err:
        export_mine_action(folder)
    assert err.value.field == "time.start_utc"
