"""A device that pushes lines at scheduled scene times (receivers, loggers)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np


class ScheduledLines:
    """Protocol engine sending line ``k`` once the clock passes ``times_s[k]``.

    Lines scheduled before the engine starts are never sent (a device talking to nobody):
    the first line sent is the first one due after creation, or after :meth:`restart` when
    the scene clock was set back since. Input is ignored.

    Parameters
    ----------
    times_s : array (N,)
        Scene UTC epoch seconds of the lines, increasing.
    make_line : callable
        ``make_line(k) -> bytes``: line ``k`` with its line ending, built when due (so that
        faults switched on meanwhile can change it).
    clock : callable
        Scene clock, UTC epoch seconds.
    """

    def __init__(self, times_s: np.ndarray, make_line: Callable[[int], bytes],
                 clock: Callable[[], float]) -> None:
        self.times_s = np.asarray(times_s, dtype=float)
        self.make_line = make_line
        self.clock = clock
        self.restart()

    def restart(self) -> None:
        """Send from the scene clock's time now on (after the clock was set back: the lines
        due meanwhile are sent again, those due before now are skipped)."""
        self._next: int = int(np.searchsorted(self.times_s, self.clock(), side="right"))

    def feed(self, data: bytes) -> None:
        """Input is ignored (a talker-only device)."""

    def pending_output(self) -> bytes:
        """Lines that fell due since the last call."""
        now = self.clock()
        end = int(np.searchsorted(self.times_s, now, side="right"))
        out = b"".join(self.make_line(k) for k in range(self._next, end))
        self._next = max(self._next, end)
        return out

    @property
    def finished(self) -> bool:
        """True once every line was sent."""
        return self._next >= self.times_s.size
