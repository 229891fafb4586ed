"""``clearfast import``: a survey folder from a radiometric camera's files and the field logs."""

from __future__ import annotations

import json
from dataclasses import fields
from pathlib import Path

import click

from clearfast_gis.cli.options import make_progress, overwrite_opt, progress_opt
from clearfast_gis.errors import ClearfastError, InvalidInput

LAYOUT_NAME = "import.json"
PATH_KEYS = ("poses", "gnss", "weather", "soil", "mission", "markers", "station_profile",
             "blackbody", "blackbody_log")


def _triple(text: str | None) -> tuple[float, float, float] | None:
    if text is None:
        return None
    try:
        vals = tuple(float(v) for v in text.split(","))
    except ValueError:
        vals = ()
    if len(vals) != 3:
        raise click.BadParameter(f"expected E,N,U in metres, got {text!r}")
    return vals  # type: ignore[return-value]


def _pair(text: str | None) -> tuple[float, float] | None:
    if text is None:
        return None
    try:
        lo, hi = (float(v) for v in text.split(","))
    except ValueError:
        raise click.BadParameter(f"expected MIN,MAX in micrometres, got {text!r}") from None
    return lo, hi


def read_layout(folder: Path) -> dict:
    """The options of a folder layout (``import.json``, paths relative to the folder)."""
    path = folder / LAYOUT_NAME
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise InvalidInput(f"cannot read: {exc}", path) from None
    from clearfast_gis.cameras.survey_import import ImportSpec

    known = {f.name for f in fields(ImportSpec)} - {"notes"}
    if not isinstance(doc, dict):
        raise InvalidInput("expected a JSON object", path)
    unknown = sorted(set(doc) - known)
    if unknown:
        raise InvalidInput(f"unknown key(s) {', '.join(unknown)}", path)
    for key in (*PATH_KEYS, "frames"):
        if key in doc:
            vals = doc[key] if isinstance(doc[key], list) else [doc[key]]
            if not all(isinstance(v, str) for v in vals):
                raise InvalidInput("expected a relative path (or a list of them)", path, key)
            resolved = [folder / v for v in vals]
            doc[key] = resolved if key == "frames" else resolved[0]
    return doc


@click.command("import")
@click.argument("sources", nargs=-1, required=True, type=click.Path(exists=True))
@click.option("--poses", type=click.Path(exists=True, dir_okay=False),
              help="Pose table: file,frame,scan,position,time_utc,pan_deg,tilt_deg.")
@click.option("--gnss", type=click.Path(exists=True, dir_okay=False), help="NMEA log.")
@click.option("--weather", type=click.Path(exists=True, dir_okay=False),
              help="TOA5 weather log (1-minute table).")
@click.option("--soil", type=click.Path(exists=True, dir_okay=False),
              help="Thermocouple CSV (time_utc,T_<depth>m_C...).")
@click.option("--mission", type=click.Path(exists=True, dir_okay=False),
              help="mission.json of clearfast plan.")
@click.option("--markers", type=click.Path(exists=True, dir_okay=False),
              help="markers.csv (id,lat_deg,lon_deg,description).")
@click.option("--blackbody", type=click.Path(exists=True, dir_okay=False),
              help="Blackbody table: file,frame,event,blackbody(1|2),time_utc; the camera files "
              "beside it (docs/import.md).")
@click.option("--blackbody-log", type=click.Path(exists=True, dir_okay=False),
              help="Blackbody temperature log (time_utc,bb1_c,bb2_c), with --blackbody.")
@click.option("--station-profile", type=click.Path(exists=True, dir_okay=False),
              help="Station profile of the weather station / soil logger (their own column "
              "names and units, docs/acquire.md).")
@click.option("--antenna-to-camera", "antenna", default=None,
              help="Camera centre minus GNSS antenna, E,N,U metres (pan/tilt base frame).")
@click.option("--pan-zero-azimuth", type=float, default=None,
              help="Grid azimuth of pan 0, degrees (default 0).")
@click.option("--tilt-zero", type=float, default=None, help="Elevation of tilt 0, degrees "
              "(default 0).")
@click.option("--lens", type=click.Choice(["pinhole", "equiangular"]), default=None,
              help="Camera geometry model (default pinhole).")
@click.option("--fov-deg", type=click.FloatRange(0, 180, min_open=True, max_open=True),
              default=None, help="Horizontal field of view (default: the file's, else the "
              "mission's aperture).")
@click.option("--band-um", default=None, help="Band MIN,MAX micrometres (default: the file's, "
              "else 7.5,13.5).")
@click.option("--unit", type=click.Choice(["C", "K"]), default=None,
              help="Unit of float temperature TIFFs without a unit tag.")
@click.option("--scale-k", type=float, default=None,
              help="Kelvin per count of 16-bit linear TIFFs without scale tags.")
@click.option("--offset-k", type=float, default=None, help="Kelvin offset of 16-bit TIFFs.")
@click.option("--utc-offset", "utc_offset_h", type=float, default=None,
              help="Time zone of camera clocks that state none, hours east of UTC.")
@click.option("--survey-id", default=None, help="Survey id (default: the output folder name).")
@click.option("--site-name", default=None, help="Site name.")
@click.option("--ground-altitude-m", type=float, default=None,
              help="Ground altitude (GNSS datum), metres (default: from the GNSS log and the "
              "mission's platform height).")
@click.option("--netd-k", type=click.FloatRange(min=0), default=None, help="Camera NETD, K.")
@click.option("-o", "--output", required=True, type=click.Path(file_okay=False),
              help="Survey folder to create.")
@overwrite_opt
@progress_opt
def command(sources, output, overwrite, progress_mode, antenna, band_um, **opts):
    """Build the survey folder OUTPUT from a radiometric camera's files (SOURCES: files or
    folders; FLIR R-JPEG/FFF/SEQ/CSQ, TLinear or temperature TIFFs), the pose table and the
    field logs. A single folder holding import.json is a complete import (docs/import.md);
    options given on the command line override it."""
    from clearfast_gis.cameras.survey_import import ImportSpec, import_survey

    srcs = [Path(s) for s in sources]
    doc: dict = {}
    if len(srcs) == 1 and srcs[0].is_dir() and (srcs[0] / LAYOUT_NAME).exists():
        doc = read_layout(srcs[0])
        doc.setdefault("frames", [srcs[0]])
    else:
        doc["frames"] = srcs
    given = {k: v for k, v in opts.items() if v is not None}
    for k in PATH_KEYS:
        if k in given:
            given[k] = Path(given[k])
    doc.update(given)
    if antenna is not None:
        doc["antenna_to_camera_m"] = _triple(antenna)
    if band_um is not None:
        doc["band_um"] = _pair(band_um)
    missing = [k for k in ("poses", "gnss", "weather", "soil", "mission",
                           "antenna_to_camera_m") if k not in doc]
    if missing:
        raise ClearfastError("missing " + ", ".join(
            "--" + k.replace("_m", "").replace("_", "-") for k in missing) +
            " (or a folder with import.json)", exit_code=2)
    try:
        spec = ImportSpec(**doc)
    except TypeError as exc:
        raise ClearfastError(f"bad import options: {exc}", exit_code=2) from None
    res = import_survey(spec, output, overwrite=overwrite, progress=make_progress(progress_mode))
    for note in res.notes:
        click.echo(f"note: {note}", err=True)
    click.echo(f"imported {res.n_frames} frames in {res.n_scans} scans from "
               f"{res.camera or 'the camera'} ({res.radiometry.kind}) -> {res.root}", err=True)
