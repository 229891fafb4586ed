"""The acquisition's event log: ``acquisition/events.csv``, one line per thing that happened.

``time_utc,source,event,detail``: survey-clock UTC (the host's clock before the GNSS time is
known), the instrument or ``mission``, what happened (``opened``, ``fix``, ``disconnected``,
``reconnected``, ``no reply``, ``move``, ``retry``, ``late``, ``missed``, ``start``, ``end``),
and a free text. Append-only (:class:`~clearfast_gis.acquire.appendlog.AppendLog`), written
from every instrument's thread.
"""

from __future__ import annotations

import csv
import io
import os
import threading
import time
from collections.abc import Callable

from clearfast_gis.acquire.appendlog import AppendLog
from clearfast_gis.timeutil import format_utc

EVENTS_HEADER = "time_utc,source,event,detail\n"


class EventLog:
    """Thread-safe appender of ``events.csv`` rows.

    Parameters
    ----------
    path : path
        ``<survey>/acquisition/events.csv`` (appended to).
    clock : callable
        UTC clock, epoch seconds; may raise until it is ready (then the host clock is used).
    echo : callable, optional
        ``echo(source, event, detail)`` for events worth showing (every event but moves).
    """

    def __init__(self, path: str | os.PathLike, clock: Callable[[], float] = time.time,
                 echo: Callable[[str, str, str], None] | None = None) -> None:
        self.log = AppendLog(path, EVENTS_HEADER.encode("ascii"), fsync_interval_s=5.0)
        self.clock = clock
        self.echo = echo
        self.counts: dict[str, int] = {}
        self._lock = threading.Lock()

    def _now(self) -> float:
        try:
            return self.clock()
        except Exception:  # the survey clock is not ready yet
            return time.time()

    def __call__(self, source: str, event: str, detail: str = "") -> None:
        """Record one event (usable as an ``on_event`` sink)."""
        buf = io.StringIO()
        csv.writer(buf, lineterminator="\n").writerow(
            [format_utc(self._now()), source, event, " ".join(str(detail).split())])
        with self._lock:
            self.log.append([buf.getvalue().encode("utf-8")])
            key = f"{source} {event}"
            self.counts[key] = self.counts.get(key, 0) + 1
        if self.echo is not None and event != "move":
            self.echo(source, event, detail)

    def close(self) -> None:
        """fsync and close."""
        with self._lock:
            self.log.close()
