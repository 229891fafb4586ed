"""``clearfast export``: export products for a mine action centre."""

from __future__ import annotations

from pathlib import Path

import click

from clearfast_gis.cli.options import make_progress, progress_opt


@click.command(name="export")
@click.argument("products", type=click.Path(exists=True, file_okay=False, dir_okay=True))
@click.option("--mine-action", "mine_action", is_flag=True,
              help="WGS84 GeoPackage + CSV with the fields a national mine action database "
                   "imports (see docs/mine_action.md).")
@click.option("-o", "--output", "out_dir", type=click.Path(file_okay=False, dir_okay=True),
              default=None, help="Output folder [default: PRODUCTS/mine_action].")
@progress_opt
def command(products: str, mine_action: bool, out_dir: str | None, progress_mode: str) -> None:
    """Export the PRODUCTS folder's suspects for a mine action centre.

    Every exported point is an indication from indirect evidence (stand-off thermal IR), never
    a confirmed hazardous area.
    """
    from clearfast_gis.export.mine_action import export_mine_action

    if not mine_action:
        raise click.UsageError("choose what to export: --mine-action")
    result = export_mine_action(products, out_dir, progress=make_progress(progress_mode))
    if progress_mode == "json":
        import json

        click.echo(json.dumps({"event": "result", "gpkg": str(result.gpkg),
                               "csv": str(result.csv), "count": result.count}))
    else:
        click.echo(f"{result.count} indications -> {Path(result.gpkg)} and {Path(result.csv)}")
