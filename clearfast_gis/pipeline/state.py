"""Checkpoints of a processing run: what is finished, so a re-run resumes.

The state lives in ``PRODUCTS/.clearfast/state.json`` and is rewritten atomically after every
finished unit of work (band offsets, a scan mosaic, the anomalies). A unit counts as finished
only when its record matches the current inputs and parameters and its product files still
have the recorded checksums.

Opening the state also

- creates the products folder, so an unwritable destination fails at once with one line
  naming it, before any work;
- takes an exclusive lock (``.clearfast/lock``, released by the kernel however the process
  ends, ``SIGKILL`` included), so two processes never write into one products folder;
- removes temporary files left by a killed run (``.NAME.<random>.ext.part``, see
  :mod:`clearfast_gis.atomic`): under the lock no live writer owns them.
"""

from __future__ import annotations

import contextlib
import fcntl
import json
import os
from pathlib import Path

from clearfast_gis.atomic import _describe_os_error, write_text
from clearfast_gis.errors import OutputError
from clearfast_gis.export.manifest import sha256_file

STATE_DIR = ".clearfast"


def is_temporary(name: str) -> bool:
    """Whether a file name is one of :func:`clearfast_gis.atomic.atomic_path`'s temporaries."""
    return name.startswith(".") and (name.endswith(".part") or ".part." in name)


def remove_temporaries(folder: str | os.PathLike) -> list[Path]:
    """Delete the atomic writers' temporary files under ``folder``; return what was removed."""
    removed = []
    for dirpath, _dirs, names in os.walk(folder):
        for name in names:
            if is_temporary(name):
                p = Path(dirpath) / name
                with contextlib.suppress(FileNotFoundError):
                    p.unlink()
                    removed.append(p)
    return removed


class RunState:
    """The record of finished work in a products folder.

    Parameters
    ----------
    products : path
        Products folder (created if missing).
    key : str
        Identity of the run's inputs and parameters; a stored state with another key is
        discarded.

    Raises
    ------
    OutputError
        The products folder cannot be created or written, or another run holds its lock.
    """

    def __init__(self, products: str | os.PathLike, key: str) -> None:
        self.products = Path(products)
        self.path = self.products / STATE_DIR / "state.json"
        self.key = key
        self.units: dict[str, dict] = {}
        self._lock = _acquire_lock(self.products)
        remove_temporaries(self.products)
        if self.path.exists():
            try:
                stored = json.loads(self.path.read_text())
            except (OSError, ValueError):
                stored = {}
            if isinstance(stored, dict) and stored.get("key") == key:
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

    def close(self) -> None:
        """Release the products folder's lock (also released when the process ends)."""
        if self._lock is not None and not self._lock.closed:
            self._lock.close()
        _HELD.pop(os.path.abspath(self.products), None)


_HELD: dict[str, object] = {}
"""Locks this process holds, by products folder: the lock keeps other processes out, while a
later run in the same process (a retry in the QGIS plugin after a failure) reuses it."""


def _acquire_lock(products: Path):
    key = os.path.abspath(products)
    held = _HELD.get(key)
    if held is not None and not held.closed:
        return held
    try:
        (products / STATE_DIR).mkdir(parents=True, exist_ok=True)
        fh = open(products / STATE_DIR / "lock", "a+b")  # held for the whole run
    except OSError as exc:
        raise OutputError(f"cannot write the products folder: {_describe_os_error(exc)}",
                          products) from None
    try:
        fcntl.flock(fh.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        fh.close()
        raise OutputError("another clearfast run is writing to this products folder",
                          products) from None
    _HELD[key] = fh
    return fh
