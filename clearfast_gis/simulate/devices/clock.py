"""The twin clock: scene UTC running ``time_scale`` times faster than the host's clock."""

from __future__ import annotations

import time
from collections.abc import Callable


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

    def now(self) -> float:
        """Scene UTC epoch seconds."""
        return self.start_s + self.time_scale * (self._mono() - self._m0)

    __call__ = now
