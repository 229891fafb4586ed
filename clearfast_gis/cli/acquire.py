"""``clearfast acquire``: run a scanning mission with the field instruments into a survey folder.

Ports come from ``--ports-file`` (as ``clearfast simulate-devices`` writes it, or a station's
own) and/or the ``--gnss/--ptu/--weather/--soil/--camera`` options, which take precedence.
The folder is written as the survey goes; running the same command again on it resumes an
interrupted acquisition.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import click

from clearfast_gis.cli.log import _port_opt
from clearfast_gis.cli.options import make_progress, progress_opt, stop_on_signals


def _utc(ctx: click.Context, param: click.Parameter, value: str | None) -> float | None:
    if value is None:
        return None
    from clearfast_gis.timeutil import parse_utc

    try:
        return parse_utc(value)
    except ValueError:
        raise click.BadParameter(f"expected an ISO 8601 UTC time such as "
                                 f"2026-11-15T06:00:00Z, got {value!r}") from None


def _scans(ctx: click.Context, param: click.Parameter, value: str | None) -> list[int] | None:
    """``0-2,5`` -> [0, 1, 2, 5]."""
    if value is None:
        return None
    out: set[int] = set()
    try:
        for part in value.replace(" ", "").split(","):
            lo, sep, hi = part.partition("-")
            a, b = int(lo), int(hi) if sep else int(lo)
            if a < 0 or b < a:
                raise ValueError
            out.update(range(a, b + 1))
    except ValueError:
        raise click.BadParameter(f"expected scan numbers such as 0-2,5, got {value!r}") from None
    return sorted(out)


def _camera(ctx: click.Context, param: click.Parameter, value: str | None):
    if value is None:
        return None
    from clearfast_gis.acquire.camera import parse_camera_spec

    try:
        return parse_camera_spec(value)
    except ValueError as exc:
        raise click.BadParameter(str(exc)) from None


@click.command("acquire")
@click.option("--ports-file", "ports_file", type=click.Path(dir_okay=False), default=None,
              help="ports.json naming the instruments' ports, the camera, and optionally the "
              "mission, the set-up and the time scale.")
@click.option("--mission", "mission_path", type=click.Path(dir_okay=False), default=None,
              help="mission.json from clearfast plan.")
@click.option("--setup", "setup_path", type=click.Path(dir_okay=False), default=None,
              help="setup.json: site, camera, platform, blackbody positions.")
@_port_opt("gnss", "gnss", "RTK-DGPS receiver (NMEA; the survey clock)")
@_port_opt("ptu", "ptu", "Pan/tilt unit (FLIR PTU protocol)")
@_port_opt("weather", "weather", "Weather station (polled, TOA5 records)")
@_port_opt("soil", "soil", "Thermocouple logger (T and B lines)")
@click.option("--camera", "camera_spec", metavar="drop:DIR[,timeout=S]", default=None,
              callback=_camera, help="Camera: a drop folder (see docs/acquire.md).")
@click.option("-o", "--output", "survey_dir", required=True,
              type=click.Path(file_okay=False, dir_okay=True, writable=True),
              help="Survey folder: new, or an interrupted acquisition of the same mission "
              "(resumed).")
@click.option("--scans", callback=_scans, default=None, metavar="LIST",
              help="Scans to take, such as 0-2,5 (default: all of the mission's).")
@click.option("--start", "start_s", callback=_utc, default=None, metavar="UTC",
              help="Planned start of scan 0 (default: now).")
@click.option("--time-scale", "time_scale", type=click.FloatRange(min=0.0, min_open=True),
              default=None, help="Survey seconds per second of the GNSS clock (default: the "
              "ports file's, else 1).")
@click.option("--warmup", "warmup_s", type=click.FloatRange(min=0.0), default=900.0,
              show_default=True, help="Survey seconds to wait for every instrument's first "
              "record before scanning.")
@click.option("--tail", "tail_s", type=click.FloatRange(min=0.0), default=900.0,
              show_default=True, help="Survey seconds to keep logging for records past the "
              "last frame.")
@click.option("--gnss-wait", "gnss_wait_s", type=click.FloatRange(min=0.0, min_open=True),
              default=30.0, show_default=True,
              help="Seconds to wait for the receiver's first UTC time.")
@click.option("--station-profile", "station_profile", default=None,
              type=click.Path(exists=True, dir_okay=False),
              help="Station profile (JSON) of the weather station: its column names and units "
                   "(and its field names if it sends no TOA5 header); copied into the survey "
                   "folder and named in survey.json.")
@progress_opt
def command(ports_file, mission_path, setup_path, gnss_spec, ptu_spec, weather_spec,
            soil_spec, camera_spec, survey_dir, scans, start_s, time_scale, warmup_s, tail_s,
            gnss_wait_s, station_profile, progress_mode) -> None:
    """Run a scanning mission stop-and-go with the field instruments (RTK-DGPS, pan/tilt unit,
    weather station, thermocouple logger, camera) into the survey folder given with -o.

    Each scan starts with the blackbody calibration; every instrument is logged with UTC
    times; the folder is written frame by frame and a run that was interrupted (Ctrl-C,
    SIGTERM, a crash) is resumed by the same command. Example with the device simulators
    (24 h of the demo in about 40 s):

    \b
      clearfast simulate-devices --ports-file sim/ports.json --time-scale 2000 &
      clearfast acquire --ports-file sim/ports.json -o survey/
    """
    from clearfast_gis.acquire.camera import parse_camera_spec
    from clearfast_gis.acquire.ports import read_ports_file
    from clearfast_gis.acquire.session import AcquisitionConfig, run_acquisition
    from clearfast_gis.errors import InvalidInput

    ports: dict = {}
    camera = None
    mission = setup = None
    scale = 1.0
    if ports_file is not None:
        pf = read_ports_file(ports_file)
        ports.update(pf.ports)
        if pf.camera is not None:
            try:
                camera = parse_camera_spec(pf.camera)
            except ValueError as exc:
                raise InvalidInput(str(exc), ports_file, "camera") from None
        mission, setup, scale = pf.mission, pf.setup, pf.time_scale
    for kind, spec in (("gnss", gnss_spec), ("ptu", ptu_spec), ("weather", weather_spec),
                       ("soil", soil_spec)):
        if spec is not None:
            ports[kind] = spec
    camera = camera_spec or camera
    mission = Path(mission_path) if mission_path else mission
    setup = Path(setup_path) if setup_path else setup
    scale = time_scale if time_scale is not None else scale
    missing = [name for name, v in (("--mission", mission), ("--setup", setup),
                                    ("--ptu", ports.get("ptu")), ("--camera", camera))
               if v is None]
    if missing:
        raise click.UsageError(f"missing {', '.join(missing)} (give them, or a --ports-file "
                               "that names them)")
    cfg = AcquisitionConfig(Path(survey_dir), mission, setup, ports, camera, scale, start_s,
                            scans=scans, gnss_wait_s=gnss_wait_s, warmup_s=warmup_s,
                            tail_s=tail_s,
                            station_profile=Path(station_profile) if station_profile else None)
    with stop_on_signals() as stop:
        summary = run_acquisition(cfg, make_progress(progress_mode), stop)
    r = summary.result
    b = max(r.n_bands, 1)
    text = (f"{'resumed: ' if summary.resumed else ''}{r.n_frames * b} frames "
            f"({r.n_frames} positions x {b} bands) and {r.n_calibration_frames * b} blackbody "
            f"frames in scans {','.join(map(str, r.scans)) or 'none'}"
            + (f"; missed scans {','.join(map(str, r.missed_scans))}" if r.missed_scans else "")
            + f" -> {survey_dir}")
    if progress_mode == "json":
        sys.stdout.write(json.dumps({"event": "summary", "stage": "acquire", "message": text,
                                     "exposures": r.n_frames,
                                     "calibration_exposures": r.n_calibration_frames,
                                     "bands": r.n_bands,
                                     "scans": r.scans, "missed_scans": r.missed_scans,
                                     "late_scans": r.late_scans, "retries": r.n_retries,
                                     "stopped": summary.stopped, "events": summary.events,
                                     "instruments": summary.instruments}) + "\n")
        sys.stdout.flush()
    if summary.stopped:
        click.echo(f"clearfast: acquisition stopped ({text}); run the same command again to "
                   "resume", err=True)
        raise SystemExit(130)
    if progress_mode != "json":
        click.echo(f"acquired {text}")
