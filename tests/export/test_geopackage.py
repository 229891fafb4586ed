"""GeoPackage writer: GDAL's validator, QGIS's layer_styles table, round trips."""

from __future__ import annotations

import sqlite3

import geopandas as gpd
import pyogrio
import pytest
import shapely

from clearfast_gis.errors import InvalidInput
from clearfast_gis.export import default_styles, read_layer_styles, write_geopackage

QGIS_COLUMNS = ["id", "f_table_catalog", "f_table_schema", "f_table_name", "f_geometry_column",
                "styleName", "styleQML", "styleSLD", "useAsDefault", "description", "owner",
                "ui", "update_time"]


def layers():
    pts = gpd.GeoDataFrame({"marker_id": ["M1", "M2"], "description": ["a", "b"]},
                           geometry=[shapely.Point(532780, 3891955),
                                     shapely.Point(532790, 3891960)],
                           crs=32636)
    poly = gpd.GeoDataFrame({"scans": [3]}, geometry=[shapely.box(532780, 3891955, 532800,
                                                                  3891985)], crs=32636)
    return {"markers": pts, "footprint": poly}


def test_valid_gpkg_with_qgis_layer_styles(tmp_path):
    from osgeo_utils.samples import validate_gpkg

    path = tmp_path / "anomalies.gpkg"
    styles = {k: v for k, v in default_styles().items() if k in ("markers", "footprint")}
    write_geopackage(path, layers(), styles)
    validate_gpkg.check(str(path))  # raises on any violation of the GeoPackage spec
    with sqlite3.connect(path) as con:
        cols = [r[1] for r in con.execute("PRAGMA table_info(layer_styles)")]
        rows = con.execute("SELECT f_table_catalog, f_table_schema, f_table_name, "
                           "f_geometry_column, styleName, useAsDefault FROM layer_styles "
                           "ORDER BY f_table_name").fetchall()
        contents = dict(con.execute("SELECT table_name, data_type FROM gpkg_contents"))
        version = con.execute("PRAGMA user_version").fetchone()[0]
    assert cols == QGIS_COLUMNS
    assert rows == [("", "", "footprint", "geom", "default", 1),
                    ("", "", "markers", "geom", "default", 1)]
    assert contents == {"markers": "features", "footprint": "features",
                        "layer_styles": "attributes"}
    assert version == 10200
    assert read_layer_styles(path) == styles


def test_round_trip_layers_and_fid(tmp_path):
    path = tmp_path / "a.gpkg"
    write_geopackage(path, layers())
    names = [n for n, _ in pyogrio.list_layers(path)]
    assert names == ["markers", "footprint"]
    back = pyogrio.read_dataframe(path, layer="markers", fid_as_index=True)
    assert list(back.index) == [1, 2] and list(back["marker_id"]) == ["M1", "M2"]
    assert back.crs.to_epsg() == 32636
    assert pyogrio.read_info(path, layer="footprint")["geometry_type"] == "Polygon"
    assert read_layer_styles(path) == {}


def test_same_layers_same_bytes(tmp_path):
    """GDAL's writer left a varying number of transactions in the SQLite header's change
    counter (about 1 write in 5 differed in bytes 24-27 and 92-95); the compact copy is a pure
    function of the content, and still a valid GeoPackage."""
    from osgeo_utils.samples import validate_gpkg

    styles = {k: v for k, v in default_styles().items() if k in ("markers", "footprint")}
    paths = [tmp_path / f"w{i}.gpkg" for i in range(12)]
    for path in paths:
        write_geopackage(path, layers(), styles, timestamp_s=1.8e9)
    first = paths[0].read_bytes()
    assert [p.name for p in paths if p.read_bytes() != first] == []
    validate_gpkg.check(str(paths[0]))
    with sqlite3.connect(paths[0]) as con:
        assert con.execute("PRAGMA application_id").fetchone()[0] == 0x47504B47  # "GPKG"


def test_rewrite_replaces_file_atomically(tmp_path):
    path = tmp_path / "a.gpkg"
    write_geopackage(path, layers())
    one = {"markers": layers()["markers"].iloc[:1]}
    write_geopackage(path, one, {"markers": "<qgis/>"})
    assert [n for n, _ in pyogrio.list_layers(path)] == ["markers", "layer_styles"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.gpkg"]


@pytest.mark.parametrize(("lays", "styles", "field"), [
    ({"Suspects": layers()["markers"]}, None, "Suspects"),
    ({"markers": layers()["markers"].set_crs(None, allow_override=True)}, None, "markers"),
    ({"markers": layers()["markers"]}, {"footprint": "<qgis/>"}, "footprint"),
])
def test_bad_layers_rejected(tmp_path, lays, styles, field):
    with pytest.raises(InvalidInput) as err:
        write_geopackage(tmp_path / "x.gpkg", lays, styles)
    assert err.value.field == field
    assert not list(tmp_path.iterdir())
