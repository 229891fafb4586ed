"""Export for a national mine action database (IMSMA Core): WGS84 GeoPackage + CSV tables.

Three record types, as a mine action centre's land-release process works with them (IMAS
07.11): the **surveyed area** (the survey footprint, a polygon), **suspected-hazard polygon
proposals** around clusters of mine indications (:mod:`clearfast_gis.export.hazard_areas`), and
the **evidence points** (the suspects above a stated mine likelihood, or all on request), each
linked to its proposal. Every record is built on indirect evidence (stand-off thermal IR): a
thermal anomaly is never automatically a confirmed hazardous area.

Field names (at most 31 characters, ``imsma_id`` and an empty ``imsma_links`` as IMSMA Core's
data model expects) and meanings are listed in ``docs/mine_action.md``. Ids are stable:
``CF-<SURVEY>-<NNNN>`` for evidence, numbered over all suspects by position (north to south,
then west to east, on a 1 cm grid), ``CF-<SURVEY>-H<NN>`` for proposals, ``CF-<SURVEY>-SA`` for
the surveyed area; the same products always give the same ids and byte-identical CSV.
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

from clearfast_gis.atomic import write_bytes, write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.timeutil import format_utc, parse_utc

METHOD = "stand-off thermal IR"
EVIDENCE = "indirect"
LAND_CLASS = "indication"
LAYER_NAME = "indications"
HAZARD_LAYER = "hazard_proposals"
AREA_LAYER = "surveyed_area"
GPKG_NAME = "mine_action.gpkg"
CSV_NAME = "mine_action.csv"
HAZARD_CSV = "hazard_proposals.csv"
AREA_CSV = "surveyed_area.csv"
XLSX_NAME = "mine_action.xlsx"
MINE_CUES = ("at_mine", "ap_mine")
DEFAULT_MIN_LIKELIHOOD = 0.5
"""Mine likelihood (``p_mine``) from which a suspect is exported as evidence."""
ORGANISATION_ENV = "CLEARFAST_ORGANISATION"
"""Environment variable with the surveying organisation's name (default of ``--organisation``)."""

FIX_LABELS = {0: "no fix", 1: "autonomous", 2: "DGPS", 4: "RTK fixed", 5: "RTK float",
              6: "dead reckoning"}

MINE_ACTION_FIELDS: dict[str, str] = {
    "imsma_id": "Stable text id CF-<SURVEY>-<NNNN>",
    "imsma_links": "Empty: links are made in IMSMA Core",
    "hazard_ref": "imsma_id of the hazard proposal that holds the point (empty if none)",
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
    "organisation": "Surveying organisation (--organisation)",
    "mine_indication": "yes when the suspect is a mine indication (likelihood or class cue)",
    "mine_likelihood": "Mine likelihood p_mine, 0-1 (empty when the products have none)",
    "priority": "Rank for technical survey, 1 = first (empty when the products have none)",
    "class_cue": "at_mine, ap_mine, clutter or unknown (from size and thermal diffusivity)",
    "cue_confidence": "Confidence of the class cue, 0-1",
    "depth_m": "Estimated burial depth, metres (empty if not characterised)",
    "depth_sigma_m": "Depth uncertainty (1 sigma), metres",
    "diameter_m": "Diameter of the thermal footprint, metres",
    "gnss_fix_quality": "GGA fix quality of the platform position (4 = RTK fixed)",
    "gnss_fix": "Fix quality in words; '(degraded)' unless RTK fixed",
    "status": "Characterisation status: ok, at_bound, weak_contrast, not_characterised",
}
"""Columns of the evidence points (layer ``indications``, ``mine_action.csv``), in order."""

_DECIMALS = {"latitude_deg": 8, "longitude_deg": 8, "utm_easting_m": 3, "utm_northing_m": 3,
             "cue_confidence": 3, "mine_likelihood": 3, "depth_m": 4, "depth_sigma_m": 4,
             "diameter_m": 3, "buffer_m": 1, "area_m2": 2, "centroid_lat_deg": 8,
             "centroid_lon_deg": 8}


@dataclass(frozen=True)
class MineActionExport:
    """Files written by :func:`export_mine_action`."""

    gpkg: Path
    csv: Path
    count: int
    hazard_proposals: int
    hazard_csv: Path
    area_csv: Path
    xlsx: Path


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


def mine_indications(suspects, min_likelihood: float = DEFAULT_MIN_LIKELIHOOD) -> np.ndarray:
    """Which suspects are mine indications: ``p_mine >= min_likelihood`` when the products have
    a mine likelihood (a ``p_mine`` column with values), else an AT/AP class cue. Boolean
    array, shape (N,)."""
    if "p_mine" in suspects and suspects["p_mine"].notna().any():
        p = suspects["p_mine"].to_numpy(np.float64)
        return np.isfinite(p) & (p >= float(min_likelihood))
    return np.isin(np.asarray([str(c) for c in suspects["class_cue"]]), MINE_CUES)


