"""Hazard polygon proposals, geometry and field-name checks, and the IMSMA Core export."""

from __future__ import annotations

import csv
import io
import math
import shutil

import numpy as np
import pyogrio
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.export import default_styles, export_mine_action, write_geopackage
from clearfast_gis.export.hazard_areas import (
    DEFAULT_BUFFER_M,
    MAX_FIELD_NAME,
    QUAD_SEGMENTS,
    check_field_names,
    check_geometries,
    hazard_clusters,
)

GON_AREA = 0.5 * 4 * QUAD_SEGMENTS * math.sin(2 * math.pi / (4 * QUAD_SEGMENTS))
"""Area of the buffer polygon of a point, in units of r² (a 32-gon inscribed in the circle)."""


def test_clusters_join_overlapping_discs_only():
    # two indications 6 m apart (discs of 5 m overlap), one 30 m away
    clusters = hazard_clusters([0.0, 6.0, 0.0], [0.0, 0.0, -30.0], 5.0)
    assert [members for _, members in clusters] == [[0, 1], [2]]  # north first
    single = clusters[1][0]
    assert single.area == pytest.approx(GON_AREA * 25.0, rel=1e-9)
    assert single.centroid.x == pytest.approx(0.0, abs=1e-9)
    pair = clusters[0][0]
    assert single.area < pair.area < 2 * single.area  # the two discs overlap
    assert hazard_clusters([], [], 5.0) == []
    with pytest.raises(ValueError):
        hazard_clusters([0.0], [0.0], 0.0)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.floats(-50, 50), st.floats(-50, 50)), min_size=1, max_size=15),
       st.floats(0.5, 10.0))
def test_clusters_partition_the_points_and_cover_them(points, buffer_m):
    e, n = (np.array(v) for v in zip(*points, strict=True))
    clusters = hazard_clusters(e, n, buffer_m)
    members = sorted(i for _, m in clusters for i in m)
    assert members == list(range(len(points)))  # every point in exactly one cluster
    for poly, idx in clusters:
        assert poly.is_valid and poly.geom_type == "Polygon"
        for i in idx:  # the whole disc (its inscribed polygon) around each point is inside
            assert poly.buffer(1e-6).covers(shapely.Point(e[i], n[i]).buffer(
                buffer_m * 0.99, quad_segs=QUAD_SEGMENTS))
    for k, (pa, _) in enumerate(clusters):  # clusters do not overlap (discs may just touch)
        for pb, _ in clusters[k + 1:]:
            assert pa.intersection(pb).area == pytest.approx(0.0, abs=1e-9)


def test_geometry_checks_name_the_record():
    good = shapely.Polygon([(0, 0), (1, 0), (1, 1), (0, 1)])
    check_geometries([good, shapely.Point(1, 2)], ["CF-A-H01", "CF-A-0001"], "x.gpkg", "l")
    bad = {
        "invalid polygon": shapely.Polygon([(0, 0), (1, 1), (1, 0), (0, 1)]),  # bow tie
        "fewer than 3 vertices": shapely.Polygon([(0, 0), (1, 0), (0, 0), (0, 0)]),
        "repeated vertex": shapely.Polygon([(0, 0), (1, 0), (1, 0), (1, 1), (0, 1)]),
        "empty geometry": shapely.Polygon(),
        "non-finite": shapely.Point(math.nan, 0.0),
    }
    for problem, geom in bad.items():
        with pytest.raises(InvalidInput, match=problem) as err:
            check_geometries([geom], ["CF-A-H02"], "x.gpkg", "hazard_proposals")
        assert err.value.field == "hazard_proposals.CF-A-H02"


def test_field_name_checks():
    check_field_names(["imsma_id", "a" * MAX_FIELD_NAME], "x.gpkg", "l")
    for name in ("a" * (MAX_FIELD_NAME + 1), "Imsma_ID", "two words"):
        with pytest.raises(InvalidInput) as err:
            check_field_names([name], "x.gpkg", "l")
        assert err.value.field == f"l.{name}"


def _csv(path):
    return list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))


def _assert_ready_for_imsma(res):
    """The GeoPackage layers and the CSVs pass the geometry and field-name checks."""
    for layer in ("indications", "hazard_proposals", "surveyed_area"):
        frame = pyogrio.read_dataframe(res.gpkg, layer=layer)
        assert frame.crs.to_epsg() == 4326
        names = [c for c in frame.columns if c != "geometry"]
        assert all(len(c) <= MAX_FIELD_NAME for c in names) and names[:2] == [
            "imsma_id", "imsma_links"]
        assert (frame["imsma_links"].fillna("") == "").all()
        check_geometries(list(frame.geometry), list(frame["imsma_id"]), res.gpkg, layer)
    for path in (res.csv, res.hazard_csv, res.area_csv):
        header = path.read_text(encoding="utf-8").splitlines()[0].split(",")
        assert all(len(c) <= MAX_FIELD_NAME for c in header) and header[0] == "imsma_id"
    for row in _csv(res.hazard_csv) + _csv(res.area_csv):
        poly = shapely.from_wkt(row["wkt"])
        check_geometries([poly], [row["imsma_id"]], res.hazard_csv, "csv")
    # the workbook holds the same three tables, numbers as numbers
    from openpyxl import load_workbook

    book = load_workbook(res.xlsx, read_only=True)
    assert book.sheetnames == ["evidence", "hazard_proposals", "surveyed_area"]
    for sheet, path in zip(book.sheetnames, (res.csv, res.hazard_csv, res.area_csv),
                           strict=True):
        rows = list(book[sheet].iter_rows(values_only=True))
        table = _csv(path)
        assert list(rows[0]) == list(table[0]) if table else True
        assert len(rows) - 1 == len(table)
        for got, want in zip(rows[1:], table, strict=True):
            for value, (name, text) in zip(got, want.items(), strict=True):
                if text == "":
                    assert value is None, name
                elif isinstance(value, str):
                    assert value == text, name
                else:
                    assert value == pytest.approx(float(text), abs=1e-8), name


