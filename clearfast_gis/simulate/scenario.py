"""Scenario files: a preset, its overrides and optionally the exact list of scene objects.

The format is described by ``clearfast_gis/schemas/scenario.schema.json``. Errors name the file
and the field (``scenario.json: objects.2.kind: expected one of ...``).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, replace
from functools import lru_cache
from importlib import resources
from pathlib import Path

import jsonschema

from clearfast_gis.errors import InvalidInput
from clearfast_gis.simulate.config import RainEvent, SimConfig, WeatherSpec, preset
from clearfast_gis.simulate.objects import KINDS, MINE_KINDS, SceneObject, default_height_m
from clearfast_gis.timeutil import format_utc, parse_utc

#: Default diameters of listed objects whose scenario entry gives none, metres.
DEFAULT_DIAMETER_M = {"at_mine": 0.337, "ap_mine": 0.104, "stone": 0.15, "metal": 0.08,
                      "vegetation": 1.0, "disturbed_soil": 0.7, "marker": 0.3}


@dataclass(frozen=True)
class Scenario:
    """A parsed scenario: the effective config and, if given, the listed objects.

    ``objects`` is None when the preset draws all objects from the seed; otherwise the listed
    objects are placed as given and ``draw_clutter`` says whether the preset's clutter
    (stones, debris, vegetation, disturbed soil) is drawn around them.
    """

    config: SimConfig
    objects: tuple[SceneObject, ...] | None = None
    draw_clutter: bool = False


@lru_cache(maxsize=1)
def scenario_schema() -> dict:
    """The scenario JSON Schema (a dict)."""
    text = resources.files("clearfast_gis").joinpath("schemas/scenario.schema.json").read_text()
    return json.loads(text)


def _field(error: jsonschema.ValidationError) -> str:
    return ".".join(str(p) for p in error.absolute_path) or "(top level)"


def parse_scenario(doc: dict, path: str | Path | None = None,
                   base: SimConfig | None = None) -> Scenario:
    """Validate a scenario document and apply it to its preset.

    Parameters
    ----------
    doc : dict
        The scenario (JSON content).
    path : path, optional
        File name for error messages.
    base : SimConfig, optional
        Config to override; default: the preset named in ``doc`` (``demo`` if none).

    Returns
    -------
    Scenario

    Raises
    ------
    InvalidInput
        With the file and the field when the document does not follow the schema.
    """
    validator = jsonschema.Draft202012Validator(scenario_schema())
    errors = sorted(validator.iter_errors(doc), key=lambda e: list(e.absolute_path))
    if errors:
        err = errors[0]
        expected = err.schema.get("x-expected") if isinstance(err.schema, dict) else None
        message = f"expected {expected}" if expected else err.message
        raise InvalidInput(message, path, _field(err))
    cfg = base if base is not None else preset(doc.get("preset", "demo"))
    upd: dict = {}
    site = doc.get("site", {})
    for key, name in (("name", "site_name"), ("latitude_deg", "latitude_deg"),
                      ("longitude_deg", "longitude_deg"),
                      ("ground_altitude_m", "ground_altitude_m"), ("epsg", "epsg")):
        if key in site:
            upd[name] = site[key]
    if "start_utc" in doc:
        upd["start_utc"] = doc["start_utc"]
    if "n_scans" in doc:
        upd["n_scans"] = int(doc["n_scans"])
    if "duration_h" in doc:
        upd["duration_s"] = float(doc["duration_h"]) * 3600.0
    area = doc.get("area", {})
    if "width_m" in area:
        upd["area_width_m"] = float(area["width_m"])
    if "length_m" in area:
        upd["area_length_m"] = float(area["length_m"])
    lift = doc.get("lift", {})
    if "height_m" in lift:
        upd["lift_height_m"] = float(lift["height_m"])
    if "offset_m" in lift:
        upd["lift_offset_m"] = float(lift["offset_m"])
    cam = doc.get("camera", {})
    if "model" in cam:
        upd["camera_model"] = cam["model"]
    if "resolution" in cam:
        upd["resolution"] = (int(cam["resolution"][0]), int(cam["resolution"][1]))
    if "aperture_deg" in cam:
        upd["aperture_deg"] = float(cam["aperture_deg"])
    if "netd_k" in cam:
        upd["netd_k"] = float(cam["netd_k"])
    if "grid_cell_m" in doc:
        upd["grid_cell_m"] = float(doc["grid_cell_m"])
    if "weather" in doc:
        upd["weather"] = _parse_weather(doc["weather"], cfg.weather, path)
    if "soil" in doc:
        upd["soil_type"] = doc["soil"]["type"]
        upd["soil_moisture"] = float(doc["soil"].get("moisture", cfg.soil_moisture))
    if "vegetation_cover" in doc:
        upd["vegetation_cover"] = float(doc["vegetation_cover"])
    if "mine_fills" in doc:
        upd["mine_fills"] = tuple(doc["mine_fills"])
    cfg = replace(cfg, **upd)
    objects = None
    if "objects" in doc:
        objects = tuple(_parse_object(i, o, cfg, path) for i, o in enumerate(doc["objects"]))
        ids = [o.id for o in objects]
        dup = {i for i in ids if ids.count(i) > 1}
        if dup:
            raise InvalidInput(f"duplicate object id {sorted(dup)[0]!r}", path, "objects")
    return Scenario(config=cfg, objects=objects, draw_clutter=bool(doc.get("draw_clutter", False)))


def _parse_weather(w: dict, base: WeatherSpec, path) -> WeatherSpec:
    """The ``weather`` block (already schema-checked) applied to ``base``."""
    upd: dict = {}
    cover = w.get("cloud_cover")
    if isinstance(cover, int | float):
        upd["cloud_cover"] = ((0.0, float(cover)),)
    elif cover is not None:
        hours = [float(p[0]) for p in cover]
        if any(b <= a for a, b in zip(hours, hours[1:], strict=False)):
            raise InvalidInput("hours must increase", path, "weather.cloud_cover")
        upd["cloud_cover"] = tuple((float(h), float(f)) for h, f in cover)
    if "rain" in w:
        upd["rain"] = tuple(RainEvent(parse_utc(r["start_utc"]), float(r["duration_h"]) * 3600.0,
                                      float(r["total_mm"])) for r in w["rain"])
    for key in ("wind_scale", "gusts"):
        if key in w:
            upd[key] = float(w[key])
    for key in ("air_temp_c", "rh_pct"):
        if key in w:
            lo, hi = (float(v) for v in w[key])
            if lo > hi:
                raise InvalidInput("the first value must not exceed the second", path,
                                   f"weather.{key}")
            upd[key] = (lo, hi)
    if "file" in w:
        f = Path(w["file"])
        if not f.is_absolute() and path is not None:
            f = Path(path).parent / f
        if not f.is_file():
            raise InvalidInput(f"no such file: {f}", path, "weather.file")
        upd["file"] = str(f)
    return replace(base, **upd)


def _parse_object(i: int, o: dict, cfg: SimConfig, path) -> SceneObject:
    kind = o["kind"]
    diameter = float(o.get("diameter_m", DEFAULT_DIAMETER_M[kind]))
    x, y = float(o["x_m"]), float(o["y_m"])
    if not (0.0 <= x <= cfg.area_width_m and 0.0 <= y <= cfg.area_length_m):
        raise InvalidInput(
            f"({x}, {y}) is outside the {cfg.area_width_m} m x {cfg.area_length_m} m area",
            path, f"objects.{i}")
    variant = o.get("variant", "hot" if kind == "marker" else "")
    material = o.get("material", "")
    if material and kind not in MINE_KINDS:
        raise InvalidInput(f"a {kind} has no mine body (material is for at_mine and ap_mine)",
                           path, f"objects.{i}.material")
    return SceneObject(
        id=o.get("id", f"OB{i + 1:03d}"), kind=kind, x_m=x, y_m=y,
        depth_m=float(o.get("depth_m", 0.0)), diameter_m=diameter,
        height_m=default_height_m(kind, diameter), variant=variant, material=material)


def load_scenario(path: str | Path, base: SimConfig | None = None) -> Scenario:
    """Read and validate a scenario JSON file (see :func:`parse_scenario`)."""
    path = Path(path)
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise InvalidInput(f"cannot read: {exc.strerror}", path) from None
    except json.JSONDecodeError as exc:
        raise InvalidInput(f"not JSON: {exc.msg}", path, f"line {exc.lineno}") from None
    if not isinstance(doc, dict):
        raise InvalidInput("expected a JSON object", path)
    return parse_scenario(doc, path, base)


def scenario_document(config: SimConfig, objects: list[SceneObject]) -> dict:
    """A scenario document that reproduces ``objects`` (local metres) on ``config``'s preset."""
    return {
        "format": "clearfast-scenario", "format_version": 1, "preset": config.name
        if config.name in ("demo", "trial", "full") else "demo",
        "objects": [{"id": o.id, "kind": o.kind, "x_m": o.x_m, "y_m": o.y_m,
                     "depth_m": o.depth_m, "diameter_m": o.diameter_m,
                     **({"variant": o.variant} if o.variant else {}),
                     **({"material": o.material} if o.material else {})} for o in objects],
        **conditions_document(config),
    }