def mine_action_table(suspects, survey_id: str, survey_date_utc: str, epsg: int,
                      organisation: str = "",
                      min_likelihood: float = DEFAULT_MIN_LIKELIHOOD):
    """The evidence rows for a suspects layer (all suspects; ``hazard_ref`` left empty).

    Parameters
    ----------
    suspects : geopandas.GeoDataFrame or pandas.DataFrame
        The ``suspects`` layer (columns of ``schemas/anomaly.schema.json``; ``x``, ``y`` in the
        survey CRS; ``p_mine``, ``priority`` and ``cue_confidence`` used when present).
    survey_id : str
        Survey id.
    survey_date_utc : str
        Survey start, ISO 8601 UTC.
    epsg : int
        EPSG code of the survey's UTM CRS.
    organisation : str
        Surveying organisation.
    min_likelihood : float
        See :func:`mine_indications`.

    Returns
    -------
    pandas.DataFrame
        Columns :data:`MINE_ACTION_FIELDS`, one row per suspect, sorted by ``imsma_id``.
    """
    import pandas as pd
    from pyproj import Transformer

    x = suspects["x"].to_numpy(np.float64)
    y = suspects["y"].to_numpy(np.float64)
    lon, lat = Transformer.from_crs(int(epsg), 4326, always_xy=True).transform(x, y)
    ids = stable_ids(survey_id, x, y, [str(a) for a in suspects["anomaly_id"]])
    fix = suspects["fix_quality"] if "fix_quality" in suspects else pd.Series([None] * len(x))

    def col(*names):
        for name in names:
            if name in suspects:
                return suspects[name].to_numpy().astype(np.float64)
        return np.full(len(x), np.nan)

    priority = col("priority")
    table = pd.DataFrame({
        "imsma_id": ids,
        "imsma_links": "",
        "hazard_ref": "",
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
        "organisation": organisation,
        "mine_indication": np.where(mine_indications(suspects, min_likelihood), "yes", "no"),
        "mine_likelihood": col("p_mine"),
        "priority": pd.array([None if np.isnan(p) else int(p) for p in priority], "Int64"),
        "class_cue": [str(c) for c in suspects["class_cue"]],
        "cue_confidence": col("cue_confidence", "confidence"),
        "depth_m": col("depth_m"),
        "depth_sigma_m": col("depth_sigma_m"),
        "diameter_m": col("diameter_m"),
        "gnss_fix_quality": pd.array([None if pd.isna(q) else int(q) for q in fix], "Int64"),
        "gnss_fix": [fix_label(None if pd.isna(q) else q) for q in fix],
        "status": [str(s) for s in suspects["status"]],
    }, columns=list(MINE_ACTION_FIELDS))
    return table.sort_values("imsma_id", kind="stable").reset_index(drop=True)


def table_to_csv(table, fields=MINE_ACTION_FIELDS) -> str:
    """CSV text of export rows: the columns ``fields``, fixed decimals, empty cells for nulls."""
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(list(fields))
    for row in table[list(fields)].itertuples(index=False):
        cells = []
        for name, value in zip(fields, row, strict=True):
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


def _read_layer(gpkg, layer: str, required: Sequence[str]):
    import pyogrio

    try:
        frame = pyogrio.read_dataframe(gpkg, layer=layer)
    except Exception as exc:  # pyogrio raises DataSourceError / DataLayerError
        raise InvalidInput(f"cannot read the {layer} layer ({exc})", gpkg, layer) from None
    missing = [c for c in required if c not in frame]
    if missing:
        raise InvalidInput("missing column", gpkg, f"{layer}.{missing[0]}")
    return frame


def _manifest_times(manifest: dict, path: Path) -> tuple[str, str]:
    """Survey start and end from ``products.json``, ISO 8601 UTC to the second."""
    stamps = []
    for key in ("start_utc", "end_utc"):
        try:
            stamps.append(format_utc(parse_utc(manifest["time"][key]), "seconds"))
        except (KeyError, TypeError, ValueError):
            raise InvalidInput("not an ISO 8601 UTC time", path, f"time.{key}") from None
    return stamps[0], stamps[1]


