"""Progress reporting: a bar for people, JSON lines for programs, nothing when quiet.

Every long stage takes a :class:`Progress` and calls :meth:`Progress.advance`. The command line
builds one from ``--progress bar|json|none``; the QGIS plugin parses the JSON lines.

Inside the processing chain every line is reported under the chain's stage
(:meth:`Progress.chain_stage`, the names of :data:`clearfast_gis.pipeline.stages.STAGES`, the
same names as the resource meter and the run state): ``"stage"`` is the stage's name,
``"label"`` its human label and ``"step"`` what the stage's code calls the step it counts.
"""

from __future__ import annotations

import json
import sys
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import TextIO


class Progress:
    """Progress of one stage of ``total`` steps.

    Parameters
    ----------
    mode : {"bar", "json", "none"}
        ``bar`` draws a tqdm bar on stderr, ``json`` writes one JSON object per line on
        stdout: ``{"event": ..., "stage": ..., "done": ..., "total": ..., "fraction": ...,
        "elapsed_s": ...}``, with ``"label"`` and ``"step"`` inside a chain stage.
    stream : text stream, optional
        Where JSON lines go (default ``sys.stdout``).

    Examples
    --------
    >>> import io
    >>> out = io.StringIO()
    >>> p = Progress("json", stream=out)
    >>> with p.chain_stage("detection", "anomaly detection"):
    ...     p.start("detect", 2)
    ...     p.advance(2)
    >>> events = [json.loads(s) for s in out.getvalue().splitlines()]
    >>> [(e["event"], e["stage"], e.get("step")) for e in events]
    [('stage', 'detection', None), ('start', 'detection', 'detect'),
     ('progress', 'detection', 'detect'), ('end', 'detection', 'detect')]
    """

    def __init__(self, mode: str = "bar", stream: TextIO | None = None) -> None:
        if mode not in ("bar", "json", "none"):
            raise ValueError(f"unknown progress mode {mode!r}")
        self.mode = mode
        self.stream = stream if stream is not None else sys.stdout
        self._bar = None
        self._stage = ""
        self._step = ""
        self._chain: tuple[str, str] | None = None  # (name, label) of the chain's stage
        self._open = False
        self._total = 0
        self._done = 0
        self._t0 = time.perf_counter()
        self._lock = threading.RLock()  # stages advance from helper threads too

    @contextmanager
    def chain_stage(self, name: str, label: str) -> Iterator[None]:
        """Report a block under the chain's stage ``name`` (human ``label`` beside it).

        Opens with a ``{"event": "stage", "stage": name, "label": label}`` line; the steps the
        block starts are reported with ``"stage": name`` and their own name as ``"step"``;
        the bar reads ``name: step``.
        """
        self.close()
        self._chain = (name, label)
        self._stage = name
        if self.mode == "json":
            self._write({"event": "stage", "stage": name, "label": label})
        try:
            yield
        finally:
            self.close()
            self._chain = None
            self._stage = ""

    def start(self, stage: str, total: int) -> None:
        """Begin a stage of ``total`` steps (inside a chain stage: one step of it)."""
        self.close()
        if self._chain is None:
            self._stage, desc = stage, stage
        else:
            self._step = stage
            name, label = self._chain
            desc = f"{name}: {stage}" if stage != name else f"{name} ({label})"
        self._total, self._done, self._open = int(total), 0, True
        self._t0 = time.perf_counter()
        if self.mode == "bar":
            from tqdm import tqdm

            self._bar = tqdm(total=total, desc=desc, unit="step", file=sys.stderr, leave=True)
        self._emit(event="start")

    def advance(self, n: int = 1, **info: object) -> None:
        """Mark ``n`` more steps done; ``info`` is added to the JSON line. Thread-safe."""
        with self._lock:
            self._done += n
            if self._bar is not None:
                self._bar.update(n)
            self._emit(event="progress", **info)

    def message(self, text: str) -> None:
        """A free-text note (shown above the bar, or as a JSON ``message`` line)."""
        if self.mode == "bar":
            from tqdm import tqdm

            tqdm.write(text, file=sys.stderr)
        elif self.mode == "json":
            self._write({"event": "message", "stage": self._stage, **self._chain_info(),
                         "message": text})

    def close(self) -> None:
        """End the current stage (inside a chain stage: its current step)."""
        if self._bar is not None:
            self._bar.close()
            self._bar = None
        if self._open:
            self._emit(event="end")
        self._open = False
        self._step = ""
        self._stage = self._chain[0] if self._chain is not None else ""

    def _chain_info(self) -> dict:
        if self._chain is None:
            return {}
        return {"label": self._chain[1]} | ({"step": self._step} if self._step else {})

    def _emit(self, event: str, **info: object) -> None:
        if self.mode != "json":
            return
        frac = self._done / self._total if self._total else 1.0
        self._write({
            "event": event, "stage": self._stage, **self._chain_info(), "done": self._done,
            "total": self._total, "fraction": round(frac, 4),
            "elapsed_s": round(time.perf_counter() - self._t0, 3), **info,
        })

    def _write(self, obj: dict) -> None:
        self.stream.write(json.dumps(obj) + "\n")
        self.stream.flush()


NULL_PROGRESS = Progress("none")
"""A progress reporter that reports nothing (default for library calls)."""
