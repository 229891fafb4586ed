"""``clearfast log``: log the field instruments over serial ports into a survey folder.

Each chosen instrument runs in its own thread: the GNSS receiver to ``gnss.nmea``, the
weather station to ``weather.dat``, the thermocouple logger to ``soil.csv`` (names from
``survey.json`` ``files`` when the folder has one); the pan/tilt unit is polled for the status
display. All ports are opened before anything is written; a port that cannot be opened stops
the command with one line naming it (exit 1). Ctrl-C, SIGTERM or the end of ``--duration``
stop every logger cleanly: each log ends with a complete line.
"""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import click

from clearfast_gis.cli.options import progress_opt, stop_on_signals


def _port(kind: str):
    def callback(ctx: click.Context, param: click.Parameter, value: str | None):
        if value is None:
            return None
        from clearfast_gis.acquire.ports import DEFAULT_BAUD, parse_port_spec

        try:
            return parse_port_spec(value, DEFAULT_BAUD[kind])
        except ValueError as exc:
            raise click.BadParameter(str(exc)) from None
    return callback


def _depths(ctx: click.Context, param: click.Parameter, value: str) -> tuple[float, ...]:
    try:
        depths = tuple(float(v) for v in value.replace(" ", "").split(","))
    except ValueError:
        depths = ()
    if not depths or any(not (d >= 0 and d < float("inf")) for d in depths):
        raise click.BadParameter(f"expected depths in metres D1,D2,..., got {value!r}")
    return depths


def _port_opt(name: str, kind: str, what: str):
    from clearfast_gis.acquire.ports import DEFAULT_BAUD

    return click.option(f"--{name}", f"{kind}_spec", metavar="PORT[,BAUD]", default=None,
                        callback=_port(kind),
                        help=f"{what} port: device or pyserial URL, baud after a comma "
                             f"(default {DEFAULT_BAUD[kind]}).")


def _file_names(survey_dir: Path) -> dict[str, str]:
    from clearfast_gis.survey.manifest import DEFAULT_FILES, read_survey_json

    names = {k: DEFAULT_FILES[k] for k in ("gnss", "weather", "soil")}
    manifest = survey_dir / "survey.json"
    if manifest.exists():
        files = read_survey_json(manifest, "survey.json")["files"]
        names.update({k: files[k] for k in names if k in files})
    return names


class _Display:
    """Status line on stderr (``bar``), JSON lines on stdout (``json``) or nothing."""

    #: seconds between status lines when stderr is not a terminal (a log file)
    FILE_INTERVAL_S = 60.0

    def __init__(self, mode: str) -> None:
        self.mode = mode
        self.tty = sys.stderr.isatty()
        self._width = 0
        self._last_line_s = -self.FILE_INTERVAL_S

    def emit(self, event: str, elapsed_s: float, parts: list, final: bool = False) -> None:
        if self.mode == "json":
            doc = {"event": event, "stage": "log", "elapsed_s": round(elapsed_s, 3),
                   "instruments": {p.kind: p.status() for p in parts}}
            sys.stdout.write(json.dumps(doc) + "\n")
            sys.stdout.flush()
        elif self.mode == "bar":
            if not (self.tty or final or elapsed_s - self._last_line_s >= self.FILE_INTERVAL_S):
                return
            self._last_line_s = elapsed_s
            line = f"{elapsed_s:7.0f} s | " + " | ".join(
                f"{p.kind} FAILED" if p.error else p.status_text() for p in parts)
            if self.tty and not final:
                sys.stderr.write("\r" + line.ljust(self._width))
                self._width = len(line)
            else:
                sys.stderr.write(("\r" if self.tty else "") + line.ljust(self._width) + "\n")
            sys.stderr.flush()


@click.command("log")
@_port_opt("gnss", "gnss", "RTK-DGPS receiver (NMEA)")
@_port_opt("weather", "weather", "Weather station (TOA5 records)")
@_port_opt("soil", "soil", "Thermocouple logger (T,<time>,<t1>,... lines)")
@_port_opt("ptu", "ptu", "Pan/tilt unit (FLIR PTU protocol)")
@click.option("--soil-depths", default="0.02,0.05,0.10,0.20,0.50", show_default=True,
              callback=_depths, metavar="D1,D2,...",
              help="Depth of each thermocouple channel, metres, in channel order.")
