"""Export of suspects for a national mine action database (WGS84 GeoPackage + CSV).

Every row is an *indication* from indirect evidence (stand-off thermal IR): a thermal anomaly is
never automatically a confirmed hazardous area. Field names and meanings are listed in
``docs/mine_action.md``. Ids are stable: ``CF-<SURVEY>-<NNNN>``, numbered by position (north to
south, then west to east, on a 1 cm grid), so re-running the export on the same products gives
the same ids and byte-identical CSV.
"""

from __future__ import annotations

import csv
import io
import math
import os
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.timeutil import format_utc, parse_utc

METHOD = "stand-off thermal IR"
EVIDENCE = "indirect"
LAND_CLASS = "indication"
LAYER_NAME = "indications"
GPKG_NAME = "mine_action.gpkg"
CSV_NAME = "mine_action.csv"

FIX_LABELS = {0: "no fix", 1: "autonomous", 2: "DGPS", 4: "RTK fixed", 5: "RTK float",
              6: "dead reckoning"}

MINE_ACTION_FIELDS: dict[str, str] = {
    "hazard_id": "Stable IMSMA-style text id CF-<SURVEY>-<NNNN>",
    "source_anomaly_id": "anomaly_id in the products' suspects layer",
    "survey_id": "Survey id (products.json)",
    "survey_date_utc": "Survey start, ISO 8601 UTC",
    "latitude_deg": "Latitude, WGS84 decimal degrees",
    "longitude_deg": "Longitude, WGS84 decimal degrees",
    "utm_easting_m": "Easting in the survey's UTM CRS, metres",
    "utm_northing_m": "Northing in the survey's UTM CRS, metres",
    "utm_epsg": "EPSG code of that UTM CRS",
    "method": f'Always "{METHOD}"',
    "evidence": f'Always "{EVIDENCE}"',
    "land_class": f'Always "{LAND_CLASS}" (never a confirmed hazardous area)',
    "class_cue": "at_mine, ap_mine, clutter or unknown (from size and thermal diffusivity)",
    "cue_confidence": "Confidence of the class cue, 0-1 (not a mine likelihood)",
    "depth_m": "Estimated burial depth, metres (empty if not characterised)",
    "depth_sigma_m": "Depth uncertainty (1 sigma), metres",
    "diameter_m": "Diameter of the thermal footprint, metres",
    "gnss_fix_quality": "GGA fix quality of the platform position (4 = RTK fixed)",
    "gnss_fix": "Fix quality in words; '(degraded)' unless RTK fixed",
    "status": "Characterisation status: ok, at_bound, weak_contrast, not_characterised",
}
"""Columns of the export, in order, with their meaning."""

_DECIMALS = {"latitude_deg": 8, "longitude_deg": 8, "utm_easting_m": 3, "utm_northing_m": 3,
             "cue_confidence": 3, "depth_m": 4, "depth_sigma_m": 4, "diameter_m": 3}


@dataclass(frozen=True)
class MineActionExport:
    """Files written by :func:`export_mine_action`."""

    gpkg: Path
    csv: Path
    count: int


def survey_code(survey_id: str) -> str:
    """The survey part of a hazard id: upper case, runs of other characters as one ``-``."""
    code = re.sub(r"[^A-Z0-9]+", "-", survey_id.upper()).strip("-")
    if not code:
        raise ValueError(f"survey id {survey_id!r} has no letters or digits")
    return code


def stable_ids(survey_id: str, easting_m: Sequence[float], northing_m: Sequence[float],
               tiebreak: Sequence[str] | None = None) -> list[str]:
    """Position-ordered ids ``CF-<SURVEY>-<NNNN>`` for points of one survey.

    Parameters
    ----------
    survey_id : str
        The survey id.
    easting_m, northing_m : sequence of float, shape (N,)
        Positions in the survey CRS, metres.
    tiebreak : sequence of str, optional
        Secondary key for points on the same centimetre (e.g. anomaly ids).

    Returns
    -------
    list of str, length N
        Numbered from 0001 north to south, then west to east, positions rounded to 1 cm; the
        same positions always get the same ids, whatever their input order.
    """
    e = np.round(np.asarray(easting_m, np.float64) * 100.0).astype(np.int64)
    n = np.round(np.asarray(northing_m, np.float64) * 100.0).astype(np.int64)
    keys = list(tiebreak) if tiebreak is not None else [""] * len(e)
    order = sorted(range(len(e)), key=lambda i: (-n[i], e[i], keys[i]))
    width = max(4, len(str(len(e))))
    code = survey_code(survey_id)
    ids = [""] * len(e)
    for rank, i in enumerate(order, start=1):
        ids[i] = f"CF-{code}-{rank:0{width}d}"
    return ids


def fix_label(quality) -> str:
    """Words for a GGA fix quality; anything but RTK fixed (4) is marked degraded."""
    if quality is None or (isinstance(quality, float) and math.isnan(quality)):
        return "unknown (degraded)"
    q = int(quality)
    label = FIX_LABELS.get(q, f"quality {q}")
    return label if q == 4 else f"{label} (degraded)"


