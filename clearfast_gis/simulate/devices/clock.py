"""The twin clock: scene UTC running ``time_scale`` times faster than the host's clock.

The clock can be held still (:meth:`TwinClock.paused`) while the twin does work that takes no
time in the world it simulates, such as rendering a frame: an exposure is instantaneous, but
rendering one takes milliseconds of wall time, which at a time scale of 2000 would be seconds
of scene time.
"""

from __future__ import annotations

import contextlib
import threading
import time
from collections.abc import Callable, Iterator


class TwinClock:
    """Scene time of the device simulators.

    ``now() = start_s + time_scale * (mono() - mono_at_start)``.

    Parameters
    ----------
    start_s : float
        Scene UTC epoch seconds at creation.
    time_scale : float
        Scene seconds per wall second (1 = real time; 1000 runs a 24 h survey in 86 s).
    mono : callable
        Host monotonic clock, seconds.
    """

    def __init__(self, start_s: float, time_scale: float = 1.0,
                 mono: Callable[[], float] = time.monotonic) -> None:
        if not time_scale > 0:
            raise ValueError(f"time_scale must be positive, got {time_scale}")
        self.start_s = float(start_s)
        self.time_scale = float(time_scale)
        self._mono = mono
        self._m0 = mono()
        self._held_at: float | None = None
        self._holds = 0
        self._lock = threading.Lock()

    def restart(self, start_s: float | None = None) -> None:
        """Set the scene time to ``start_s`` (default: the original start) now."""
        with self._lock:
            self.start_s = self.start_s if start_s is None else float(start_s)
            self._m0 = self._mono()

    def now(self) -> float:
        """Scene UTC epoch seconds."""
        with self._lock:
            mono = self._mono() if self._held_at is None else self._held_at
            return self.start_s + self.time_scale * (mono - self._m0)

    @contextlib.contextmanager
    def paused(self) -> Iterator[float]:
        """Hold the scene time still for the block (nestable); yields the scene time."""
        with self._lock:
            if self._holds == 0:
                self._held_at = self._mono()
            self._holds += 1
        try:
            yield self.now()
        finally:
            with self._lock:
                self._holds -= 1
                if self._holds == 0:
                    self._m0 += self._mono() - self._held_at
                    self._held_at = None

    __call__ = now
