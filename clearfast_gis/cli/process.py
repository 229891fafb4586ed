"""``clearfast process SURVEY -o PRODUCTS``: the whole chain."""

from __future__ import annotations

import click

from clearfast_gis.cli.options import (
    detection_options,
    make_progress,
    mosaic_options,
    products_opt,
    progress_opt,
    resume_opt,
    station_profile_opt,
    survey_arg,
)


@click.command("process", short_help="Run the whole chain: survey folder to products.")
@survey_arg
@products_opt
@mosaic_options
@detection_options
@click.option("--no-invert", is_flag=True, help="Skip the depth/diffusivity estimation.")
@station_profile_opt
@resume_opt
@progress_opt
def command(survey, products, no_invert, station_profile, resume, progress_mode, **params):
    """Calibrate, mosaic, detect and characterise a survey; write COG mosaics,
    anomalies.gpkg, report.html and products.json into PRODUCTS.

    An interrupted run continues where it stopped (--resume, the default).
    """
    from clearfast_gis.cli.options import build_options
    from clearfast_gis.pipeline import process_survey

    options = build_options(params, invert=not no_invert)
    progress = make_progress(progress_mode)
    manifest = process_survey(survey, products, options, resume=resume, progress=progress,
                              station_profile=station_profile)
    _summary(products, manifest, progress_mode)


def _summary(products: str, manifest: dict, progress_mode: str) -> None:
    import json
    from pathlib import Path

    n = _count_suspects(Path(products))
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
