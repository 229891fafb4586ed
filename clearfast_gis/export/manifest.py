"""``products.json``: what a products folder holds and how it was made."""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Mapping
from pathlib import Path

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.export._schema import validate_record

PRODUCTS_FORMAT = "clearfast-products"
MANIFEST_NAME = "products.json"


def sha256_file(path: str | os.PathLike, chunk_bytes: int = 1 << 20) -> str:
    """Checksum text ``"sha256:<64 hex>"`` of a file, as ``products.json`` records inputs."""
    digest = hashlib.sha256()
    with open(path, "rb") as fh:
        while block := fh.read(chunk_bytes):
            digest.update(block)
    return "sha256:" + digest.hexdigest()


def write_products_manifest(path: str | os.PathLike, manifest: Mapping) -> Path:
    """Validate ``manifest`` against ``schemas/products.schema.json`` and write it atomically.

    ``format`` and ``format_version`` are filled in when missing. ``path`` is either the
    ``products.json`` file or the products folder.

    Raises
    ------
    InvalidInput
        Naming the first invalid field.
    """
    target = Path(path)
    if target.suffix.lower() != ".json":
        target = target / MANIFEST_NAME
    doc = {"format": PRODUCTS_FORMAT, "format_version": 1, **dict(manifest)}
    validate_record(doc, "products", target)
    write_text(target, json.dumps(doc, indent=2, sort_keys=False, allow_nan=False) + "\n")
    return target


def read_products_manifest(path: str | os.PathLike) -> dict:
    """Read and validate ``products.json`` (``path`` = the file or the products folder)."""
    target = Path(path)
    if target.is_dir():
        target = target / MANIFEST_NAME
    try:
        doc = json.loads(target.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise InvalidInput("missing: not a products folder", target) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InvalidInput(f"cannot read ({exc})", target) from None
    except json.JSONDecodeError as exc:
        raise InvalidInput(f"not JSON ({exc.msg})", target, f"line {exc.lineno}") from None
    validate_record(doc, "products", target)
    return doc
