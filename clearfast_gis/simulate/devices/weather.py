"""Simulated weather station: a datalogger answering ``GET <record>`` polls with TOA5 lines."""

from __future__ import annotations

import re
import threading
from collections.abc import Callable

import numpy as np

from clearfast_gis.survey.toa5 import WeatherLog, toa5_text

_GET = re.compile(rb"^\s*GET\s+(\d+)\s*$")


class SimulatedWeatherStation:
    """The poll protocol of :mod:`clearfast_gis.acquire.weather` over a table of records.

    Record ``k`` (numbered from 0 in table order) exists once the scene clock reaches its
    time. ``GET n`` is answered with the existing records from ``n`` on, at most ``page`` of
    them, then ``END`` (or ``MORE`` when records were left for the next request). Anything
    else gets ``ERR unknown command``.

    Parameters
    ----------
    records : WeatherLog
        The station's 1-minute table.
    clock : callable
        Scene clock, UTC epoch seconds.
    page : int
        Most records in one reply.

    Attributes
    ----------
    requests : list of int
        Record numbers asked for, in order.
    """

    def __init__(self, records: WeatherLog, clock: Callable[[], float], page: int = 60,
                 station: str = "clearfast_sim") -> None:
        self.times_s = np.asarray(records.time_s, dtype=float)
        text = toa5_text(records, station).split("\r\n")
        self.lines = [(line + "\r\n").encode("ascii") for line in text[4:] if line]
        #: the field-name and units lines each reply starts with (columns go by name)
        self.header = "".join(line + "\r\n" for line in text[1:3]).encode("ascii")
        self.clock = clock
        self.page = int(page)
        self.requests: list[int] = []
        self._in = bytearray()
        self._out = bytearray()
        self._lock = threading.Lock()

    def feed(self, data: bytes) -> None:
        """Take request bytes; every complete line is answered."""
        self._in += data
        while (end := self._in.find(b"\n")) >= 0:
            line = bytes(self._in[:end]).strip()
            del self._in[:end + 1]
            if line:
                self._answer(line)

    def _answer(self, line: bytes) -> None:
        m = _GET.match(line)
        if not m:
            reply = b"ERR unknown command\r\n"
        else:
            first = int(m.group(1))
            self.requests.append(first)
            exist = int(np.searchsorted(self.times_s, self.clock(), side="right"))
            last = min(exist, first + self.page)
            reply = self.header + b"".join(self.lines[first:last])
            reply += b"MORE\r\n" if last < exist else b"END\r\n"
        with self._lock:
            self._out += reply

    def pending_output(self) -> bytes:
        """The replies not yet sent."""
        with self._lock:
            data, self._out = bytes(self._out), bytearray()
        return data
