"""``process_survey``: the chain's stages (:data:`~clearfast_gis.pipeline.stages.STAGES`) run
in order, with progress, checkpoints and resume."""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path

from clearfast_gis import kernels
from clearfast_gis.errors import InvalidInput
from clearfast_gis.export.cog import remove_decoded
from clearfast_gis.export.manifest import read_products_manifest, write_products_manifest
from clearfast_gis.parallel import serial_kernels
from clearfast_gis.pipeline import stages
from clearfast_gis.pipeline.options import MOSAIC_PARAMETERS, ProcessOptions
from clearfast_gis.pipeline.stages import STAGES, RunContext, stage_index
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.resources import StageMeter, cpu_seconds


def process_survey(survey_path: str | Path, products: str | Path,
                   options: ProcessOptions | None = None, resume: bool = True,
                   progress: Progress = NULL_PROGRESS, until: str = stages.PRODUCTS,
                   from_stage: str | None = None,
                   station_profile: str | Path | None = None) -> dict:
    """Run the chain from a survey folder to a products folder.

    Parameters
    ----------
    survey_path : path
        Survey folder (``survey.json``).
    products : path
        Products folder (created).
    options : ProcessOptions, optional
        Default parameters when omitted.
    resume : bool
        Keep the finished units of an earlier run of the same inputs whose stage keys (the
        parameters each stage depends on) are unchanged.
    progress : Progress
    until : str
        Last stage to run (:data:`~clearfast_gis.pipeline.stages.STAGE_NAMES`); e.g.
        ``"residuals_and_footprint"`` stops after the scan mosaics (``clearfast mosaic``).
    from_stage : str, optional
        Redo this stage and the ones after it even when they are up to date (the stages
        before it resume); ``"detection"`` is ``clearfast detect``.
    station_profile : path, optional
        Station profile of the weather and soil logs, instead of the one ``survey.json``
        names (``files.station_profile``).

    Returns
    -------
    dict
        The products manifest (``products.json`` content).

    Examples
    --------
    >>> process_survey("survey", "products", until="no_such_stage")
    Traceback (most recent call last):
    ...
    ValueError: unknown stage 'no_such_stage' (stages: read_and_validate, \
band_coregistration, mosaics, attitude_adjustment, residuals_and_footprint, detection, \
characterisation, products)
    """
    last = stage_index(until)
    first = stage_index(from_stage) if from_stage is not None else None
    options = ProcessOptions() if options is None else options
    with kernels.use(options.kernels), serial_kernels():
        return _run(RunContext(Path(survey_path), Path(products), options, progress,
                               StageMeter(), fresh=not resume,
                               station_profile=station_profile), first, last)


def _run(c: RunContext, first: int | None, last: int) -> dict:
    """:func:`process_survey` once the kernel set is chosen: the loop over the stages."""
    t_all, cpu_all = time.perf_counter(), cpu_seconds()
    remove_decoded(c.products)  # mosaics decoded by a run that did not end: maybe rewritten
    try:
        for k, stage in enumerate(STAGES[:last + 1]):
            if first is not None and k == 1:
                # the run state exists once the first stage has opened it: forget every stage
                # from ``first`` on before any later stage can take an earlier run as up to date
                for later in STAGES[max(first, 1):]:
                    c.state.drop(later.name)
            with c.meter.stage(stage.name), c.progress.chain_stage(stage.name, stage.label):
                c.records[stage.name] = stage.run(c)
    finally:
        if c.job is not None:
            c.job.close()
        remove_decoded(c.products)
    read = c[stages.READ]
    if stages.PRODUCTS in c.records:
        manifest = c[stages.PRODUCTS].manifest
    else:
        from clearfast_gis.export.products import base_manifest
        from clearfast_gis.geometry.gnss import fix_quality_summary

        manifest = base_manifest(read.ctx.survey, read.epsg, c.options,
                                 c[stages.MOSAICS].scan_records if stages.MOSAICS in c.records
                                 else {}, fix_quality_summary(read.ctx.track,
                                                             read.ctx.survey.frames.time_s))
        manifest["products"] = {"mosaics": "mosaics/", "footprint": "footprint.geojson"}
    adjustment = c.records.get(stages.ADJUSTMENT)
    manifest["attitude_adjustment"] = None if adjustment is None else adjustment.summary
    total_wall = time.perf_counter() - t_all
    manifest["timings_s"] = {k: round(v["wall_s"], 3) for k, v in c.meter.stages.items()} \
        | {"total": round(total_wall, 3)}
    manifest["resources"] = c.meter.summary(total_wall, cpu_seconds() - cpu_all) \
        | {"kernels": c.options.kernels}
    write_products_manifest(c.products, manifest)
    return manifest


def redetect(products: str | Path, options: ProcessOptions,
             progress: Progress = NULL_PROGRESS) -> dict:
    """Re-run detection and characterisation on existing mosaics with new parameters
    (``process_survey(..., from_stage="detection")`` with the mosaics' own parameters).

    The survey folder recorded in ``products.json`` supplies the logs.
    """
    products = Path(products)
    manifest = read_products_manifest(products)
    survey_path = manifest.get("survey_path")
    if not survey_path or not Path(survey_path).exists():
        raise InvalidInput("the survey folder recorded in products.json is not available",
                           products / "products.json", "survey_path")
    old = manifest.get("parameters", {})
    keep = {k: old[k] for k in MOSAIC_PARAMETERS if k in old}
    opts = dataclasses.replace(options, **keep)
    return process_survey(survey_path, products, opts, resume=True, progress=progress,
                          from_stage=stages.DETECTION)


__all__ = ["process_survey", "redetect"]