def export_mine_action(products_dir: str | os.PathLike, out_dir: str | os.PathLike | None = None,
                       progress: Progress = NULL_PROGRESS, *,
                       min_likelihood: float = DEFAULT_MIN_LIKELIHOOD,
                       include_all: bool = False, buffer_m: float | None = None,
                       organisation: str | None = None) -> MineActionExport:
    """Write ``mine_action.gpkg`` (EPSG:4326) and its CSV tables for IMSMA Core.

    Layers: ``indications`` (evidence points), ``hazard_proposals`` and ``surveyed_area``
    (polygons); CSVs ``mine_action.csv``, ``hazard_proposals.csv``, ``surveyed_area.csv``, and
    the three tables as sheets of ``mine_action.xlsx``.
    Field names and geometries are checked before anything is written.

    Parameters
    ----------
    products_dir : path
        A products folder (``products.json`` and ``anomalies.gpkg`` with ``suspects`` and
        ``footprint`` layers).
    out_dir : path, optional
        Output folder; default ``<products_dir>/mine_action``.
    progress : Progress
        Reporter (stage ``mine_action``, 3 steps).
    min_likelihood : float
        Mine likelihood from which a suspect is a mine indication (see
        :func:`mine_indications`).
    include_all : bool
        Export every suspect as evidence, not only the mine indications.
    buffer_m : float, optional
        Disc radius of the hazard proposals, metres (default
        :data:`~clearfast_gis.export.hazard_areas.DEFAULT_BUFFER_M`).
    organisation : str, optional
        Surveying organisation; default the ``CLEARFAST_ORGANISATION`` environment variable
        (empty when unset).

    Returns
    -------
    MineActionExport
    """
    import geopandas as gpd

    from clearfast_gis.export.geopackage import write_geopackage
    from clearfast_gis.export.hazard_areas import (
        DEFAULT_BUFFER_M,
        check_field_names,
        check_geometries,
    )
    from clearfast_gis.export.land_release import (
        AREA_FIELDS,
        HAZARD_FIELDS,
        hazard_table,
        surveyed_area_table,
    )
    from clearfast_gis.export.manifest import read_products_manifest
    from clearfast_gis.export.styles import mine_action_styles
    from clearfast_gis.export.xlsx import workbook_bytes

    products = Path(products_dir)
    out = Path(out_dir) if out_dir is not None else products / "mine_action"
    buffer_m = DEFAULT_BUFFER_M if buffer_m is None else float(buffer_m)
    if not (math.isfinite(buffer_m) and buffer_m > 0):
        raise InvalidInput("the hazard buffer must be a positive number of metres", out,
                           "buffer_m")
    if not 0.0 <= min_likelihood <= 1.0:
        raise InvalidInput("a likelihood is between 0 and 1", out, "min_likelihood")
    if organisation is None:
        organisation = os.environ.get(ORGANISATION_ENV, "")
    manifest = read_products_manifest(products)
    gpkg_in = products / "anomalies.gpkg"
    if not gpkg_in.is_file():
        raise InvalidInput("missing: no anomalies.gpkg in the products folder", gpkg_in)
    survey_date, survey_end = _manifest_times(manifest, products / "products.json")
    progress.start("mine_action", 3)
    try:
        suspects = _read_layer(gpkg_in, "suspects",
                               ("anomaly_id", "x", "y", "class_cue", "status"))
        footprint = _read_layer(gpkg_in, "footprint", ())
        progress.advance()
        epsg = int(manifest["crs"]["epsg"])
        table = mine_action_table(suspects, manifest["survey_id"], survey_date, epsg,
                                  organisation, min_likelihood)
        hazards, hazard_polys = hazard_table(table, epsg, manifest["survey_id"],
                                             organisation, buffer_m)
        n_mine = int((table["mine_indication"] == "yes").sum())
        area, area_polys = surveyed_area_table(
            footprint.geometry, epsg, manifest["survey_id"], (survey_date, survey_end),
            organisation, (len(table), n_mine, len(hazards)))
        evidence = table if include_all else table[table["mine_indication"] == "yes"]
        evidence = evidence.reset_index(drop=True)
        points = gpd.points_from_xy(evidence["longitude_deg"], evidence["latitude_deg"])
        layers = {
            LAYER_NAME: gpd.GeoDataFrame(evidence, geometry=points, crs=4326),
            HAZARD_LAYER: gpd.GeoDataFrame(hazards.drop(columns="wkt"),
                                           geometry=gpd.GeoSeries(hazard_polys, crs=4326)),
            AREA_LAYER: gpd.GeoDataFrame(area.drop(columns="wkt"),
                                         geometry=gpd.GeoSeries(area_polys, crs=4326)),
        }
        gpkg_out = out / GPKG_NAME
        for name, frame in layers.items():
            check_field_names([c for c in frame.columns if c != "geometry"], gpkg_out, name)
            check_geometries(list(frame.geometry), list(frame["imsma_id"]), gpkg_out, name)
        progress.advance()
        end_s = parse_utc(survey_end)
        write_geopackage(gpkg_out, layers, mine_action_styles(), timestamp_s=end_s)
        csv_out = write_text(out / CSV_NAME, table_to_csv(evidence))
        hazard_csv = write_text(out / HAZARD_CSV, table_to_csv(hazards, HAZARD_FIELDS))
        area_csv = write_text(out / AREA_CSV, table_to_csv(area, AREA_FIELDS))
        xlsx = write_bytes(out / XLSX_NAME, workbook_bytes(
            {"evidence": (evidence, list(MINE_ACTION_FIELDS)),
             HAZARD_LAYER: (hazards, list(HAZARD_FIELDS)),
             AREA_LAYER: (area, list(AREA_FIELDS))}, _DECIMALS, end_s))
        progress.advance()
    finally:
        progress.close()
    return MineActionExport(gpkg_out, Path(csv_out), len(evidence), len(hazards),
                            Path(hazard_csv), Path(area_csv), Path(xlsx))
