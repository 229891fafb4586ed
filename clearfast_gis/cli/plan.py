"""``clearfast plan``: plan a stop-and-go pan/tilt scanning mission (paper §2.2)."""

from __future__ import annotations

import json

import click

from clearfast_gis.errors import InvalidInput


def _numbers(text: str, n: int, what: str, sep: str = ",") -> list[float]:
    parts = text.replace(" ", "").split(sep)
    try:
        values = [float(p) for p in parts]
    except ValueError:
        values = []
    if len(values) != n or not all(v == v and abs(v) != float("inf") for v in values):
        raise click.BadParameter(f"expected {what}, got {text!r}")
    return values


def _resolution(ctx: click.Context, param: click.Parameter, value: str) -> tuple[int, int]:
    parts = value.lower().split("x")
    if len(parts) != 2 or not all(p.strip().isdigit() for p in parts):
        raise click.BadParameter(f"expected 2 integers WxH, e.g. 640x512, got {value!r}")
    w, h = int(parts[0]), int(parts[1])
    if w < 2 or h < 2:
        raise click.BadParameter(f"expected 2 integers of at least 2, got {value!r}")
    return w, h


def _area(ctx: click.Context, param: click.Parameter, value: str) -> list[float]:
    return _numbers(value, 4, "4 numbers XMIN,YMIN,XMAX,YMAX (metres)")


def _platform(ctx: click.Context, param: click.Parameter,
              value: str | None) -> list[float] | None:
    return None if value is None else _numbers(value, 2, "2 numbers X,Y (metres)")


@click.command("plan")
@click.option("--height", "height_m", type=click.FloatRange(min=0.0, min_open=True),
              required=True, help="Camera height above the ground, metres.")
@click.option("--aperture", "aperture_deg",
              type=click.FloatRange(0.0, 180.0, min_open=True, max_open=True), required=True,
              help="Horizontal aperture (2 alpha), degrees.")
@click.option("--resolution", callback=_resolution, required=True, metavar="WxH",
              help="Frame size in pixels, e.g. 640x512.")
@click.option("--area", callback=_area, required=True, metavar="XMIN,YMIN,XMAX,YMAX",
              help="Area rectangle, metres (local frame or survey CRS).")
@click.option("--platform", "platform_xy", callback=_platform, default=None, metavar="X,Y",
              help="Platform position in the same frame (default: 3 m off the middle of the "
                   "area's long side).")
@click.option("--overlap", type=click.FloatRange(0.0, 0.9), default=0.3, show_default=True,
              help="Overlap between neighbouring frames, along and across.")
@click.option("--scan-minutes", type=click.FloatRange(min=0.0, min_open=True), default=25.0,
              show_default=True, help="Duration of one scan, minutes.")
@click.option("--hours", type=click.FloatRange(min=0.0, min_open=True), default=24.0,
              show_default=True, help="Duration of the diurnal survey, hours.")
@click.option("--interval-minutes", type=click.FloatRange(min=0.0, min_open=True), default=None,
              help="Time between scan starts (default: the scan duration rounded up to a "
                   "clock-aligned interval, 25 -> 30).")
@click.option("--model", "camera_model", type=click.Choice(["equiangular", "pinhole"]),
              default="equiangular", show_default=True, help="Camera projection model.")
@click.option("--json", "as_json", is_flag=True, help="Print the summary as JSON.")
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False, writable=True),
              help="mission.json to write.")
def command(height_m: float, aperture_deg: float, resolution: tuple[int, int],
            area: list[float], platform_xy: list[float] | None, overlap: float,
            scan_minutes: float, hours: float, interval_minutes: float | None,
            camera_model: str, as_json: bool, output: str) -> None:
    """Plan a stop-and-go pan/tilt scanning mission and write mission.json.

    Rows of constant tilt from the far edge of the area to the near edge, pan steps in
    serpentine order, both with the requested overlap; prints the number of images, the
    ground pixel sizes and the number of diurnal scans.
    """
    from clearfast_gis.atomic import write_text
    from clearfast_gis.geometry.planner import build_plan, format_summary

    try:
        plan = build_plan(height_m, aperture_deg, resolution, area, platform_xy, overlap,
                          scan_minutes, hours, camera_model, interval_minutes)
    except InvalidInput as exc:
        if exc.path is None and exc.field:
            raise InvalidInput(exc.message, None, f"--{exc.field}") from None
        raise
    write_text(output, json.dumps(plan.mission, indent=1) + "\n")
    summary = plan.summary()
    if as_json:
        click.echo(json.dumps({**summary, "output": str(output)}, indent=1))
    else:
        click.echo(format_summary(summary))
        click.echo(f"wrote {output}")
