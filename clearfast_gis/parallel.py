"""Threads for the chain's independent pieces of work (images of a stack, scans).

The heavy kernels release the GIL (numba ``nogil``, OpenCV, GDAL), so threads share one
process's memory and run on all cores. ``CLEARFAST_THREADS`` caps the threads (a batch worker
sets it so that its processes do not oversubscribe the machine).
"""

from __future__ import annotations

import os
from collections import deque
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import Future, ThreadPoolExecutor
from contextlib import contextmanager
from typing import TypeVar

import cv2

from clearfast_gis import kernels

T = TypeVar("T")
R = TypeVar("R")

MAX_THREADS = 4
"""Threads used at most by default (the chain's stages stop scaling beyond)."""


def n_threads() -> int:
    """Threads to use: ``CLEARFAST_THREADS`` if set (>= 1), else min(CPU count, 4)."""
    env = os.environ.get("CLEARFAST_THREADS", "").strip()
    if env.isdigit() and int(env) >= 1:
        return int(env)
    try:
        cpus = len(os.sched_getaffinity(0))
    except AttributeError:  # not Linux
        cpus = os.cpu_count() or 1
    return max(1, min(cpus, MAX_THREADS))


def thread_map(fn: Callable[[T], R], items: Iterable[T], threads: int | None = None
               ) -> list[R]:
    """``[fn(x) for x in items]`` on a pool of threads, results in the order of ``items``.

    The first exception raised by ``fn`` is raised here (after the running calls finish).
    """
    items = list(items)
    n = n_threads() if threads is None else max(1, int(threads))
    if n == 1 or len(items) < 2:
        return [fn(x) for x in items]
    pool = ThreadPoolExecutor(min(n, len(items)), thread_name_prefix="clearfast")
    try:
        return list(pool.map(fn, items))
    finally:  # on an error or Ctrl-C, the calls not started are dropped, not waited for
        pool.shutdown(wait=True, cancel_futures=True)


def thread_imap(fn: Callable[[T], R], items: Iterable[T], threads: int | None = None,
                ahead: int = 8) -> Iterator[R]:
    """``fn`` over ``items`` on a pool of threads, yielded lazily in the order of ``items``.

    At most ``ahead`` results per thread are computed ahead of the consumer (bounded memory);
    the consumer's own work (e.g. inserting projected frames into a mosaic in scan order)
    overlaps with the next calls.
    """
    n = n_threads() if threads is None else max(1, int(threads))
    if n == 1:
        for x in items:
            yield fn(x)
        return
    window: deque[Future] = deque()
    with ThreadPoolExecutor(n, thread_name_prefix="clearfast") as pool:
        try:
            for x in items:
                window.append(pool.submit(fn, x))
                if len(window) >= ahead * n:
                    yield window.popleft().result()
            while window:
                yield window.popleft().result()
        finally:
            for f in window:
                f.cancel()


@contextmanager
def serial_kernels() -> Iterator[None]:
    """Run a block with the libraries' own thread pools off (restored afterwards).

    The chain parallelises over frames, images and scans with :func:`thread_map`; OpenCV
    splitting each call over the same cores on top of that only adds the cost of waking its
    workers: on a 320 x 256 frame, blur and remap take twice the CPU time with two OpenCV
    threads as with one, for no gain in wall time when every core is already busy.

    With the reference kernels (:func:`clearfast_gis.kernels.reference`, entered before this
    block) SimpleITK runs on one thread too: its multi-threaded registration adds the threads'
    partial metric sums in the order they finish, so the same registration gave results a few
    1e-11 px apart from call to call; on one thread it gives the same bits every time. This is
    the one place outside :mod:`clearfast_gis.kernels` that asks which set is active: it sets
    a library's thread pool (a thread-count policy), it chooses no kernel.
    """
    before = cv2.getNumThreads()
    cv2.setNumThreads(1)
    sitk_before = None
    if kernels.reference():
        import SimpleITK as sitk  # only the reference kernels need it (1 s to import)

        sitk_before = sitk.ProcessObject.GetGlobalDefaultNumberOfThreads()
        sitk.ProcessObject.SetGlobalDefaultNumberOfThreads(1)
    try:
        yield
    finally:
        cv2.setNumThreads(before)
        if sitk_before is not None:
            sitk.ProcessObject.SetGlobalDefaultNumberOfThreads(sitk_before)
