"""``clearfast export``: export products for a mine action centre."""

from __future__ import annotations

from pathlib import Path

import click

from clearfast_gis.cli.options import make_progress, progress_opt
from clearfast_gis.export.hazard_areas import DEFAULT_BUFFER_M
from clearfast_gis.export.mine_action import DEFAULT_MIN_LIKELIHOOD, ORGANISATION_ENV


@click.command(name="export")
@click.argument("products", type=click.Path(exists=True, file_okay=False, dir_okay=True))
@click.option("--mine-action", "mine_action", is_flag=True,
              help="WGS84 GeoPackage + CSV with the fields a national mine action database "
                   "imports (see docs/mine_action.md).")
@click.option("-o", "--output", "out_dir", type=click.Path(file_okay=False, dir_okay=True),
              default=None, help="Output folder [default: PRODUCTS/mine_action].")
@click.option("--min-likelihood", type=click.FloatRange(0.0, 1.0),
              default=DEFAULT_MIN_LIKELIHOOD, show_default=True,
              help="Mine likelihood (p_mine) from which a suspect is exported as evidence; "
                   "products without p_mine use the AT/AP class cue.")
@click.option("--all-suspects", "include_all", is_flag=True,
              help="Export every suspect as evidence, not only the mine indications.")
@click.option("--hazard-buffer", "buffer_m", type=float, default=DEFAULT_BUFFER_M,
              show_default=True,
              help="Radius (m) of the hazard polygon proposed around each mine indication.")
@click.option("--organisation", default=None,
              help=f"Surveying organisation [default: ${ORGANISATION_ENV}].")
@progress_opt
def command(products: str, mine_action: bool, out_dir: str | None, min_likelihood: float,
            include_all: bool, buffer_m: float, organisation: str | None,
            progress_mode: str) -> None:
    """Export the PRODUCTS folder for a mine action centre (IMSMA Core).

    Writes the surveyed area, hazard polygon proposals around clusters of mine indications and
    the evidence points. Every record rests on indirect evidence (stand-off thermal IR): the
    polygons are suspected hazardous areas to review, never confirmed ones.
    """
    from clearfast_gis.export.mine_action import export_mine_action

    if not mine_action:
        raise click.UsageError("choose what to export: --mine-action")
    result = export_mine_action(products, out_dir, progress=make_progress(progress_mode),
                                min_likelihood=min_likelihood, include_all=include_all,
                                buffer_m=buffer_m, organisation=organisation)
    if progress_mode == "json":
        import json

        click.echo(json.dumps({"event": "result", "gpkg": str(result.gpkg),
                               "csv": str(result.csv), "count": result.count,
                               "hazard_proposals": result.hazard_proposals}))
    else:
        click.echo(f"{result.count} indications, {result.hazard_proposals} hazard polygon "
                   f"proposals -> {Path(result.gpkg)} and {Path(result.csv)}")
