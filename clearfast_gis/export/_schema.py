"""Validation of product records against the JSON Schemas in ``clearfast_gis/schemas``."""

from __future__ import annotations

import json
import os
from functools import cache
from pathlib import Path

from clearfast_gis.errors import InvalidInput


@cache
def load_schema(name: str) -> dict:
    """The JSON Schema ``clearfast_gis/schemas/<name>.schema.json`` as a dict."""
    path = Path(__file__).resolve().parents[1] / "schemas" / f"{name}.schema.json"
    return json.loads(path.read_text(encoding="utf-8"))


@cache
def _validator(name: str):
    import jsonschema

    schema = load_schema(name)
    cls = jsonschema.validators.validator_for(schema)
    return cls(schema, format_checker=cls.FORMAT_CHECKER)


def validate_record(record: dict, schema_name: str, path: str | os.PathLike | None,
                    prefix: str = "") -> None:
    """Raise :class:`InvalidInput` naming the first invalid field of ``record``.

    Parameters
    ----------
    record : dict
        The instance to validate.
    schema_name : str
        ``"anomaly"`` or ``"products"``.
    path : path or None
        File reported in the error.
    prefix : str
        Prefix of the reported field, e.g. ``"suspects[3]"``.
    """
    errors = sorted(_validator(schema_name).iter_errors(record),
                    key=lambda e: (len(e.absolute_path), list(map(str, e.absolute_path))))
    if not errors:
        return
    err = errors[0]
    parts = [prefix] if prefix else []
    for p in err.absolute_path:
        if isinstance(p, int):
            parts[-1:] = [f"{parts[-1] if parts else ''}[{p}]"]
        else:
            parts.append(str(p))
    if err.validator == "required":
        missing = err.message.split("'")[1] if "'" in err.message else err.message
        parts.append(missing)
        raise InvalidInput("missing", path, ".".join(parts))
    expected = err.schema.get("x-expected") if isinstance(err.schema, dict) else None
    got = json.dumps(err.instance)[:60] if not isinstance(err.instance, dict) else "an object"
    message = f"expected {expected}, got {got}" if expected else err.message
    raise InvalidInput(message, path, ".".join(parts) or None)
