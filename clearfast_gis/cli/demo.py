"""``clearfast demo [OUT]``: simulate the embedded demo survey and process it end to end."""

from __future__ import annotations

from pathlib import Path

import click

from clearfast_gis.cli.options import make_progress, progress_opt


@click.command("demo", short_help="Simulate the demo survey and process it end to end.")
@click.argument("out", type=click.Path(file_okay=False), default="demo-out")
@click.option("--seed", type=int, default=0, show_default=True, help="Simulation seed.")
@progress_opt
def command(out, seed, progress_mode):
    """Simulate the built-in demo survey (a clear November day near Nicosia, AT and AP mines
    among clutter) into OUT/survey, process it into OUT/products and compare the suspects
    with the simulation's ground truth."""
    from clearfast_gis.evaluation.truth import score_against_truth
    from clearfast_gis.pipeline import ProcessOptions, process_survey
    from clearfast_gis.simulate import preset, simulate_survey

    out = Path(out)
    survey = out / "survey"
    products = out / "products"
    progress = make_progress(progress_mode)
    if not (survey / "survey.json").exists():
        simulate_survey(survey, preset("demo"), seed=seed, progress=progress)
    process_survey(survey, products, ProcessOptions(), resume=True, progress=progress)
    score = score_against_truth(survey, products)
    click.echo(score.summary())
    click.echo(f"products: {products}")
    click.echo(f"report:   {products / 'report.html'}")