def conditions_document(config: SimConfig) -> dict:
    """The scenario fields of ``config``'s weather and ground that differ from the default
    (``weather``, ``soil``, ``vegetation_cover``, ``mine_fills``)."""
    out: dict = {}
    w, d = config.weather, WeatherSpec()
    weather: dict = {}
    if w.cloud_cover:
        weather["cloud_cover"] = [list(p) for p in w.cloud_cover]
    if w.rain:
        weather["rain"] = [{"start_utc": format_utc(r.start_s, "seconds"),
                            "duration_h": r.duration_s / 3600.0, "total_mm": r.total_mm}
                           for r in w.rain]
    for key in ("wind_scale", "gusts", "air_temp_c", "rh_pct", "file"):
        if getattr(w, key) != getattr(d, key):
            value = getattr(w, key)
            weather[key] = list(value) if isinstance(value, tuple) else value
    if weather:
        out["weather"] = weather
    if config.soil_type is not None:
        out["soil"] = {"type": config.soil_type, "moisture": config.soil_moisture}
    if config.vegetation_cover > 0:
        out["vegetation_cover"] = config.vegetation_cover
    if config.mine_fills:
        out["mine_fills"] = list(config.mine_fills)
    return out


__all__ = ["KINDS", "Scenario", "load_scenario", "parse_scenario", "scenario_document",
           "scenario_schema"]
