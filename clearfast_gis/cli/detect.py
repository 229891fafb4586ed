"""``clearfast detect PRODUCTS``: re-run detection with new parameters on existing mosaics."""

from __future__ import annotations

import click

from clearfast_gis.cli.options import (
    detection_options,
    make_progress,
    no_invert_opt,
    progress_opt,
)


@click.command("detect", short_help="Re-run anomaly detection on existing mosaics.")
@click.argument("products", type=click.Path(exists=True, file_okay=False))
@detection_options
@no_invert_opt
@progress_opt
def command(products, no_invert, progress_mode, **params):
    """Detect anomalies again in PRODUCTS/mosaics with new detector parameters (D1, D2,
    epsilon, l, gamma), then rewrite anomalies.gpkg and the report. The mosaics are kept."""
    from clearfast_gis.cli.options import build_options
    from clearfast_gis.cli.process import _summary
    from clearfast_gis.pipeline import redetect

    options = build_options(params, invert=not no_invert)
    manifest = redetect(products, options, progress=make_progress(progress_mode))
    _summary(products, manifest, progress_mode)
