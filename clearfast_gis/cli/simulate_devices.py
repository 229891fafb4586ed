"""``clearfast simulate-devices``: the digital twin's instruments on pseudo-terminals.

Opens a pseudo-terminal for each serial instrument (GNSS receiver, pan/tilt unit, weather
station, thermocouple logger) and a drop folder for the camera, all speaking the protocols
the drivers speak and driven by the digital twin, and writes their paths to the ports file
(with the twin's mission.json and setup.json beside it), so that ``clearfast acquire
--ports-file`` runs exactly as in the field.
"""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import click

from clearfast_gis.cli.options import progress_opt, seed_opt, stop_on_signals


def _faults(ctx: click.Context, param: click.Parameter, value: tuple[str, ...]):
    from clearfast_gis.simulate.devices.rig import parse_fault

    try:
        return [parse_fault(v) for v in value]
    except ValueError as exc:
        raise click.BadParameter(str(exc)) from None


def _utc(ctx: click.Context, param: click.Parameter, value: str | None) -> float | None:
    from clearfast_gis.cli.acquire import _utc as parse

    return parse(ctx, param, value)


@click.command("simulate-devices")
@click.option("--ports-file", "ports_file", required=True, type=click.Path(dir_okay=False),
              help="Where to write ports.json; the links, drop folder, mission.json, "
              "setup.json, markers.csv and truth/ go beside it.")
@click.option("--preset", "preset_name", type=click.Choice(["demo", "trial", "full"]),
              default=None, help="The twin's survey (default: the scenario's, else demo).")
@click.option("--scenario", "scenario_path",
              type=click.Path(exists=True, dir_okay=False, readable=True),
              help="Scenario JSON (schemas/scenario.schema.json): overrides and objects.")
@seed_opt
@click.option("--drift", is_flag=True, help="The trial's sinking, tilting lift.")
@click.option("--time-scale", "time_scale", type=click.FloatRange(min=0.0, min_open=True),
              default=1.0, show_default=True,
              help="Scene seconds per second (2000 runs the 24 h demo in about 45 s).")
@click.option("--start", "start_s", default=None, metavar="UTC", callback=_utc,
              help="Scene time when the devices start (default: the twin's start).")
@click.option("--fault", "faults", multiple=True, callback=_faults,
              metavar="KIND:DEVICE@S[+S]",
              help="A fault at scene seconds after the twin's start: unplug:gnss@3600+60, "
              "mute:camera@7200+30, noise:weather@100, rtk-loss@5400+300 (repeatable).")
@click.option("--duration", "duration_s", type=click.FloatRange(min=0.0, min_open=True),
              default=None, help="Stop after this many seconds (default: at the twin's end, "
              "or Ctrl-C / SIGTERM).")
@progress_opt
def command(ports_file, preset_name, scenario_path, seed, drift, time_scale, start_s, faults,
            duration_s, progress_mode) -> None:
    """Serve the digital twin's instruments on pseudo-terminals and write their ports file."""
    from clearfast_gis.simulate.config import preset
    from clearfast_gis.simulate.devices.rig import DeviceRig
    from clearfast_gis.simulate.scenario import load_scenario
    from clearfast_gis.simulate.twin import build_twin
    from clearfast_gis.timeutil import format_utc

    objects, draw_clutter = None, False
    if scenario_path is not None:
        scen = load_scenario(scenario_path, preset(preset_name) if preset_name else None)
        config, objects, draw_clutter = scen.config, scen.objects, scen.draw_clutter
        objects = list(objects) if objects is not None else None
    else:
        config = preset(preset_name or "demo")
    if progress_mode == "bar":
        click.echo("building the digital twin ...", err=True)
    twin = build_twin(config, seed, drift, objects, draw_clutter)
    rig = DeviceRig(twin, Path(ports_file).resolve().parent, time_scale, start_s, faults=faults)
    t0 = time.monotonic()
    with stop_on_signals() as stop, rig:
        ready = {"event": "ready", "stage": "simulate-devices",
                 "ports_file": str(rig.ports_file),
                 "scene_utc": format_utc(rig.clock.now(), "seconds"),
                 "time_scale": time_scale,
                 "devices": {k: d.path for k, d in rig.devices.items()},
                 "camera": str(rig.server.folder)}
        if progress_mode == "json":
            sys.stdout.write(json.dumps(ready) + "\n")
            sys.stdout.flush()
        elif progress_mode == "bar":
            click.echo(f"devices ready: {rig.ports_file} (scene time "
                       f"{ready['scene_utc']}, x{time_scale:g}); Ctrl-C to stop", err=True)
        while not stop.wait(0.2):
            if rig.finished or (duration_s is not None
                                and time.monotonic() - t0 >= duration_s):
                break
            if rig.server.error:
                raise click.ClickException(f"camera: {rig.server.error}")
    end = {"event": "end", "stage": "simulate-devices", "frames": rig.camera.n_frames,
           "scene_utc": format_utc(rig.clock.now(), "seconds"), "faults": rig.log}
    if progress_mode == "json":
        sys.stdout.write(json.dumps(end) + "\n")
    elif progress_mode == "bar":
        click.echo(f"devices stopped at scene time {end['scene_utc']}; {end['frames']} frames "
                   "rendered", err=True)
