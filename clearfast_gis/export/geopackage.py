"""GeoPackage products with default QGIS styles embedded in the ``layer_styles`` table.

Layers are written with pyogrio (GeoPackage 1.2, readable by every GDAL in the field); the
``layer_styles`` table is then added with sqlite3 using the exact table definition QGIS itself
creates, so QGIS applies the styles when it opens the layers. The whole file is written under a
temporary name and renamed at the end.
"""

from __future__ import annotations

import os
import re
import shutil
import sqlite3
import tempfile
from collections.abc import Mapping
from pathlib import Path

from clearfast_gis.atomic import atomic_path
from clearfast_gis.errors import InvalidInput

GPKG_VERSION = "1.2"
"""GeoPackage version written (QGIS 3.22 with GDAL 3.6 reads it without warnings)."""

GEOMETRY_COLUMN = "geom"

_LAYER_STYLES_DDL = (
    'CREATE TABLE IF NOT EXISTS "layer_styles" ( '
    '"id" INTEGER PRIMARY KEY AUTOINCREMENT NOT NULL, "f_table_catalog" TEXT(256), '
    '"f_table_schema" TEXT(256), "f_table_name" TEXT(256), "f_geometry_column" TEXT(256), '
    '"styleName" TEXT(30), "styleQML" TEXT, "styleSLD" TEXT, "useAsDefault" BOOLEAN, '
    '"description" TEXT, "owner" TEXT(30), "ui" TEXT(30), '
    "\"update_time\" DATETIME DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now')))"
)

_LAYER_NAME = re.compile(r"^[a-z][a-z0-9_]*$")


def write_geopackage(
    path: str | os.PathLike,
    layers: Mapping[str, object],
    styles: Mapping[str, str] | None = None,
    style_name: str = "default",
    timestamp_s: float | None = None,
) -> str:
    """Write GeoDataFrames as layers of one GeoPackage, with default styles, atomically.

    Parameters
    ----------
    path : path
        Output ``.gpkg``; replaced if it exists.
    layers : mapping of str to geopandas.GeoDataFrame
        Layer name (lower-case snake_case) -> features. Each frame needs a CRS. Layers are
        written in the mapping's order; every layer gets an integer ``fid`` primary key.
    styles : mapping of str to str, optional
        Layer name -> QML text stored as that layer's default style in ``layer_styles``.
    style_name : str
        ``styleName`` of the stored styles.
    timestamp_s : float, optional
        UTC epoch seconds written as every table's ``gpkg_contents.last_change`` and every
        style's ``update_time``; with it, the same layers give a byte-identical file (a
        re-run reproduces its products exactly). Default: the time of writing.

    Returns
    -------
    str
        The final path.
    """
    import pyogrio

    styles = dict(styles or {})
    if not layers:
        raise InvalidInput("no layers to write", path)
    for name, frame in layers.items():
        if not _LAYER_NAME.match(name):
            raise InvalidInput("layer names must be lower-case snake_case", path, name)
        if getattr(frame, "crs", None) is None:
            raise InvalidInput("the layer has no CRS", path, name)
    unknown = sorted(set(styles) - set(layers))
    if unknown:
        raise InvalidInput("style for a layer that is not written", path, unknown[0])
    with atomic_path(path) as tmp, tempfile.TemporaryDirectory(prefix="clearfast-gpkg-") as d:
        # built in a scratch folder (GDAL wants the .gpkg extension and, on a full disk,
        # reports sqlite errors rather than the OS error), then copied onto the temporary
        # name: a full destination disk surfaces as an OSError that atomic_path reports.
        work = Path(d) / "layers.gpkg"
        for name, frame in layers.items():
            pyogrio.write_dataframe(
                frame, work, layer=name, driver="GPKG", append=work.exists(),
                geometry_type=_geometry_type(frame), promote_to_multi=False,
                dataset_options={"VERSION": GPKG_VERSION}, layer_options={"FID": "fid"},
            )
        if styles:
            add_layer_styles(work, styles, style_name=style_name)
        if timestamp_s is not None:
            set_timestamps(work, timestamp_s)
        final = Path(d) / "final.gpkg"
        compact_copy(work, final)
        shutil.copyfile(final, tmp)
    return os.fspath(path)


