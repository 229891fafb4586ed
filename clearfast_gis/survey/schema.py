"""JSON Schemas of the survey folder (``clearfast_gis/schemas``) and readable schema errors.

Errors come out as ``(field, message)`` pairs such as ``("camera.resolution", "expected 2
integers")``: the field is the dotted JSON path (list items as numbers), the message uses the
schema's ``x-expected`` annotation when it has one.
"""

from __future__ import annotations

import functools
import json
from importlib import resources
from typing import Any

import jsonschema

#: schema names in ``clearfast_gis/schemas`` (``<name>.schema.json``)
SCHEMA_NAMES = ("survey", "mission", "frames", "blackbody_frames", "setup", "station_profile")


@functools.cache
def load_schema(name: str) -> dict:
    """The JSON Schema ``<name>.schema.json`` shipped with the package, as a dict."""
    text = resources.files("clearfast_gis").joinpath("schemas", f"{name}.schema.json").read_text(
        encoding="utf-8")
    return json.loads(text)


@functools.cache
def _validator(name: str) -> jsonschema.protocols.Validator:
    schema = load_schema(name)
    cls = jsonschema.validators.validator_for(schema)
    return cls(schema)


def field_name(path: list | tuple) -> str:
    """Dotted JSON path: ``["camera", "bands", 0, "name"]`` -> ``camera.bands.0.name``."""
    return ".".join(str(p) for p in path)


def _resolve(root: dict, node: Any) -> Any:
    while isinstance(node, dict) and isinstance(node.get("$ref"), str) and \
            node["$ref"].startswith("#/"):
        target: Any = root
        for part in node["$ref"][2:].split("/"):
            target = target[part]
        node = target
    return node


def _schema_at(root: dict, path: list) -> dict | None:
    node: Any = _resolve(root, root)
    for key in path:
        if not isinstance(node, dict):
            return None
        if isinstance(key, int):
            prefix = node.get("prefixItems")
            node = prefix[key] if prefix and key < len(prefix) else node.get("items")
        else:
            props = node.get("properties", {})
            if key in props:
                node = props[key]
            elif isinstance(node.get("additionalProperties"), dict):
                node = node["additionalProperties"]
            else:
                return None
        node = _resolve(root, node)
    return node if isinstance(node, dict) else None


def _type_name(value: Any) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true/false"
    if isinstance(value, int | float):
        return "a number"
    if isinstance(value, str):
        return "a text"
    if isinstance(value, list):
        return f"a list of {len(value)}"
    if isinstance(value, dict):
        return "an object"
    return type(value).__name__


def _describe(root: dict, error: jsonschema.ValidationError) -> tuple[str, str]:
    path = list(error.absolute_path)
    if error.validator == "required":
        missing = next((k for k in error.validator_value if k not in (error.instance or {})), "?")
        return field_name([*path, missing]), "missing"
    if error.validator == "additionalProperties":
        return field_name(path) or "(top level)", " ".join(error.message.split())
    # climb from the failing item to the list that carries the expectation
    probe = list(path)
    while True:
        node = _schema_at(root, probe)
        if node is not None and "x-expected" in node:
            got = ""
            if probe == path and error.validator == "type":
                got = f", got {_type_name(error.instance)}"
            elif probe == path and error.validator in ("const", "enum"):
                got = f", got {json.dumps(error.instance)[:40]}"
            return field_name(probe) or "(top level)", f"expected {node['x-expected']}{got}"
        if probe and isinstance(probe[-1], int):
            probe.pop()
            continue
        break
    return field_name(path) or "(top level)", " ".join(error.message.split())


def schema_errors(instance: Any, name: str) -> list[tuple[str, str]]:
    """All errors of ``instance`` against schema ``name`` as sorted ``(field, message)`` pairs.

    Parameters
    ----------
    instance : Any
        Parsed JSON document (or one table row as a dict).
    name : str
        One of :data:`SCHEMA_NAMES`.

    Returns
    -------
    list of (str, str)
        Unique ``(field, message)`` pairs, ordered by field; empty when valid.
    """
    root = load_schema(name)
    out = {_describe(root, e) for e in _validator(name).iter_errors(instance)}
    return sorted(out)
