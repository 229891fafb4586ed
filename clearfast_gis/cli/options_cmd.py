"""``clearfast options [--json]``: the processing defaults, for people and for programs.

The QGIS plugin reads ``clearfast options --json`` to show the toolkit's own defaults, so the
defaults are defined once (:class:`clearfast_gis.pipeline.options.ProcessOptions`).
"""

from __future__ import annotations

import json

import click

from clearfast_gis import __version__
from clearfast_gis.cli.options import DEFAULTS


def defaults_document() -> dict:
    """``{"version": ..., "process": {parameter: default}}`` (JSON-ready)."""
    return {"version": __version__, "process": DEFAULTS.as_dict()}


@click.command("options", short_help="Show the processing defaults.")
@click.option("--json", "as_json", is_flag=True, help="One JSON object on stdout.")
def command(as_json: bool) -> None:
    """Print the defaults of ``process``, ``detect`` and ``batch`` (parameter names as in
    products.json; sizes in metres)."""
    doc = defaults_document()
    if as_json:
        click.echo(json.dumps(doc, sort_keys=True))
        return
    width = max(map(len, doc["process"]))
    for name, value in doc["process"].items():
        click.echo(f"{name:<{width}}  {'(auto)' if value is None else value}")
