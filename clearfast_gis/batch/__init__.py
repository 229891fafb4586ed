"""Convert many surveys: local processes, or a Dask distributed cluster.

``run_batch`` plans one job per survey folder (products in ``OUTDIR/<survey folder name>``),
runs them with :func:`~clearfast_gis.batch.local.run_local` or, given a scheduler address,
:func:`~clearfast_gis.batch.cluster.run_dask`, and returns one
:class:`~clearfast_gis.batch.jobs.SurveyResult` per survey. A failing survey never stops the
others. See ``docs/batch.md``.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path

from clearfast_gis.atomic import _describe_os_error
from clearfast_gis.batch.jobs import SurveyJob, SurveyResult, convert_survey, plan_jobs
from clearfast_gis.batch.report import BatchProgress, summary_json, summary_table
from clearfast_gis.errors import OutputError


def run_batch(surveys: Sequence[str | os.PathLike], outdir: str | os.PathLike,
              workers: int | None = None, scheduler: str | None = None, options=None,
              resume: bool = True, on_event: Callable[[dict], None] | None = None
              ) -> list[SurveyResult]:
    """Convert every survey folder of ``surveys`` into ``outdir/<folder name>``.

    Parameters
    ----------
    surveys : sequence of path
        Survey folders; their folder names must differ.
    outdir : path
        Output folder (created).
    workers : int, optional
        Local processes; default: min(number of surveys, CPU count). Ignored with a
        scheduler (the cluster's workers run the tasks).
    scheduler : str, optional
        Dask scheduler address (``tcp://host:port``): run on that cluster.
    options : clearfast_gis.pipeline.ProcessOptions, optional
    resume : bool
        Continue interrupted conversions.
    on_event : callable, optional
        Receives per-survey ``start`` and ``finish`` events (e.g. a :class:`BatchProgress`).

    Returns
    -------
    list of SurveyResult
        In the order of ``surveys``.

    Raises
    ------
    ClearfastError
        Duplicate survey folder names (exit status 2), an unwritable ``outdir``, an
        unreachable scheduler.
    """
    jobs = plan_jobs(surveys, outdir)
    try:
        Path(outdir).mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the output folder: {_describe_os_error(exc)}",
                          outdir) from None
    if not jobs:
        return []
    if scheduler:
        from clearfast_gis.batch.cluster import connect, run_dask

        client = connect(scheduler)
        try:
            return run_dask(jobs, client, options, resume, on_event)
        finally:
            client.close()
    from clearfast_gis.batch.local import run_local

    n = workers if workers else min(len(jobs), os.cpu_count() or 1)
    return run_local(jobs, n, options, resume, on_event)


__all__ = ["BatchProgress", "SurveyJob", "SurveyResult", "convert_survey", "plan_jobs",
           "run_batch", "summary_json", "summary_table"]
