"""What a batch shows while it runs (a bar, or JSON lines) and the summary table after it."""

from __future__ import annotations

import json
import sys
import threading
from collections.abc import Sequence
from typing import TextIO

from clearfast_gis.batch.jobs import SurveyResult


class BatchProgress:
    """Per-survey ``start`` / ``finish`` events, shown as a bar or written as JSON lines.

    Parameters
    ----------
    mode : {"bar", "json", "none"}
        ``bar``: a tqdm bar of finished surveys on stderr with a line per finished survey;
        ``json``: one object per line on ``stream``: ``{"event": "start", "survey", "worker"}``,
        ``{"event": "finish", "survey", "status", "anomalies", "seconds", "error", ...}``.
    total : int
        Number of surveys.
    stream : text stream, optional
        Where JSON lines go (default stdout).

    Events may come from several threads; they are serialised.
    """

    def __init__(self, mode: str, total: int, stream: TextIO | None = None) -> None:
        if mode not in ("bar", "json", "none"):
            raise ValueError(f"unknown progress mode {mode!r}")
        self.mode = mode
        self.total = int(total)
        self.stream = stream if stream is not None else sys.stdout
        self._lock = threading.Lock()
        self._finished: set[str] = set()
        self._running: set[str] = set()
        self._bar = None
        if mode == "bar":
            from tqdm import tqdm

            self._bar = tqdm(total=total, desc="surveys", unit="survey", file=sys.stderr)

    def __call__(self, event: dict) -> None:
        """Take one event (``start`` or ``finish``)."""
        with self._lock:
            kind, name = event.get("event"), event.get("name", event.get("survey"))
            if kind == "start":
                if name in self._finished:
                    return
                self._running.add(name)
                self._write({"event": "start", "survey": name, "worker": event.get("worker")})
                if self._bar is not None:
                    self._bar.set_postfix_str(", ".join(sorted(self._running)))
            elif kind == "finish":
                self._running.discard(name)
                self._finished.add(name)
                self._write({"event": "finish", "survey": name, "status": event.get("status"),
                             "anomalies": event.get("anomalies"),
                             "seconds": round(float(event.get("seconds") or 0.0), 3),
                             "error": event.get("error"), "products": event.get("products"),
                             "worker": event.get("worker"),
                             "done": len(self._finished), "total": self.total})
                if self._bar is not None:
                    self._bar.write(finish_line(event), file=sys.stderr)
                    self._bar.set_postfix_str(", ".join(sorted(self._running)))
                    self._bar.update(1)

    def close(self) -> None:
        """End the bar."""
        if self._bar is not None:
            self._bar.close()
            self._bar = None

    def _write(self, obj: dict) -> None:
        if self.mode == "json":
            self.stream.write(json.dumps(obj) + "\n")
            self.stream.flush()


def finish_line(event: dict) -> str:
    """One line for a finished survey: ``name: ok, 12 anomalies, 31.2 s`` or its error."""
    name = event.get("name", event.get("survey"))
    if event.get("status") == "ok":
        return f"{name}: ok, {event.get('anomalies')} anomalies, {event.get('seconds'):.1f} s"
    return f"{name}: FAILED: {event.get('error')}"


def summary_table(results: Sequence[SurveyResult]) -> str:
    """The summary as a fixed-width text table: survey, status, anomalies, time, error."""
    header = ("survey", "status", "anomalies", "time")
    rows = [(r.name, r.status, "-" if r.anomalies is None else str(r.anomalies),
             f"{r.seconds:.1f} s") for r in results]
    widths = [max(len(h), *(len(row[i]) for row in rows)) if rows else len(h)
              for i, h in enumerate(header)]

    def fmt(row) -> str:
        cells = [row[0].ljust(widths[0]), row[1].ljust(widths[1]), row[2].rjust(widths[2]),
                 row[3].rjust(widths[3])]
        return "  ".join(cells).rstrip()

    lines = [fmt(header), "  ".join("-" * w for w in widths)]
    for r, row in zip(results, rows, strict=True):
        lines.append(fmt(row) + (f"  {r.error}" if r.error else ""))
    n_failed = sum(r.status != "ok" for r in results)
    lines.append(f"{len(results)} survey(s): {len(results) - n_failed} ok, {n_failed} failed")
    return "\n".join(lines)


def summary_json(results: Sequence[SurveyResult]) -> dict:
    """The summary as the final JSON line's object."""
    n_failed = sum(r.status != "ok" for r in results)
    return {"event": "summary", "surveys": len(results), "ok": len(results) - n_failed,
            "failed": n_failed, "results": [r.as_dict() for r in results]}
