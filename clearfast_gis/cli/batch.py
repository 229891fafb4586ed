"""``clearfast batch SURVEY... -o OUTDIR``: convert many surveys, locally or on Dask."""

from __future__ import annotations

import click

from clearfast_gis.cli.options import (
    detection_options,
    mosaic_options,
    no_invert_opt,
    progress_opt,
    resume_opt,
)


@click.command("batch", short_help="Convert many surveys, locally or on a Dask cluster.")
@click.argument("surveys", nargs=-1, required=True,
                type=click.Path(exists=True, file_okay=False, dir_okay=True, readable=True))
@click.option("-o", "--output", "outdir", required=True,
              type=click.Path(file_okay=False, dir_okay=True),
              help="Output folder; each survey's products go to OUTDIR/<survey folder name>.")
@click.option("--workers", type=click.IntRange(min=1), default=None,
              help="Local worker processes (default: one per survey, at most the CPU count).")
@click.option("--scheduler", default=None, metavar="tcp://HOST:PORT",
              help="Run on this Dask distributed scheduler's workers instead of locally.")
@mosaic_options
@detection_options
@no_invert_opt
@resume_opt
@progress_opt
@click.pass_context
def command(ctx, surveys, outdir, workers, scheduler, no_invert, resume, progress_mode,
            **params):
    """Run the whole chain on every SURVEY folder, each into OUTDIR/<folder name>.

    A failing survey does not stop the others: its status and one-line error appear in the
    summary table, and the exit status is 1 if any survey failed. Interrupted conversions
    continue where they stopped (--resume, the default).
    """
    import json

    from clearfast_gis.batch import BatchProgress, run_batch, summary_json, summary_table
    from clearfast_gis.cli.options import build_options

    if workers is not None and scheduler:
        raise click.UsageError("--workers is for local runs; the scheduler's cluster decides "
                               "the workers")
    options = build_options(params, invert=not no_invert)
    progress = BatchProgress(progress_mode, len(surveys))
    try:
        results = run_batch(list(surveys), outdir, workers=workers, scheduler=scheduler,
                            options=options, resume=resume, on_event=progress)
    finally:
        progress.close()
    if progress_mode == "json":
        click.echo(json.dumps(summary_json(results)))
    else:
        click.echo(summary_table(results))
    ctx.exit(1 if any(r.status != "ok" for r in results) else 0)
