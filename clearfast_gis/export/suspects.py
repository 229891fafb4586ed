"""The ``suspects`` layer: one point per anomaly, attributes per ``schemas/anomaly.schema.json``."""

from __future__ import annotations

import json
import math
import os
from collections.abc import Iterable, Mapping

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.export._schema import load_schema, validate_record

SUSPECT_COLUMNS: dict[str, str] = {
    "anomaly_id": "str",
    "x": "float",
    "y": "float",
    "lat": "float",
    "lon": "float",
    "area_m2": "float",
    "diameter_m": "float",
    "circularity": "float",
    "depth_m": "float",
    "depth_sigma_m": "float",
    "diffusivity_m2s": "float",
    "diffusivity_sigma_m2s": "float",
    "status": "str",
    "polarity": "str",
    "class_cue": "str",
    "cue_confidence": "float",
    "p_mine": "float",
    "priority": "Int64",
    "set_aside_reason": "str",
    "n_scans": "int",
    "contrast_day_k": "float",
    "contrast_night_k": "float",
    "mine_curve_r": "float",
    "mine_curve_level": "float",
    "fix_quality": "Int64",
    "figure": "str",
    "contrast_series": "str",
}
"""Columns of the suspects layer, in order, with their pandas kind (``Int64`` = nullable)."""


def contrast_series_text(time_utc: Iterable[str], contrast_k: Iterable[float]) -> str:
    """The ``contrast_series`` attribute: compact JSON ``{"time_utc": [...], "contrast_k": [...]}``.

    Contrasts are rounded to 1 mK.
    """
    times = [str(t) for t in time_utc]
    values = [None if not math.isfinite(float(c)) else round(float(c), 3) for c in contrast_k]
    if len(times) != len(values):
        raise ValueError("time_utc and contrast_k differ in length")
    return json.dumps({"time_utc": times, "contrast_k": values}, separators=(",", ":"))


def parse_contrast_series(text: str) -> tuple[list[str], np.ndarray]:
    """Inverse of :func:`contrast_series_text`: (ISO times, contrast in kelvin (N,), NaN = null)."""
    obj = json.loads(text)
    if not isinstance(obj, dict) or not isinstance(obj.get("time_utc"), list) or not isinstance(
            obj.get("contrast_k"), list) or len(obj["time_utc"]) != len(obj["contrast_k"]):
        raise ValueError("expected {\"time_utc\": [...], \"contrast_k\": [...]} of equal length")
    values = np.array([np.nan if c is None else float(c) for c in obj["contrast_k"]], np.float64)
    return [str(t) for t in obj["time_utc"]], values


def _normalise(record: Mapping, index: int, path) -> dict:
    rec = {k: (None if isinstance(v, float) and math.isnan(v) else v) for k, v in record.items()}
    for key, value in list(rec.items()):
        if isinstance(value, np.generic):
            rec[key] = value.item()
    series = rec.get("contrast_series")
    if isinstance(series, Mapping):
        rec["contrast_series"] = contrast_series_text(series["time_utc"], series["contrast_k"])
    elif series is not None:
        try:
            parse_contrast_series(str(series))
        except (ValueError, TypeError) as exc:
            raise InvalidInput(str(exc), path, f"suspects[{index}].contrast_series") from None
    required = set(load_schema("anomaly")["required"])
    for key in SUSPECT_COLUMNS:
        if key not in required:
            rec.setdefault(key, None)
    return rec


def suspects_frame(records: Iterable[Mapping], epsg: int, path: str | os.PathLike | None = None):
    """Validated suspects as a GeoDataFrame of points in the survey CRS.

    Parameters
    ----------
    records : iterable of mapping
        One mapping per suspect with at least the required fields of
        ``schemas/anomaly.schema.json`` (``x``, ``y`` in metres in the survey CRS). ``lat`` and
        ``lon`` are computed from ``x``, ``y`` when missing; ``contrast_series`` may be given as
        a mapping ``{"time_utc": [...], "contrast_k": [...]}``. Extra scalar fields are kept
        after the standard columns.
    epsg : int
        EPSG code of the survey CRS.
    path : path, optional
        File named in validation errors (default ``suspects``).

    Returns
    -------
    geopandas.GeoDataFrame
        Columns :data:`SUSPECT_COLUMNS` (+ extras) and ``geometry``; CRS ``EPSG:<epsg>``.

    Raises
    ------
    InvalidInput
        Naming ``suspects[i].<field>`` for the first invalid attribute, or a repeated
        ``anomaly_id``.
    """
    import geopandas as gpd
    import pandas as pd
    from pyproj import Transformer

    where = path if path is not None else "suspects"
    recs = [_normalise(r, i, where) for i, r in enumerate(records)]
    to_lonlat = Transformer.from_crs(int(epsg), 4326, always_xy=True)
    for rec in recs:
        if (rec["lat"] is None or rec["lon"] is None) and isinstance(rec["x"], int | float) \
                and isinstance(rec["y"], int | float):
            lon, lat = to_lonlat.transform(float(rec["x"]), float(rec["y"]))
            rec["lat"], rec["lon"] = float(lat), float(lon)
    seen: set[str] = set()
    for i, rec in enumerate(recs):
        validate_record(rec, "anomaly", where, f"suspects[{i}]")
        if rec["anomaly_id"] in seen:
            raise InvalidInput("repeated anomaly_id", where, f"suspects[{i}].anomaly_id")
        seen.add(rec["anomaly_id"])
    for rec in recs:
        for key in SUSPECT_COLUMNS:
            rec.setdefault(key, None)
    extras = [k for rec in recs for k in rec if k not in SUSPECT_COLUMNS]
    extras = list(dict.fromkeys(extras))
    columns = [*SUSPECT_COLUMNS, *extras]
    data = {}
    for col in columns:
        values = [rec.get(col) for rec in recs]
        kind = SUSPECT_COLUMNS.get(col)
        if kind == "float":
            data[col] = pd.Series([np.nan if v is None else float(v) for v in values],
                                  dtype="float64")
        elif kind == "int":
            data[col] = pd.Series(values, dtype="int64")
        elif kind == "Int64":
            data[col] = pd.Series(values, dtype="Int64")
        elif kind == "str":
            data[col] = pd.Series(values, dtype="object")
        else:
            data[col] = pd.Series(values)
    frame = pd.DataFrame(data, columns=columns)
    geometry = gpd.points_from_xy(frame["x"], frame["y"], crs=int(epsg))
    return gpd.GeoDataFrame(frame, geometry=geometry, crs=int(epsg))
