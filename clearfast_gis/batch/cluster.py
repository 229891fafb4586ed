"""Batch conversion on a Dask distributed cluster: one task per survey.

The client submits one task per survey to the scheduler; any worker runs it and writes the
products to ``OUTDIR/<survey>`` (so OUTDIR and the surveys must be at the same path on every
worker: a shared file system). Workers report the start of a survey as a ``clearfast-batch``
event that the client subscribes to; the finish comes with the task's result.

A task whose worker dies is run again by the scheduler on another worker; with resume (the
default) that run continues from the scans the dead worker had finished.
"""

from __future__ import annotations

import uuid
from collections.abc import Callable, Sequence

from clearfast_gis.batch.jobs import SurveyJob, SurveyResult, convert_survey
from clearfast_gis.errors import ClearfastError

TOPIC = "clearfast-batch"
"""Event topic of the workers' ``start`` events."""


def _emit(event: dict) -> None:
    from distributed import get_worker

    get_worker().log_event(TOPIC, event)


def _task(job: SurveyJob, options, resume: bool) -> SurveyResult:
    return convert_survey(job, options, resume, emit=_emit)


def connect(scheduler: str, timeout_s: float = 10.0):
    """A ``distributed.Client`` of the scheduler at ``scheduler`` (``tcp://host:port``).

    Raises
    ------
    ClearfastError
        The scheduler cannot be reached within ``timeout_s``.
    """
    from distributed import Client

    try:
        return Client(scheduler, timeout=timeout_s)
    except (OSError, TimeoutError) as exc:
        raise ClearfastError(f"cannot reach the Dask scheduler ({type(exc).__name__}: "
                             f"{' '.join(str(exc).split())})", scheduler, "--scheduler") from None


def run_dask(jobs: Sequence[SurveyJob], client, options=None, resume: bool = True,
             on_event: Callable[[dict], None] | None = None) -> list[SurveyResult]:
    """Convert ``jobs`` on the cluster of ``client``, one task per survey.

    Parameters
    ----------
    jobs : sequence of SurveyJob
    client : distributed.Client
    options : ProcessOptions, optional
    resume : bool
    on_event : callable, optional
        Called with every ``start`` event (from the workers) and every ``finish`` event.

    Returns
    -------
    list of SurveyResult
        In the order of ``jobs``.
    """
    from distributed import as_completed

    def on_log(event) -> None:
        _, msg = event
        if on_event is not None and isinstance(msg, dict):
            on_event(msg)

    batch_id = uuid.uuid4().hex[:8]  # keys unique across batches sharing a scheduler
    client.subscribe_topic(TOPIC, on_log)
    try:
        futures = [client.submit(_task, job, options, resume, pure=False,
                                 key=f"clearfast-survey-{job.name}-{batch_id}")
                   for job in jobs]
        index = {f.key: i for i, f in enumerate(futures)}
        results: dict[int, SurveyResult] = {}
        for fut in as_completed(futures):
            i = index[fut.key]
            try:
                res = fut.result()
            except Exception as exc:  # the task failed on every worker it was tried on
                job = jobs[i]
                res = SurveyResult(job.name, "failed", None, 0.0,
                                   f"task lost: {type(exc).__name__}: {exc}", job.products, "")
            results[i] = res
            if on_event is not None:
                on_event({"event": "finish", **res.as_dict()})
    finally:
        client.unsubscribe_topic(TOPIC)
    return [results[i] for i in range(len(jobs))]
