"""Progress reporting: a bar for people, JSON lines for programs, nothing when quiet.

Every long stage takes a :class:`Progress` and calls :meth:`Progress.advance`. The command line
builds one from ``--progress bar|json|none``; the QGIS plugin parses the JSON lines.
"""

from __future__ import annotations

import json
import sys
import threading
import time
from typing import TextIO


class Progress:
    """Progress of one stage of ``total`` steps.

    Parameters
    ----------
    mode : {"bar", "json", "none"}
        ``bar`` draws a tqdm bar on stderr, ``json`` writes one JSON object per line on
        stdout: ``{"stage": ..., "done": ..., "total": ..., "fraction": ..., "elapsed_s": ...}``.
    stream : text stream, optional
        Where JSON lines go (default ``sys.stdout``).
    """

    def __init__(self, mode: str = "bar", stream: TextIO | None = None) -> None:
        if mode not in ("bar", "json", "none"):
            raise ValueError(f"unknown progress mode {mode!r}")
        self.mode = mode
        self.stream = stream if stream is not None else sys.stdout
        self._bar = None
        self._stage = ""
        self._total = 0
        self._done = 0
        self._t0 = time.perf_counter()
        self._lock = threading.RLock()  # stages advance from helper threads too

    def start(self, stage: str, total: int) -> None:
        """Begin a stage of ``total`` steps."""
        self.close()
        self._stage, self._total, self._done = stage, int(total), 0
        self._t0 = time.perf_counter()
        if self.mode == "bar":
            from tqdm import tqdm

            self._bar = tqdm(total=total, desc=stage, unit="step", file=sys.stderr, leave=True)
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
            self._write({"event": "message", "stage": self._stage, "message": text})

    def close(self) -> None:
        """End the current stage."""
        if self._bar is not None:
            self._bar.close()
            self._bar = None
            self._emit(event="end")
        elif self._stage and self.mode == "json":
            self._emit(event="end")
        self._stage = ""

    def _emit(self, event: str, **info: object) -> None:
        if self.mode != "json":
            return
        frac = self._done / self._total if self._total else 1.0
        self._write({
            "event": event, "stage": self._stage, "done": self._done, "total": self._total,
            "fraction": round(frac, 4), "elapsed_s": round(time.perf_counter() - self._t0, 3),
            **info,
        })

    def _write(self, obj: dict) -> None:
        self.stream.write(json.dumps(obj) + "\n")
        self.stream.flush()


NULL_PROGRESS = Progress("none")
"""A progress reporter that reports nothing (default for library calls)."""
