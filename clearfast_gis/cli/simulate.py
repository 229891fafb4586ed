"""``clearfast simulate OUT``: write a complete simulated survey folder with its ground truth.

The folder follows the survey format (``clearfast validate`` accepts it) and adds ``truth/``:
``objects.csv``, ``apparent_temperature/scan_NNN.tif``, ``poses.csv``, ``bands.csv`` and
``scenario.json`` (the objects as a scenario file, to re-simulate the same scene).
"""

from __future__ import annotations

import click

from clearfast_gis.cli.options import make_progress, overwrite_opt, progress_opt, seed_opt


@click.command("simulate")
@click.argument("out", type=click.Path(file_okay=False, dir_okay=True, writable=True))
@click.option("--preset", "preset_name", type=click.Choice(["demo", "trial", "full"]),
              default=None, help="Survey size: demo (seconds), trial (the paper's layout, "
              "minutes), full (trial at 640x512). Default: the scenario's, else demo.")
@seed_opt
@click.option("--drift", is_flag=True,
              help="The trial's fault: the lift slowly sinks and tilts over the survey.")
@click.option("--scenario", "scenario_path",
              type=click.Path(exists=True, dir_okay=False, readable=True),
              help="Scenario JSON (schemas/scenario.schema.json): overrides and objects.")
@click.option("--camera-format", type=click.Choice(["flir-rjpeg", "tlinear", "celsius-tiff"]),
              default=None,
              help="Write the frames as a radiometric camera does (one LWIR band, no "
              "blackbodies): OUT becomes a folder for clearfast import (docs/import.md).")
@overwrite_opt
@progress_opt
def command(out: str, preset_name: str | None, seed: int, drift: bool,
            scenario_path: str | None, camera_format: str | None, overwrite: bool,
            progress_mode: str) -> None:
    """Simulate a diurnal thermal-IR survey into the folder OUT (with truth/)."""
    from clearfast_gis.simulate.config import preset
    from clearfast_gis.simulate.run import simulate_survey
    from clearfast_gis.simulate.scenario import load_scenario

    objects, draw_clutter = None, False
    if scenario_path is not None:
        base = preset(preset_name) if preset_name else None
        scen = load_scenario(scenario_path, base)
        config, objects, draw_clutter = scen.config, scen.objects, scen.draw_clutter
        if objects is not None:
            objects = list(objects)
    else:
        config = preset(preset_name or "demo")
    if camera_format is not None:
        from clearfast_gis.simulate.camera_files import radiometric_camera_config

        config = radiometric_camera_config(config)
    progress = make_progress(progress_mode)
    result = simulate_survey(out, config, seed=seed, drift=drift, objects=objects,
                             draw_clutter=draw_clutter, progress=progress, overwrite=overwrite)
    if camera_format is not None:
        from clearfast_gis.simulate.camera_files import write_camera_folder

        write_camera_folder(result.root, result.twin, camera_format)
    if progress_mode != "json":
        click.echo(f"simulated {result.n_scans} scans x {result.n_positions} positions x "
                   f"{result.n_bands} bands = {result.n_frames} frames, "
                   f"{len(result.objects)} objects -> {result.root}")
