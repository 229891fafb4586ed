"""Append-only instrument logs and the splitting of a serial byte stream into lines.

Raw logs are never rewritten: lines are appended whole (one ``write`` per batch of complete
lines, unbuffered), and the file is ``fsync``-ed every few seconds and on close. A stop request
never leaves half a line, because incomplete input stays in :class:`LineSplitter` and is
dropped. If a previous run died mid-write (power cut) and the file does not end with a line
break, one line break is appended first, so the damaged line stays a single line that the
readers skip or report.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from pathlib import Path

from clearfast_gis.errors import OutputError

#: longest line kept, bytes; longer runs without a line break are dropped (wrong baud rate)
MAX_LINE_BYTES = 4096


class LineSplitter:
    """Accumulates bytes and returns complete lines (``\\n``-terminated, terminator kept).

    Parameters
    ----------
    max_line_bytes : int
        A run of more bytes without a line break is discarded and counted in
        :attr:`n_overlong`.
    """

    def __init__(self, max_line_bytes: int = MAX_LINE_BYTES) -> None:
        self._buf = bytearray()
        self.max_line_bytes = int(max_line_bytes)
        self.n_overlong = 0

    def feed(self, data: bytes) -> list[bytes]:
        """Add ``data``; return the lines it completes, each ending in ``b"\\n"``."""
        self._buf += data
        end = self._buf.rfind(b"\n")
        lines: list[bytes] = []
        if end >= 0:
            lines = [bytes(x) + b"\n" for x in self._buf[:end].split(b"\n")]
            del self._buf[:end + 1]
        if len(self._buf) > self.max_line_bytes:
            self._buf.clear()
            self.n_overlong += 1
        return lines

    @property
    def pending(self) -> bytes:
        """Bytes of the incomplete last line."""
        return bytes(self._buf)


class AppendLog:
    """An append-only log file written in whole lines.

    Parameters
    ----------
    path : path
        The log file (created with its parent folder if missing).
    header : bytes, optional
        Written once, when the file is new or empty.
    fsync_interval_s : float
        Seconds between ``fsync`` calls while lines arrive.
    clock : callable
        Monotonic clock for the fsync interval (seconds).

    Raises
    ------
    OutputError
        When the file cannot be opened or written.
    """

    def __init__(self, path: str | os.PathLike, header: bytes = b"",
                 fsync_interval_s: float = 5.0,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.path = Path(path)
        self.fsync_interval_s = float(fsync_interval_s)
        self._clock = clock
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            self._fh = open(self.path, "ab", buffering=0)
        except OSError as exc:
            raise OutputError(f"cannot open for appending: {exc.strerror or exc}",
                              self.path) from None
        self.n_lines = 0
        self._last_sync = clock()
        size = self.path.stat().st_size
        self.was_empty = size == 0
        if size == 0 and header:
            self._write(header)
        elif size > 0 and not self._ends_with_newline():
            self._write(b"\n")

    def _ends_with_newline(self) -> bool:
        with open(self.path, "rb") as fh:
            fh.seek(-1, os.SEEK_END)
            return fh.read(1) == b"\n"

    def _write(self, data: bytes) -> None:
        try:
            view = memoryview(data)
            while view:
                n = self._fh.write(view)
                view = view[n:]
        except OSError as exc:
            raise OutputError(f"cannot write: {exc.strerror or exc}", self.path) from None

    def append(self, lines: list[bytes]) -> None:
        """Append complete lines (each must end with ``b"\\n"``) in one write."""
        if not lines:
            return
        if any(not line.endswith(b"\n") for line in lines):
            raise ValueError("AppendLog.append takes complete lines ending with a line break")
        self._write(b"".join(lines))
        self.n_lines += len(lines)
        now = self._clock()
        if now - self._last_sync >= self.fsync_interval_s:
            self.sync()

    def sync(self) -> None:
        """Flush the file to the disk now."""
        try:
            os.fsync(self._fh.fileno())
        except OSError as exc:
            raise OutputError(f"cannot write: {exc.strerror or exc}", self.path) from None
        self._last_sync = self._clock()

    def read_existing(self) -> bytes:
        """The whole current content (to continue record numbers after a restart)."""
        return self.path.read_bytes()

    def close(self) -> None:
        """fsync and close (idempotent)."""
        if self._fh.closed:
            return
        try:
            self.sync()
        finally:
            self._fh.close()

    def __enter__(self) -> AppendLog:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
