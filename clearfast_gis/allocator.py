"""The C heap of a processing run: glibc's ``malloc`` told to keep freed memory for reuse.

The chain allocates and frees arrays of 0.1-30 MB tens of thousands of times (a frame's
projection onto its window, a calibrated block of frames, a mosaic band's morphology). With
glibc's defaults such an array is either a fresh ``mmap`` (above the mmap threshold), whose
pages the kernel zeroes on first touch and unmaps when it is freed, or heap memory that
``free`` hands back to the kernel as soon as 128 KiB sit unused at the top of the heap. Both
cost a page fault per 4 KiB every time: on the trial survey 9.6-11.4 s of system time in the
stages after the mosaics alone.

:func:`keep_freed_memory` raises the mmap threshold and the trim threshold (``mallopt``, the
tunables glibc documents as ``M_MMAP_THRESHOLD``, ``M_TRIM_THRESHOLD`` and ``M_TOP_PAD``), so
that freed arrays stay in the heap and are reused without faults. The peak memory grows by
what the heap keeps (at most :data:`TRIM_THRESHOLD_BYTES` of free memory at its top).
Measured in BENCHMARKS.md ("The C heap keeps freed memory").

It is called by the programs that run the chain (the ``clearfast`` program and ``python -m
clearfast_gis.cli.main``, through :func:`clearfast_gis.cli.main.main`; the local batch
workers; :mod:`clearfast_gis.worker`), not by the library's functions nor by
:func:`clearfast_gis.cli.main.cli` called from Python: a process that embeds the toolkit
keeps its own allocator settings. Settings given in the environment
(``MALLOC_*_`` variables or ``GLIBC_TUNABLES``) are left as they are.
"""

from __future__ import annotations

import ctypes
import os
import sys

MMAP_THRESHOLD_BYTES = 64 * 1024 * 1024
"""Arrays at least this large are still mapped on their own (a survey's full stacks, which
are allocated a few times per run), bytes. Smaller ones come from the heap."""

TRIM_THRESHOLD_BYTES = 512 * 1024 * 1024
"""Free memory the heap keeps at its top before giving it back to the kernel, bytes."""

TOP_PAD_BYTES = 64 * 1024 * 1024
"""Extra memory the heap asks the kernel for each time it grows, bytes."""

_M_TRIM_THRESHOLD, _M_TOP_PAD, _M_MMAP_THRESHOLD = -1, -2, -3  # <malloc.h>
_ENV = ("MALLOC_MMAP_THRESHOLD_", "MALLOC_TRIM_THRESHOLD_", "MALLOC_TOP_PAD_", "GLIBC_TUNABLES")


def keep_freed_memory() -> bool:
    """Set glibc's heap to keep freed memory (see the module notes), once per process.

    Returns
    -------
    bool
        True when the settings were applied; False on a C library without ``mallopt``
        (not glibc), or when the environment already sets the allocator.
    """
    if not sys.platform.startswith("linux") or any(k in os.environ for k in _ENV):
        return False
    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):  # no C library handle, or one without mallopt (musl)
        return False
    mallopt.argtypes = [ctypes.c_int, ctypes.c_int]
    mallopt.restype = ctypes.c_int
    return all(mallopt(option, value) == 1 for option, value in (
        (_M_MMAP_THRESHOLD, MMAP_THRESHOLD_BYTES),
        (_M_TRIM_THRESHOLD, TRIM_THRESHOLD_BYTES),
        (_M_TOP_PAD, TOP_PAD_BYTES)))
