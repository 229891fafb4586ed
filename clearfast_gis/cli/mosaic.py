"""``clearfast mosaic SURVEY -o PRODUCTS``: georeferenced COG mosaics, one per scan."""

from __future__ import annotations

import click

from clearfast_gis.cli.options import (
    make_progress,
    mosaic_options,
    products_opt,
    progress_opt,
    resume_opt,
    survey_arg,
)


@click.command("mosaic", short_help="Build georeferenced COG mosaics, one per scan.")
@survey_arg
@products_opt
@mosaic_options
@resume_opt
@progress_opt
def command(survey, products, resume, progress_mode, **params):
    """Calibrate every frame, project it onto the ground from its RTK-DGPS and pan/tilt pose,
    co-register it by mutual information and insert it: PRODUCTS/mosaics/scan_NNN.tif
    (Cloud Optimized GeoTIFF, float32 degrees C, one band per spectral band, UTM CRS), and
    products.json. This is the mosaic stage of `clearfast process`."""
    from clearfast_gis.cli.options import build_options
    from clearfast_gis.pipeline import process_survey

    options = build_options(params)
    manifest = process_survey(survey, products, options, resume=resume,
                              progress=make_progress(progress_mode),
                              until="residuals_and_footprint")
    if progress_mode == "json":
        import json

        click.echo(json.dumps({"event": "done", "products": str(products),
                               "mosaics": [s["file"] for s in manifest["scans"]]}))
    else:
        click.echo(f"{len(manifest['scans'])} scan mosaics -> {products}/mosaics")
