"""Byte-identical products for identical content: the GeoPackage's timestamps."""

from __future__ import annotations

import sqlite3
import time

import geopandas as gpd
from shapely.geometry import Point

from clearfast_gis.export import default_styles, write_geopackage
from clearfast_gis.timeutil import parse_utc


def _layers():
    crs = "EPSG:32636"
    return {"markers": gpd.GeoDataFrame({"marker_id": ["M1", "M2"], "description": ["a", "b"]},
                                        geometry=[Point(500000, 3890000),
                                                  Point(500001, 3890002)], crs=crs)}


def test_geopackage_with_a_fixed_timestamp_is_byte_identical(tmp_path):
    stamp = parse_utc("2026-11-16T00:00:00Z")
    styles = {k: v for k, v in default_styles().items() if k == "markers"}
    a = write_geopackage(tmp_path / "a.gpkg", _layers(), styles, timestamp_s=stamp)
    time.sleep(0.05)  # a different wall clock
    b = write_geopackage(tmp_path / "b.gpkg", _layers(), styles, timestamp_s=stamp)
    assert open(a, "rb").read() == open(b, "rb").read()
    con = sqlite3.connect(a)
    try:
        changes = {r[0] for r in con.execute("SELECT last_change FROM gpkg_contents")}
        updates = {r[0] for r in con.execute("SELECT update_time FROM layer_styles")}
    finally:
        con.close()
    assert changes == updates == {"2026-11-16T00:00:00.000Z"}
