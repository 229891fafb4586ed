"""Batch conversion on this machine: one process per survey at a time.

A ``ProcessPoolExecutor`` with the ``spawn`` start method: every worker is a fresh
interpreter (no GDAL, numba or thread state inherited through ``fork``), a survey's crash or
memory stays in its process, and there is no scheduler to start. Workers send their ``start``
events through a queue that a thread of the parent reads.
"""

from __future__ import annotations

import multiprocessing
import os
import queue
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed

from clearfast_gis.allocator import keep_freed_memory
from clearfast_gis.batch.jobs import SurveyJob, SurveyResult, convert_survey
from clearfast_gis.parallel import n_threads

_EVENTS = None


def _init_worker(events, threads: int = 0) -> None:
    global _EVENTS
    _EVENTS = events
    keep_freed_memory()  # the worker is a process that runs the chain
    if threads:  # share the cores between the worker processes (clearfast_gis.parallel)
        os.environ.setdefault("CLEARFAST_THREADS", str(threads))


def _emit(event: dict) -> None:
    if _EVENTS is not None:
        _EVENTS.put(event)


def _task(job: SurveyJob, options, resume: bool) -> SurveyResult:
    return convert_survey(job, options, resume, emit=_emit)


def run_local(jobs: Sequence[SurveyJob], workers: int, options=None, resume: bool = True,
              on_event: Callable[[dict], None] | None = None) -> list[SurveyResult]:
    """Convert ``jobs`` with ``workers`` local processes.

    Parameters
    ----------
    jobs : sequence of SurveyJob
    workers : int
        Processes (>= 1).
    options : ProcessOptions, optional
    resume : bool
    on_event : callable, optional
        Called in the parent with every ``start`` event and every ``finish`` event
        (``{"event": "finish", **SurveyResult.as_dict()}``).

    Returns
    -------
    list of SurveyResult
        In the order of ``jobs``.
    """
    ctx = multiprocessing.get_context("spawn")
    events = ctx.Queue()
    stop = threading.Event()

    def pump() -> None:
        while not stop.is_set():
            try:
                ev = events.get(timeout=0.1)
            except queue.Empty:
                continue
            if on_event is not None:
                on_event(ev)

    reader = threading.Thread(target=pump, daemon=True)
    reader.start()
    results: dict[int, SurveyResult] = {}
    try:
        with ProcessPoolExecutor(max_workers=max(1, int(workers)), mp_context=ctx,
                                 initializer=_init_worker,
                                 initargs=(events, max(1, n_threads() // workers))) as pool:
            futures = {pool.submit(_task, job, options, resume): i for i, job in enumerate(jobs)}
            for fut in as_completed(futures):
                i = futures[fut]
                try:
                    res = fut.result()
                except Exception as exc:  # the worker process died (killed, out of memory)
                    job = jobs[i]
                    res = SurveyResult(job.name, "failed", None, 0.0,
                                       f"worker process lost: {type(exc).__name__}: {exc}",
                                       job.products, "")
                _drain(events, on_event)
                results[i] = res
                if on_event is not None:
                    on_event({"event": "finish", **res.as_dict()})
    finally:
        stop.set()
        reader.join()
        _drain(events, on_event)
        events.close()
    return [results[i] for i in range(len(jobs))]


def _drain(events, on_event) -> None:
    while True:
        try:
            ev = events.get_nowait()
        except (queue.Empty, OSError, ValueError):
            return
        if on_event is not None:
            on_event(ev)
