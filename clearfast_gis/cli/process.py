"""``clearfast process SURVEY -o PRODUCTS``: the whole chain."""

from __future__ import annotations

import click

from clearfast_gis.cli.options import (
    detection_options,
    make_progress,
    mosaic_options,
    no_invert_opt,
    products_opt,
    progress_opt,
    resume_opt,
    station_profile_opt,
    survey_arg,
)
from clearfast_gis.pipeline.stages import STAGE_NAMES


@click.command("process", short_help="Run the whole chain: survey folder to products.")
@survey_arg
@products_opt
@mosaic_options
@detection_options
@no_invert_opt
@click.option("--from", "from_stage", type=click.Choice(STAGE_NAMES), default=None,
              help="Redo this stage and the ones after it even when up to date (the stages "
              "before it resume).")
@click.option("--until", type=click.Choice(STAGE_NAMES), default=STAGE_NAMES[-1],
              show_default=True, help="Stop after this stage.")
@station_profile_opt
@resume_opt
@progress_opt
def command(survey, products, no_invert, from_stage, until, station_profile, resume,
            progress_mode, **params):
    """Calibrate, mosaic, detect and characterise a survey; write COG mosaics,
    anomalies.gpkg, report.html and products.json into PRODUCTS.

    An interrupted run continues where it stopped (--resume, the default): each stage keeps
    its finished work while the parameters it depends on are unchanged.
    """
    from clearfast_gis.cli.options import build_options
    from clearfast_gis.pipeline import process_survey

    if from_stage is not None and STAGE_NAMES.index(from_stage) > STAGE_NAMES.index(until):
        raise click.UsageError(f"--from {from_stage} comes after --until {until}")
    options = build_options(params, invert=not no_invert)
    progress = make_progress(progress_mode)
    manifest = process_survey(survey, products, options, resume=resume, progress=progress,
                              until=until, from_stage=from_stage,
                              station_profile=station_profile)
    _summary(products, manifest, progress_mode)


def _summary(products: str, manifest: dict, progress_mode: str) -> None:
    import json
    from pathlib import Path

    n = _count_suspects(Path(products)) if (Path(products) / "anomalies.gpkg").exists() else 0
    if progress_mode == "json":
        click.echo(json.dumps({"event": "done", "products": str(products), "suspects": n,
                               "timings_s": manifest.get("timings_s", {})}))
        return
    click.echo(f"{len(manifest.get('scans', []))} scan mosaics, {n} suspects -> {products}")
    click.echo(f"report: {Path(products) / 'report.html'}")


def _count_suspects(products) -> int:
    import pyogrio

    info = pyogrio.read_info(products / "anomalies.gpkg", layer="suspects")
    return int(info["features"])
