"""Threads for the chain's independent pieces of work (images of a stack, scans).

The heavy kernels release the GIL (numba ``nogil``, OpenCV, GDAL), so threads share one
process's memory and run on all cores. ``CLEARFAST_THREADS`` caps the threads (a batch worker
sets it so that its processes do not oversubscribe the machine). Work that holds the GIL
throughout (drawing figures) runs in worker processes instead (:class:`ProcessChunks`).
"""

from __future__ import annotations

import os
import pickle
import subprocess
import sys
from collections import deque
from collections.abc import Callable, Iterable, Iterator, Sequence
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


class ProcessChunks:
    """``fn`` over contiguous chunks of ``items`` in worker processes, started at once;
    :meth:`result` waits and returns ``fn``'s outputs concatenated in the order of ``items``.

    For work that holds the GIL throughout (matplotlib drawing figures), which threads cannot
    share out. ``fn`` is a module-level function that takes a list of items and returns a list
    of as many results; it, the items and the results must pickle, and each result must not
    depend on the chunk it was computed in, so that the results are the same with any number
    of processes. Each worker is a fresh ``python -m clearfast_gis.worker`` (the caller's
    script is not imported again, as ``multiprocessing`` would). ``fn`` runs in this process
    instead, when :meth:`result` is called, with one process (:func:`n_threads` is 1) and for
    the chunks whose worker failed (so that an error is raised here, as itself). Use as a
    context manager: leaving it stops the workers.
    """

    def __init__(self, fn: Callable[[list[T]], list[R]], items: Sequence[T],
                 processes: int | None = None) -> None:
        self._fn = fn
        items = list(items)
        n = min(n_threads() if processes is None else max(1, int(processes)), len(items))
        n = max(n, 1)
        self._chunks = [items[len(items) * i // n:len(items) * (i + 1) // n] for i in range(n)]
        self._workers: list[tuple[subprocess.Popen, Future]] = []
        if n == 1:
            return
        env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in sys.path if p),
               "CLEARFAST_THREADS": "1"}
        try:
            procs = [subprocess.Popen([sys.executable, "-m", "clearfast_gis.worker"],
                                      stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                      stderr=subprocess.DEVNULL, env=env)
                     for _ in self._chunks]
        except OSError:  # no interpreter to start (an embedding program): all of it here
            self._chunks = [items]
            return
        # each worker's pipes on a thread of its own: a large result must not wait for the
        # input of another worker to be written
        self._workers = [(proc, _PIPES.submit(_exchange, proc, pickle.dumps((fn, chunk))))
                         for proc, chunk in zip(procs, self._chunks, strict=True)]

    def result(self) -> list[R]:
        """The results in the order of the items (the first error of ``fn`` is raised)."""
        if not self._workers:
            return self._fn(self._chunks[0])
        out: list[R] = []
        try:
            for chunk, (_proc, answer) in zip(self._chunks, self._workers, strict=True):
                got = answer.result()
                out.extend(self._fn(chunk) if got is None else got)
        finally:
            self.close()
        return out

    def close(self) -> None:
        """Stop the workers still running."""
        for proc, _ in self._workers:
            if proc.poll() is None:
                proc.kill()
            proc.wait()

    def __enter__(self) -> ProcessChunks:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


_PIPES = ThreadPoolExecutor(thread_name_prefix="clearfast-pipe")
"""Threads that feed the worker processes of :class:`ProcessChunks` and read their answers
(they wait on pipes: no CPU)."""


def _exchange(proc: subprocess.Popen, request: bytes) -> list | None:
    """Send a worker its request; its unpickled answer, or None when it failed."""
    try:
        data, _ = proc.communicate(request)
    except OSError:
        return None
    if proc.returncode != 0:
        return None
    try:
        return pickle.loads(data)
    except (pickle.UnpicklingError, EOFError, AttributeError, ImportError):
        return None