def mine_action_table(suspects, survey_id: str, survey_date_utc: str, epsg: int):
    """The export rows for a suspects layer.

    Parameters
    ----------
    suspects : geopandas.GeoDataFrame or pandas.DataFrame
        The ``suspects`` layer (columns of ``schemas/anomaly.schema.json``; ``x``, ``y`` in the
        survey CRS).
    survey_id : str
        Survey id.
    survey_date_utc : str
        Survey start, ISO 8601 UTC.
    epsg : int
        EPSG code of the survey's UTM CRS.

    Returns
    -------
    pandas.DataFrame
        Columns :data:`MINE_ACTION_FIELDS`, one row per suspect, sorted by ``hazard_id``.
    """
    import pandas as pd
    from pyproj import Transformer

    x = suspects["x"].to_numpy(np.float64)
    y = suspects["y"].to_numpy(np.float64)
    lon, lat = Transformer.from_crs(int(epsg), 4326, always_xy=True).transform(x, y)
    ids = stable_ids(survey_id, x, y, [str(a) for a in suspects["anomaly_id"]])
    fix = suspects["fix_quality"] if "fix_quality" in suspects else pd.Series([None] * len(x))

    def col(name):
        return suspects[name].to_numpy() if name in suspects else np.full(len(x), np.nan)

    table = pd.DataFrame({
        "hazard_id": ids,
        "source_anomaly_id": [str(a) for a in suspects["anomaly_id"]],
        "survey_id": survey_id,
        "survey_date_utc": survey_date_utc,
        "latitude_deg": np.asarray(lat, np.float64),
        "longitude_deg": np.asarray(lon, np.float64),
        "utm_easting_m": x,
        "utm_northing_m": y,
        "utm_epsg": int(epsg),
        "method": METHOD,
        "evidence": EVIDENCE,
        "land_class": LAND_CLASS,
        "class_cue": [str(c) for c in suspects["class_cue"]],
        "cue_confidence": col("cue_confidence").astype(np.float64),
        "depth_m": col("depth_m").astype(np.float64),
        "depth_sigma_m": col("depth_sigma_m").astype(np.float64),
        "diameter_m": col("diameter_m").astype(np.float64),
        "gnss_fix_quality": pd.array([None if pd.isna(q) else int(q) for q in fix], "Int64"),
        "gnss_fix": [fix_label(None if pd.isna(q) else q) for q in fix],
        "status": [str(s) for s in suspects["status"]],
    }, columns=list(MINE_ACTION_FIELDS))
    return table.sort_values("hazard_id", kind="stable").reset_index(drop=True)


def table_to_csv(table) -> str:
    """CSV text of :func:`mine_action_table` rows: fixed decimals, empty cells for nulls."""
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(list(MINE_ACTION_FIELDS))
    for row in table.itertuples(index=False):
        cells = []
        for name, value in zip(MINE_ACTION_FIELDS, row, strict=True):
            if value is None or (not isinstance(value, str) and _isnull(value)):
                cells.append("")
            elif name in _DECIMALS:
                cells.append(f"{float(value):.{_DECIMALS[name]}f}")
            else:
                cells.append(str(value))
        writer.writerow(cells)
    return buf.getvalue()


def _isnull(value) -> bool:
    import pandas as pd

    return bool(pd.isna(value))


def export_mine_action(products_dir: str | os.PathLike, out_dir: str | os.PathLike | None = None,
                       progress: Progress = NULL_PROGRESS) -> MineActionExport:
    """Write ``mine_action.gpkg`` (layer ``indications``, EPSG:4326) and ``mine_action.csv``.

    Parameters
    ----------
    products_dir : path
        A products folder (``products.json`` and ``anomalies.gpkg`` with a ``suspects`` layer).
    out_dir : path, optional
        Output folder; default ``<products_dir>/mine_action``.
    progress : Progress
        Reporter (stage ``mine_action``, 3 steps).

    Returns
    -------
    MineActionExport
    """
    import geopandas as gpd
    import pyogrio

    from clearfast_gis.export.geopackage import write_geopackage
    from clearfast_gis.export.manifest import read_products_manifest
    from clearfast_gis.export.styles import mine_action_style

    products = Path(products_dir)
    out = Path(out_dir) if out_dir is not None else products / "mine_action"
    manifest = read_products_manifest(products)
    gpkg_in = products / "anomalies.gpkg"
    if not gpkg_in.is_file():
        raise InvalidInput("missing: no anomalies.gpkg in the products folder", gpkg_in)
    try:
        survey_date = format_utc(parse_utc(manifest["time"]["start_utc"]), "seconds")
    except ValueError:
        raise InvalidInput("not an ISO 8601 UTC time", products / "products.json",
                           "time.start_utc") from None
    progress.start("mine_action", 3)
    try:
        try:
            suspects = pyogrio.read_dataframe(gpkg_in, layer="suspects")
        except Exception as exc:  # pyogrio raises DataSourceError / DataLayerError
            raise InvalidInput(f"cannot read the suspects layer ({exc})", gpkg_in,
                               "suspects") from None
        missing = [c for c in ("anomaly_id", "x", "y", "class_cue", "status")
                   if c not in suspects]
        if missing:
            raise InvalidInput("missing column", gpkg_in, f"suspects.{missing[0]}")
        progress.advance()
        epsg = int(manifest["crs"]["epsg"])
        table = mine_action_table(suspects, manifest["survey_id"], survey_date, epsg)
        progress.advance()
        frame = gpd.GeoDataFrame(
            table, geometry=gpd.points_from_xy(table["longitude_deg"], table["latitude_deg"]),
            crs=4326)
        gpkg_out = Path(write_geopackage(out / GPKG_NAME, {LAYER_NAME: frame},
                                         {LAYER_NAME: mine_action_style()}))
        csv_out = write_text(out / CSV_NAME, table_to_csv(table))
        progress.advance()
    finally:
        progress.close()
    return MineActionExport(gpkg_out, Path(csv_out), len(table))
