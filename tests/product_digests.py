"""Digests of a products folder, for comparing two runs byte for byte (timings aside)."""

from __future__ import annotations

import hashlib
import json
import re
from pathlib import Path

from clearfast_gis.atomic import is_temporary


def product_files(products: Path) -> dict[str, Path]:
    """Files under their final names (temporaries and the state folder left out)."""
    out = {}
    for p in products.rglob("*"):
        rel = p.relative_to(products).as_posix()
        # *.aux.xml: statistics GDAL sidecars that a viewer (QGIS) writes beside the mosaics
        if (p.is_file() and not rel.startswith(".clearfast/") and not is_temporary(p.name)
                and not p.name.endswith(".aux.xml")):
            out[rel] = p
    return out


def comparable_digests(products: Path) -> dict[str, str]:
    """sha256 of every product; products.json and report.html without their timings and
    resources."""
    out = {}
    for rel, p in product_files(products).items():
        data = p.read_bytes()
        if rel == "products.json":
            doc = json.loads(data)
            doc.pop("timings_s")
            doc.pop("resources")  # wall/CPU/memory of this run
            data = json.dumps(doc, sort_keys=True).encode()
        elif rel == "report.html":
            data, n = re.subn(rb"<h2>Stage timings</h2><table>.*?</table>", b"", data,
                              flags=re.S)
            assert n == 1
        out[rel] = hashlib.sha256(data).hexdigest()
    return out
