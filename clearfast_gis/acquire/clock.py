"""The survey clock: UTC from the GNSS receiver's time sentences, or the host clock.

Frames, moves and waits of an acquisition are timed on one clock. In the field the receiver's
UTC (RMC and ZDA sentences) is the reference: a laptop's clock may be minutes off and nothing
corrects it on a site without network. :class:`GnssClock` keeps the latest few time sentences
with the host's monotonic clock at their arrival and extrapolates::

    now = max_i (utc_i + time_scale * (mono_now - mono_i))

The maximum picks the sentence that arrived with the least delay (serial latency only ever
makes a sentence late), and the result never goes backwards. The clock gives a time once
:data:`LOCK_AFTER` consecutive time sentences agree (within ``max_jump_s``); after that lock a
sentence that disagrees with the extrapolation by more than ``max_jump_s`` (a receiver's
cold-start or week-rollover date that passed the logger's checks) is refused, so one bad
sentence never moves the survey clock; before the lock, a disagreeing sentence restarts the
count. ``time_scale`` is 1
for a real receiver; a device simulator running its scene faster than real time (``clearfast
simulate-devices --time-scale``) announces its factor in the ports file, so that the same code
waits 4 h of scene time in 4 h / time_scale of wall time. The accuracy is the latency of the
NMEA sentences (typically 0.05-0.2 s), ample for a 0.5 s settle time and 2-3 s per position.

:class:`HostClock` is the fallback when no receiver is connected. Both clocks offer ``now()``
(UTC epoch seconds) and ``sleep(dt_s)`` (``dt_s`` survey seconds).
"""

from __future__ import annotations

import collections
import threading
import time
from collections.abc import Callable

from clearfast_gis.errors import ClearfastError

#: consistent time sentences after which the clock refuses a sentence that jumps
LOCK_AFTER = 2

#: wall seconds a time sentence may arrive late (a busy host) on top of ``max_jump_s``
LATE_WALL_S = 10.0


class ClockError(ClearfastError):
    """The survey clock has no time yet (no RMC or ZDA sentence received)."""


class SurveyClock:
    """Base of the survey clocks: ``now()`` and waits in survey seconds.

    Attributes
    ----------
    time_scale : float
        Survey seconds per wall second.
    """

    time_scale = 1.0

    def now(self) -> float:
        """UTC epoch seconds."""
        raise NotImplementedError

    def sleep(self, dt_s: float) -> None:
        """Wait ``dt_s`` survey seconds (``dt_s / time_scale`` wall seconds; nothing for
        negative values)."""
        time.sleep(max(0.0, float(dt_s)) / self.time_scale)

    def wait(self, event: threading.Event, dt_s: float) -> bool:
        """Wait ``dt_s`` survey seconds or until ``event`` is set; True if it was set."""
        return event.wait(max(0.0, float(dt_s)) / self.time_scale)


class HostClock(SurveyClock):
    """The host's UTC clock (``time.time``), real time."""

    def now(self) -> float:
        """UTC epoch seconds."""
        return time.time()


class GnssClock(SurveyClock):
    """UTC extrapolated from the receiver's latest time sentences.

    Parameters
    ----------
    time_scale : float
        Survey seconds per wall second: 1 for a real receiver, the simulator's factor for an
        accelerated digital twin.
    mono : callable
        Host monotonic clock, seconds.
    window : int
        Number of recent time sentences kept.
    max_jump_s : float
        Largest disagreement, survey seconds, between a time sentence and the clock's
        extrapolation that is still a consistent sentence.

    Attributes
    ----------
    n_observed : int
        Time sentences received.
    n_refused : int
        Time sentences refused for jumping away from a locked clock.
    """

    def __init__(self, time_scale: float = 1.0, mono: Callable[[], float] = time.monotonic,
                 window: int = 16, max_jump_s: float = 3600.0) -> None:
        if not time_scale > 0:
            raise ValueError(f"time_scale must be positive, got {time_scale}")
        self.time_scale = float(time_scale)
        self._mono = mono
        self._recent: collections.deque[tuple[float, float]] = collections.deque(maxlen=window)
        self._last = float("-inf")
        self._lock = threading.Lock()
        self._ready = threading.Event()
        self.n_observed = 0
        self.n_refused = 0
        self.max_jump_s = float(max_jump_s)
        self._consistent = 0

    def observe(self, utc_s: float, mono_s: float | None = None) -> bool:
        """Record a time sentence: its UTC epoch seconds and its arrival (host monotonic
        seconds; default now). Usable as :class:`~clearfast_gis.acquire.gnss.GnssLogger`'s
        ``on_time``. Returns False when the sentence was refused (see the module
        docstring)."""
        arrived = self._mono() if mono_s is None else float(mono_s)
        utc = float(utc_s)
        with self._lock:
            self.n_observed += 1
            if self._recent:
                expected = max(u + self.time_scale * (arrived - m) for u, m in self._recent)
                # late delivery of a sentence (a busy host) counts in wall seconds
                if abs(utc - expected) > self.max_jump_s + self.time_scale * LATE_WALL_S:
                    if self._consistent >= LOCK_AFTER:
                        self.n_refused += 1
                        return False
                    self._recent.clear()
                    self._consistent = 0
            self._recent.append((utc, arrived))
            self._consistent += 1
            locked = self._consistent >= LOCK_AFTER
        if locked:
            self._ready.set()
        return True

    @property
    def ready(self) -> bool:
        """True once :data:`LOCK_AFTER` consecutive time sentences agreed."""
        return self._ready.is_set()

    def wait_ready(self, timeout_s: float) -> bool:
        """Wait up to ``timeout_s`` wall seconds for the clock's lock (:attr:`ready`)."""
        return self._ready.wait(timeout_s)

    def age_s(self) -> float:
        """Wall seconds since the latest time sentence arrived (inf before the first)."""
        with self._lock:
            if not self._recent:
                return float("inf")
            return self._mono() - self._recent[-1][1]

    def now(self) -> float:
        """UTC epoch seconds, never less than a previous reading.

        Raises
        ------
        ClockError
            Before the lock (:attr:`ready`).
        """
        mono = self._mono()
        with self._lock:
            if not self._recent:
                raise ClockError("no UTC time from the GNSS receiver yet (no RMC or ZDA "
                                 "sentence)", "gnss")
            if self._consistent < LOCK_AFTER:
                raise ClockError(f"no UTC time from the GNSS receiver yet ({LOCK_AFTER} "
                                 "consecutive RMC or ZDA sentences must agree)", "gnss")
            t = max(utc + self.time_scale * (mono - m) for utc, m in self._recent)
            self._last = max(self._last, t)
            return self._last