def compact_copy(src: str | os.PathLike, dst: str | os.PathLike) -> None:
    """Copy a GeoPackage to a new file with SQLite's ``VACUUM INTO``: the same content in
    fresh pages, with a header that depends on nothing but the content.

    GDAL's writer leaves a varying number of transactions behind (the header's file change
    counter differed in about 1 write in 5 of the same layers), so two writes of one content
    were not byte-identical; the copy is, and it keeps the GeoPackage's ``application_id``
    and ``user_version``.
    """
    con = sqlite3.connect(os.fspath(src))
    try:
        con.execute("VACUUM INTO ?", (os.fspath(dst),))
    finally:
        con.close()


def set_timestamps(path: str | os.PathLike, timestamp_s: float) -> None:
    """Set ``gpkg_contents.last_change`` (and ``layer_styles.update_time``) to one instant.

    GDAL and SQLite stamp these with the wall clock; a fixed instant (e.g. the survey's end)
    makes the file a pure function of its content.
    """
    from clearfast_gis.timeutil import format_utc

    stamp = format_utc(float(timestamp_s), timespec="milliseconds")
    with sqlite3.connect(os.fspath(path)) as con:
        con.execute("UPDATE gpkg_contents SET last_change = ?", (stamp,))
        has_styles = con.execute(
            "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'layer_styles'"
        ).fetchone()
        if has_styles is not None:
            con.execute("UPDATE layer_styles SET update_time = ?", (stamp,))
    con.close()


def _geometry_type(frame) -> str | None:
    types = sorted({t for t in frame.geometry.geom_type.dropna().unique()})
    if len(types) == 1:
        return types[0]
    if not types:
        return "Unknown"
    return None


def add_layer_styles(path: str | os.PathLike, styles: Mapping[str, str],
                     style_name: str = "default") -> None:
    """Store QML styles as the default styles of layers of an existing GeoPackage.

    Creates the ``layer_styles`` table (QGIS's definition) and registers it in
    ``gpkg_contents`` as an attributes table when missing; replaces earlier default styles of
    the same layers.
    """
    with sqlite3.connect(os.fspath(path)) as con:
        con.execute(_LAYER_STYLES_DDL)
        registered = con.execute(
            "SELECT 1 FROM gpkg_contents WHERE table_name = 'layer_styles'").fetchone()
        if registered is None:
            con.execute(
                "INSERT INTO gpkg_contents (table_name, data_type, identifier, description, "
                "last_change, srs_id) VALUES ('layer_styles', 'attributes', 'layer_styles', '', "
                "strftime('%Y-%m-%dT%H:%M:%fZ','now'), 0)")
        for layer, qml in styles.items():
            row = con.execute(
                "SELECT column_name FROM gpkg_geometry_columns WHERE table_name = ?",
                (layer,)).fetchone()
            geometry_column = row[0] if row else ""
            con.execute("UPDATE layer_styles SET useAsDefault = 0 WHERE f_table_name = ?",
                        (layer,))
            con.execute(
                "INSERT INTO layer_styles (f_table_catalog, f_table_schema, f_table_name, "
                "f_geometry_column, styleName, styleQML, styleSLD, useAsDefault, description, "
                "owner, ui) VALUES ('', '', ?, ?, ?, ?, '', 1, ?, '', NULL)",
                (layer, geometry_column, style_name, qml,
                 f"clearfast default style of {layer}"))
    # sqlite3's context manager commits but does not close
    con.close()


def read_layer_styles(path: str | os.PathLike) -> dict[str, str]:
    """Default styles stored in a GeoPackage: layer name -> QML text (empty if none)."""
    if not Path(path).is_file():
        raise InvalidInput("no such GeoPackage", path)
    con = sqlite3.connect(f"file:{os.fspath(path)}?mode=ro", uri=True)
    try:
        has = con.execute(
            "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'layer_styles'"
        ).fetchone()
        if has is None:
            return {}
        rows = con.execute(
            "SELECT f_table_name, styleQML FROM layer_styles WHERE useAsDefault = 1 "
            "ORDER BY update_time, id").fetchall()
    finally:
        con.close()
    return {name: qml for name, qml in rows}
