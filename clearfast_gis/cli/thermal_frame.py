"""``clearfast thermal-frame``: one frame's object temperature with the camera's own parameters."""

from __future__ import annotations

import click
import numpy as np

from clearfast_gis.errors import ClearfastError


@click.command("thermal-frame")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--frame", "frame_no", type=click.IntRange(min=0), default=None,
              help="Frame number in a multi-frame file (SEQ, CSQ; 0-based).")
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False),
              help="Float32 TIFF of object temperature, degrees C.")
@click.option("--unit", type=click.Choice(["C", "K"]), default=None,
              help="Unit of a float temperature TIFF without a unit tag.")
@click.option("--scale-k", type=float, default=None,
              help="Kelvin per count of a 16-bit linear TIFF without scale tags "
                   "(FLIR TLinear: 0.04 or 0.01).")
@click.option("--offset-k", type=float, default=None,
              help="Kelvin offset of a 16-bit linear TIFF (default 0).")
def command(file, frame_no, output, unit, scale_k, offset_k):
    """Write FILE's object temperature (degrees C, float32 TIFF, rows and columns as the raw
    image is stored) computed with the camera's own emissivity, reflected and atmospheric
    temperature, distance and humidity: the number the camera's software shows."""
    from pathlib import Path

    from clearfast_gis.cameras import exiftool, read_frames
    from clearfast_gis.cameras.flir import split_records
    from clearfast_gis.cameras.tiff import write_tiff

    if frame_no is None and Path(file).is_file():  # a sequence needs --frame: say so first
        tags = exiftool.read_tags(file)
        if str(tags.get("File:FileType", "")).upper() in ("SEQ", "CSQ"):
            n = len(split_records(Path(file).read_bytes()))
            if n > 1:
                raise ClearfastError(f"{file} holds {n} frames: choose one with --frame N "
                                     f"(0-{n - 1})", exit_code=2)
        frames = read_frames(file, unit=unit, scale_k=scale_k, offset_k=offset_k, tags=tags)
    else:
        frames = read_frames(file, frame=frame_no, unit=unit, scale_k=scale_k,
                             offset_k=offset_k)
    fr = frames[0]
    t_c = fr.object_temperature_c()
    write_tiff(output, t_c, "degC")
    finite = t_c[np.isfinite(t_c)]
    click.echo(f"{fr.camera or fr.format} frame {fr.index}: {t_c.shape[1]}x{t_c.shape[0]}, "
               f"{finite.min():.2f} to {finite.max():.2f} degC -> {output}", err=True)
