"""Checkpoints of a processing run: what is finished, so a re-run resumes.

The state lives in ``PRODUCTS/.clearfast/state.json`` and is rewritten atomically after every
finished unit of work (a scan mosaic, the anomalies). A unit counts as finished only when its
record matches the current inputs and parameters and its product file still has the recorded
checksum.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from clearfast_gis.atomic import write_text
from clearfast_gis.export.manifest import sha256_file


class RunState:
    """The record of finished work in a products folder.

    Parameters
    ----------
    products : path
        Products folder.
    key : str
        Identity of the run's inputs and parameters; a stored state with another key is
        discarded.
    """

    def __init__(self, products: str | os.PathLike, key: str) -> None:
        self.products = Path(products)
        self.path = self.products / ".clearfast" / "state.json"
        self.key = key
        self.units: dict[str, dict] = {}
        if self.path.exists():
            try:
                stored = json.loads(self.path.read_text())
            except (OSError, ValueError):
                stored = {}
            if stored.get("key") == key:
                self.units = stored.get("units", {})

    def done(self, unit: str, files: list[str] | None = None) -> dict | None:
        """The record of ``unit`` if finished and its files unchanged, else None."""
        rec = self.units.get(unit)
        if rec is None:
            return None
        for rel, digest in rec.get("files", {}).items():
            p = self.products / rel
            if not p.exists() or sha256_file(p) != digest:
                return None
        if files is not None and set(files) - set(rec.get("files", {})):
            return None
        return rec

    def finish(self, unit: str, record: dict, files: list[str] = ()) -> None:
        """Record ``unit`` as finished with the checksums of its product ``files``."""
        rec = dict(record)
        rec["files"] = {rel: sha256_file(self.products / rel) for rel in files}
        self.units[unit] = rec
        write_text(self.path, json.dumps({"key": self.key, "units": self.units}, indent=1,
                                         sort_keys=True))

    def drop(self, prefix: str) -> None:
        """Forget every unit whose name starts with ``prefix``."""
        self.units = {k: v for k, v in self.units.items() if not k.startswith(prefix)}