@click.option("-o", "--output", "survey_dir", required=True,
              type=click.Path(file_okay=False, dir_okay=True, writable=True),
              help="Survey folder (created if missing); logs are appended to.")
@click.option("--duration", "duration_s", type=click.FloatRange(min=0.0, min_open=True),
              default=None, help="Stop after this many seconds (default: Ctrl-C or SIGTERM).")
@click.option("--status-interval", "status_s", type=click.FloatRange(min=0.05), default=1.0,
              show_default=True, help="Seconds between status updates.")
@click.option("--station-profile", "station_profile", default=None,
              type=click.Path(exists=True, dir_okay=False),
              help="Station profile (JSON): the weather station's column names and units (and "
                   "its field names if it sends no TOA5 header).")
@progress_opt
def command(gnss_spec, weather_spec, soil_spec, ptu_spec, soil_depths: tuple[float, ...],
            survey_dir: str, duration_s: float | None, status_s: float,
            station_profile: str | None, progress_mode: str) -> None:
    """Log the field instruments over serial ports into a survey folder.

    Runs the chosen loggers concurrently and shows a status line (or JSON lines with
    --progress json) until --duration ends or Ctrl-C / SIGTERM; every log file is left
    complete. Example:

    \b
      clearfast log --gnss /dev/ttyUSB0,115200 --weather /dev/ttyUSB1 \\
                    --soil /dev/ttyUSB2 --ptu /dev/ttyUSB3 -o survey/
    """
    from clearfast_gis.acquire import (
        GnssLogger,
        PanTiltUnit,
        ThermocoupleLogger,
        WeatherStationLogger,
        open_port,
    )
    from clearfast_gis.acquire.monitor import PtuMonitor
    from clearfast_gis.errors import ClearfastError
    from clearfast_gis.survey.station_profiles import read_station_profile

    chosen = [(k, s) for k, s in (("gnss", gnss_spec), ("weather", weather_spec),
                                  ("soil", soil_spec), ("ptu", ptu_spec)) if s is not None]
    if not chosen:
        raise click.UsageError("choose at least one instrument: --gnss, --weather, --soil "
                               "or --ptu")
    root = Path(survey_dir)
    names = _file_names(root)
    profile = read_station_profile(station_profile) if station_profile else None
    ports: dict = {}
    parts: list = []
    try:
        for kind, spec in chosen:
            ports[kind] = open_port(spec)
        for kind, port in ports.items():
            if kind == "gnss":
                parts.append(GnssLogger(port, root / names["gnss"]))
            elif kind == "weather":
                parts.append(WeatherStationLogger(port, root / names["weather"],
                                                  profile=profile))
            elif kind == "soil":
                parts.append(ThermocoupleLogger(port, root / names["soil"], soil_depths))
            else:
                parts.append(PtuMonitor(PanTiltUnit(port)))
    except BaseException:
        for p in parts:
            if hasattr(p, "log"):
                p.close_logs()
        for port in ports.values():
            port.close()
        raise

    display = _Display(progress_mode)
    t0 = time.monotonic()
    with stop_on_signals() as stop:
        try:
            threads = [p.start(stop) for p in parts]
            display.emit("start", 0.0, parts)
            while not stop.is_set():
                elapsed = time.monotonic() - t0
                if duration_s is not None and elapsed >= duration_s:
                    break
                wait = status_s if duration_s is None else min(status_s, duration_s - elapsed)
                if stop.wait(max(0.0, wait)):
                    break
                display.emit("status", time.monotonic() - t0, parts)
                if not any(t.is_alive() for t in threads):
                    break  # every instrument failed
            stop.set()
            for t in threads:
                t.join(timeout=10.0)
        finally:
            stop.set()
            for port in ports.values():
                port.close()
    display.emit("end", time.monotonic() - t0, parts, final=True)
    errors = [p.error for p in parts if p.error]
    if errors:
        raise ClearfastError(errors[0] + (f" (and {len(errors) - 1} more instruments failed)"
                                          if len(errors) > 1 else ""))