def test_export_cue_based_surveyed_area_and_proposals(demo_products, tmp_path):
    res = export_mine_action(demo_products.root, tmp_path / "ma", organisation="MAG test")
    _assert_ready_for_imsma(res)
    evidence = _csv(res.csv)
    # the AT/AP cues (A001-A004) without p_mine; clutter and unknown left out
    assert len(evidence) == res.count == 4
    assert {r["class_cue"] for r in evidence} == {"at_mine", "ap_mine"}
    hazards = pyogrio.read_dataframe(res.gpkg, layer="hazard_proposals")
    area = pyogrio.read_dataframe(res.gpkg, layer="surveyed_area")
    assert len(area) == 1 and area["imsma_id"][0] == "CF-DEMO-SEED0-SA"
    assert area["organisation"][0] == "MAG test" and area["n_suspects"][0] == 8
    assert area["survey_end_utc"][0] == "2026-11-16T00:00:00Z"
    assert len(hazards) == res.hazard_proposals >= 1
    # every evidence point lies in its proposal, and the links agree both ways
    points = pyogrio.read_dataframe(res.gpkg, layer="indications")
    by_id = dict(zip(hazards["imsma_id"], hazards.geometry, strict=True))
    for row in points.itertuples():
        assert by_id[row.hazard_ref].covers(row.geometry)
        assert area.geometry[0].buffer(1e-7).covers(row.geometry)
    for h in hazards.itertuples():
        linked = sorted(points["imsma_id"][points["hazard_ref"] == h.imsma_id])
        assert h.evidence_ids.split(",") == linked and h.n_indications == len(linked)
        assert h.buffer_m == DEFAULT_BUFFER_M
    assert hazards["area_m2"].sum() >= GON_AREA * DEFAULT_BUFFER_M ** 2 * 0.999


def test_export_with_likelihood_threshold_and_all(demo_products, tmp_path):
    root = tmp_path / "ranked"
    shutil.copytree(demo_products.root, root)
    gpkg = root / "anomalies.gpkg"
    layers = {n: pyogrio.read_dataframe(gpkg, layer=n)
              for n in ("anomalies", "suspects", "markers", "footprint")}
    s = layers["suspects"].rename(columns={"confidence": "cue_confidence"})
    s["p_mine"] = np.linspace(0.95, 0.05, len(s))  # A001 0.95 ... A008 0.05
    s["priority"] = np.arange(1, len(s) + 1)
    layers["suspects"] = s
    write_geopackage(gpkg, layers, default_styles(layers))
    res = export_mine_action(root, tmp_path / "a", min_likelihood=0.65)
    rows = _csv(res.csv)
    assert sorted(r["source_anomaly_id"] for r in rows) == ["A001", "A002", "A003"]
    assert {r["mine_likelihood"] for r in rows} >= {"0.950"}
    assert sorted(r["priority"] for r in rows) == ["1", "2", "3"]
    _assert_ready_for_imsma(res)
    every = export_mine_action(root, tmp_path / "b", min_likelihood=0.65, include_all=True,
                               buffer_m=2.0)
    rows = _csv(every.csv)
    assert len(rows) == 8
    assert sum(r["mine_indication"] == "yes" for r in rows) == 3
    # only mine indications are evidence of a proposal
    assert all((r["hazard_ref"] == "") == (r["mine_indication"] == "no") for r in rows)
    with pytest.raises(InvalidInput):
        export_mine_action(root, tmp_path / "c", buffer_m=-1.0)
    assert not (tmp_path / "c").exists()


def test_workbook_bytes_do_not_depend_on_the_clock():
    import time

    import pandas as pd

    from clearfast_gis.export.xlsx import workbook_bytes

    table = pd.DataFrame({"imsma_id": ["CF-A-0001", "CF-A-0002"], "depth_m": [0.0123456, None],
                          "n": [3, 4]})
    sheets = {"evidence": (table, ["imsma_id", "depth_m", "n"])}
    first = workbook_bytes(sheets, {"depth_m": 4}, 1794787200.0)
    time.sleep(1.1)  # a later second of the wall clock
    assert workbook_bytes(sheets, {"depth_m": 4}, 1794787200.0) == first
    from openpyxl import load_workbook

    rows = list(load_workbook(io.BytesIO(first)).active.iter_rows(values_only=True))
    assert rows == [("imsma_id", "depth_m", "n"), ("CF-A-0001", 0.0123, 3), ("CF-A-0002", None, 4)]
