"""JSON documents of the survey folder: ``survey.json`` and ``mission.json``.

Both are checked against their JSON Schemas on read and on write; errors name the file and the
JSON path, e.g. ``survey.json: camera.resolution: expected 2 integers``.
"""

from __future__ import annotations

import json
import math
import os
import re
from pathlib import Path, PurePosixPath
from typing import Any

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput, more_problems
from clearfast_gis.survey._text import read_text
from clearfast_gis.survey.schema import schema_errors
from clearfast_gis.timeutil import parse_utc

#: the usual file names of a survey folder (survey.json ``files``)
DEFAULT_FILES = {"mission": "mission.json", "frames": "frames.csv",
                 "blackbody_frames": "blackbody/frames.csv",
                 "blackbody_log": "blackbody/temperatures.csv", "gnss": "gnss.nmea",
                 "weather": "weather.dat", "soil": "soil.csv", "markers": "markers.csv"}


def _reject_constant(name: str) -> float:
    raise ValueError(f"{name} is not allowed in JSON")


def parse_json(text: str, label: str) -> Any:
    """Parse JSON text; errors give the line and column. NaN/Infinity are refused."""
    try:
        return json.loads(text, parse_constant=_reject_constant)
    except json.JSONDecodeError as exc:
        raise InvalidInput(f"not valid JSON: {exc.msg}", label,
                           f"line {exc.lineno} column {exc.colno}") from None
    except (ValueError, RecursionError) as exc:
        raise InvalidInput(f"not valid JSON: {exc}", label) from None


def manifest_problems(doc: Any, schema: str) -> list[tuple[str, str]]:
    """Schema problems plus the cross-field rules a schema cannot state, as (field, message)."""
    problems = schema_errors(doc, schema)
    if problems or not isinstance(doc, dict):
        return problems
    if schema == "survey":
        try:
            t0, t1 = parse_utc(doc["time"]["start_utc"]), parse_utc(doc["time"]["end_utc"])
            if t1 <= t0:
                problems.append(("time.end_utc", "must be later than time.start_utc"))
        except ValueError as exc:
            problems.append(("time", str(exc)))
        for i, b in enumerate(doc["camera"]["bands"]):
            if b["lambda_max_um"] <= b["lambda_min_um"]:
                problems.append((f"camera.bands.{i}", "lambda_max_um must exceed lambda_min_um"))
        names = [b["name"] for b in doc["camera"]["bands"]]
        if len(set(names)) != len(names):
            problems.append(("camera.bands", "band names must be unique"))
        for key, rel in doc["files"].items():
            if not is_safe_relpath(rel):
                problems.append((f"files.{key}", "expected a relative path inside the survey "
                                 "folder"))
    elif schema == "mission":
        xmin, ymin, xmax, ymax = doc["area"]
        if not (xmax > xmin and ymax > ymin):
            problems.append(("area", "expected xmin < xmax and ymin < ymax"))
        idx = [p["index"] for p in doc["positions"]]
        if len(set(idx)) != len(idx):
            problems.append(("positions", "position indices must be unique"))
    return problems


def is_safe_relpath(rel: str) -> bool:
    """True for a relative path with no ``..`` part, no drive and no leading slash."""
    if not isinstance(rel, str) or not rel or "\x00" in rel:
        return False
    p = PurePosixPath(rel.replace("\\", "/"))
    return not (p.is_absolute() or ".." in p.parts or re.match(r"[A-Za-z]:", rel))


def resolve_inside(root: str | os.PathLike, rel: str, label: str, field: str) -> Path:
    """``root / rel`` after checking that it stays inside ``root`` (symlinks followed)."""
    if not is_safe_relpath(rel):
        raise InvalidInput("expected a relative path inside the survey folder", label, field)
    root_r = Path(root).resolve()
    full = (root_r / rel.replace("\\", "/")).resolve()
    if full != root_r and root_r not in full.parents:
        raise InvalidInput(f"{rel!r} leaves the survey folder", label, field)
    return full


def _load_checked(path: str | os.PathLike, schema: str, label: str | None) -> dict:
    label = str(path) if label is None else label
    doc = parse_json(read_text(path, label), label)
    problems = manifest_problems(doc, schema)
    if problems:
        field, msg = problems[0]
        more = more_problems(len(problems))
        raise InvalidInput(msg + more, label, field)
    return doc


def read_survey_json(path: str | os.PathLike, label: str | None = None) -> dict:
    """Read and validate ``survey.json``."""
    return _load_checked(path, "survey", label)


def read_mission(path: str | os.PathLike, label: str | None = None) -> dict:
    """Read and validate ``mission.json``."""
    return _load_checked(path, "mission", label)


def _clean(obj: Any) -> Any:
    """numpy scalars/arrays and tuples to plain JSON types."""
    if isinstance(obj, dict):
        return {str(k): _clean(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [_clean(v) for v in obj]
    if hasattr(obj, "tolist"):
        return _clean(obj.tolist())
    if isinstance(obj, float) and not math.isfinite(obj):
        raise ValueError("NaN or infinity cannot be written to JSON")
    return obj


def _write_checked(path: str | os.PathLike, doc: dict, schema: str) -> Path:
    doc = _clean(doc)
    problems = manifest_problems(doc, schema)
    if problems:
        field, msg = problems[0]
        raise InvalidInput(msg, Path(path).name, field)
    write_text(path, json.dumps(doc, indent=2) + "\n")
    return Path(path)


def write_survey_json(path: str | os.PathLike, manifest: dict) -> Path:
    """Validate ``manifest`` against ``survey.schema.json`` and write it atomically."""
    return _write_checked(path, manifest, "survey")


def write_mission(path: str | os.PathLike, mission: dict) -> Path:
    """Validate ``mission`` against ``mission.schema.json`` and write it atomically."""
    return _write_checked(path, mission, "mission")
