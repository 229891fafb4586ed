"""Reused memory for the calibrated frames of a scan.

A trial scan's calibrated frames are 251 positions x 3 bands of 320 x 256 float32 (247 MB),
held until its mosaic is built; the next scan's are calibrated meanwhile. Memory freshly
obtained from the system is zeroed by the kernel page by page when first written, which cost
about as much CPU time as the calibration kernel that writes it. A :class:`BufferPool` hands
out the blocks of a finished scan again instead: the next scan's calibration overwrites every
element of a block it takes, so the values do not depend on where the memory came from.
"""

from __future__ import annotations

import threading

import numpy as np


class BufferPool:
    """Arrays of released leases, given out again by shape and dtype (thread-safe)."""

    def __init__(self) -> None:
        self._free: dict[tuple, list[np.ndarray]] = {}
        self._lock = threading.Lock()

    def lease(self) -> BufferLease:
        """A new lease: the arrays one piece of work takes, returned together."""
        return BufferLease(self)

    def _take(self, shape: tuple[int, ...], dtype: np.dtype) -> np.ndarray:
        key = (tuple(shape), np.dtype(dtype).str)
        with self._lock:
            free = self._free.get(key)
            if free:
                return free.pop()
        return np.empty(shape, dtype=dtype)

    def _give(self, arrays: list[np.ndarray]) -> None:
        with self._lock:
            for a in arrays:
                self._free.setdefault((a.shape, a.dtype.str), []).append(a)

    def clear(self) -> None:
        """Drop the free arrays (their memory goes back to the allocator)."""
        with self._lock:
            self._free.clear()


class BufferLease:
    """The arrays taken for one piece of work (one scan's calibrated frames)."""

    def __init__(self, pool: BufferPool) -> None:
        self._pool = pool
        self._taken: list[np.ndarray] = []
        self._lock = threading.Lock()

    def empty(self, shape: tuple[int, ...], dtype=np.float32) -> np.ndarray:
        """An array of ``shape`` and ``dtype`` with undefined contents (``np.empty``'s
        contract), a released one when the pool has it."""
        a = self._pool._take(shape, dtype)
        with self._lock:
            self._taken.append(a)
        return a

    def release(self) -> None:
        """Give every array taken back to the pool. The caller must hold no view of them any
        more: they will be overwritten."""
        with self._lock:
            taken, self._taken = self._taken, []
        self._pool._give(taken)
