"""Checkpoints of a processing run: what is finished, so a re-run resumes.

The state lives in ``PRODUCTS/.clearfast/state.json`` and is rewritten atomically after every
finished unit of work (band offsets, a scan mosaic, the anomalies). Units are named
``STAGE`` or ``STAGE/PART`` after the stage of :mod:`clearfast_gis.pipeline.stages` that
made them and carry that stage's key (the parameters it depends on, chained with the stages
before it). A unit counts as finished only when the inputs are the same, its stage key is the
current one and its product files still have the recorded checksums.

Opening the state also

- creates the products folder, so an unwritable destination fails at once with one line
  naming it, before any work;
- takes an exclusive lock (``.clearfast/lock``, released by the kernel however the process
  ends, ``SIGKILL`` included), so two processes never write into one products folder;
- removes temporary files left by a killed run (``.NAME.<random>.ext.part``, see
  :mod:`clearfast_gis.atomic`): under the lock no live writer owns them.
"""

from __future__ import annotations

import fcntl
import json
import os
from pathlib import Path

from clearfast_gis.atomic import _describe_os_error, remove_temporaries, write_text
from clearfast_gis.errors import OutputError
from clearfast_gis.export.layout import STATE_DIR
from clearfast_gis.export.manifest import sha256_file


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

    def done(self, unit: str, files: list[str] | None = None, key: str | None = None
             ) -> dict | None:
        """The record of ``unit`` if finished (with stage key ``key`` when given) and its
        files unchanged, else None."""
        rec = self.units.get(unit)
        if rec is None or (key is not None and rec.get("stage_key") != key):
            return None
        for rel, digest in rec.get("files", {}).items():
            p = self.products / rel
            if not p.exists() or sha256_file(p) != digest:
                return None
        if files is not None and set(files) - set(rec.get("files", {})):
            return None
        return rec

    def finish(self, unit: str, record: dict, files: list[str] = (), key: str | None = None
               ) -> None:
        """Record ``unit`` as finished with the checksums of its product ``files`` (and the
        stage key ``key``)."""
        rec = dict(record)
        if key is not None:
            rec["stage_key"] = key
        rec["files"] = {rel: sha256_file(self.products / rel) for rel in files}
        self.units[unit] = rec
        write_text(self.path, json.dumps({"key": self.key, "units": self.units}, indent=1,
                                         sort_keys=True))

    def drop(self, stage: str) -> None:
        """Forget every unit of ``stage`` (``stage`` and ``stage/...``)."""
        self.units = {k: v for k, v in self.units.items()
                      if k != stage and not k.startswith(stage + "/")}

    def close(self) -> None:
        """Release the products folder's lock (also released when the process ends)."""
        if self._lock is not None and not self._lock.closed:
            self._lock.close()
        _HELD.pop(os.path.abspath(self.products), None)


    def stage(self, name: str, key: str) -> StageState:
        """The units of stage ``name`` under its current key."""
        return StageState(self, name, key)


class StageState:
    """One stage's view of the run state: unit names relative to the stage (``""`` is the
    stage's own unit, ``"scan_003"`` is ``STAGE/scan_003``), every unit checked against and
    recorded with the stage's key."""

    def __init__(self, state: RunState, name: str, key: str) -> None:
        self.state, self.name, self.key = state, name, key

    def unit(self, part: str = "") -> str:
        """Full unit name of ``part``."""
        return f"{self.name}/{part}" if part else self.name

    def done(self, part: str = "", files: list[str] | None = None) -> dict | None:
        return self.state.done(self.unit(part), files, key=self.key)

    def finish(self, part: str, record: dict, files: list[str] = ()) -> None:
        self.state.finish(self.unit(part), record, files, key=self.key)

    def files(self, part: str = "") -> dict:
        """Checksums recorded for the unit's files (empty when unknown)."""
        return self.state.units.get(self.unit(part), {}).get("files", {})


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
