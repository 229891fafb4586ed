"""Options shared by several subcommands (defined once, as rasterio's ``rio`` does)."""

from __future__ import annotations

import click

from clearfast_gis.progress import Progress

progress_opt = click.option(
    "--progress",
    "progress_mode",
    type=click.Choice(["bar", "json", "none"]),
    default="bar",
    show_default=True,
    help="Progress display: a bar for people, JSON lines on stdout for programs.",
)

resume_opt = click.option(
    "--resume/--no-resume",
    default=True,
    show_default=True,
    help="Skip stages whose products are already complete and up to date.",
)

seed_opt = click.option("--seed", type=int, default=0, show_default=True,
                        help="Random seed (identical seeds give identical files).")

overwrite_opt = click.option("--overwrite", is_flag=True, help="Replace existing outputs.")

survey_arg = click.argument(
    "survey", type=click.Path(exists=True, file_okay=False, dir_okay=True, readable=True)
)

products_opt = click.option(
    "-o", "--output", "products", required=True,
    type=click.Path(file_okay=False, dir_okay=True, writable=True),
    help="Products folder (created if missing).",
)


def make_progress(mode: str) -> Progress:
    """The progress reporter for ``--progress MODE``."""
    return Progress(mode)
