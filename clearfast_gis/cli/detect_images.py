"""``clearfast detect-images``: anomaly detection in plain thermal snapshots."""

from __future__ import annotations

import csv
import io

import click

from clearfast_gis.atomic import write_text
from clearfast_gis.cli.options import make_progress, progress_opt
from clearfast_gis.errors import ClearfastError

COLUMNS = ["image", "x_px", "y_px", "area_px", "diameter_px", "circularity", "score", "polarity",
           "scale_px"]


@click.command("detect-images")
@click.argument("images", nargs=-1, required=True,
                type=click.Path(dir_okay=False))
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False),
              help="Detections CSV, one row per detection.")
@click.option("--mode", type=click.Choice(["multiscale", "single"]), default="single",
              show_default=True,
              help="Multi-scale ladder of object sizes, or one D1/D2 pair (--d1-px ...).")
@click.option("--min-diameter-px", type=float, default=16.0, show_default=True,
              help="Multi-scale: smallest object diameter (pixels).")
@click.option("--max-diameter-px", type=float, default=None,
              help="Multi-scale: largest object diameter (pixels); default 0.4 x the image side.")
@click.option("--altitude-m", type=float, default=None,
              help="Multi-scale: flight altitude (m); ladder around --px-at-1m / altitude.")
@click.option("--altitude-from-name", is_flag=True,
              help="Multi-scale: read the altitude from each file name ('__0-7m_' = 0.7 m) "
                   "when present.")
@click.option("--px-at-1m", type=float, default=250.0, show_default=True,
              help="Object diameter in pixels at 1 m range (with an altitude).")
@click.option("--spread", type=float, default=8.0, show_default=True,
              help="Largest over smallest diameter of the altitude ladder.")
@click.option("--d1-px", type=float, default=41.0, show_default=True,
              help="Single: top-hat disk diameter D1 (working pixels), above the largest "
                   "object.")
@click.option("--d2-px", type=float, default=5.0, show_default=True,
              help="Opening disk diameter D2 (working pixels), below the smallest object.")
@click.option("--epsilon", type=float, default=0.01, show_default=True,
              help="Histogram-stretch fraction.")
@click.option("--min-score", type=float, default=0.0, show_default=True,
              help="Drop detections scoring below this.")
@click.option("--polarity", type=click.Choice(["hot", "cold", "both"]), default="hot",
              show_default=True, help="Warm blobs, cool blobs or both.")
@click.option("--smooth-px", type=float, default=3.0, show_default=True,
              help="Gaussian pre-filter sigma (working pixels) against fine texture; 0 = off.")
@click.option("--scale", type=click.IntRange(1, 16), default=2, show_default=True,
              help="Work on the image shrunk by this factor.")
@progress_opt
def command(images, output, mode, min_diameter_px, max_diameter_px, altitude_m,
            altitude_from_name, px_at_1m, spread, d1_px, d2_px, epsilon, min_score, polarity,
            smooth_px, scale, progress_mode):
    """Detect warm (or cool) blobs in IMAGE... (PNG, JPEG, TIFF) and write a CSV with
    columns image, x_px, y_px, area_px, diameter_px, circularity, score, polarity, scale_px."""
    from clearfast_gis.detection import multiscale as ms
    from clearfast_gis.detection.imageio import read_image
    from clearfast_gis.detection.snapshot import detect_snapshot

    if not d1_px > d2_px >= 1:
        raise ClearfastError(f"need --d1-px > --d2-px >= 1, got {d1_px} and {d2_px}",
                             exit_code=2)
    if not 0 <= epsilon < 0.5:
        raise ClearfastError(f"--epsilon must be in [0, 0.5), got {epsilon}", exit_code=2)
    if min_diameter_px < 2 or (max_diameter_px is not None and max_diameter_px < min_diameter_px):
        raise ClearfastError("need 2 <= --min-diameter-px <= --max-diameter-px", exit_code=2)
    if (altitude_m is not None and altitude_m <= 0) or px_at_1m <= 0 or spread < 1:
        raise ClearfastError("need --altitude-m > 0, --px-at-1m > 0 and --spread >= 1",
                             exit_code=2)
    params = ms.MultiScaleParams(epsilon=epsilon)

    def ladder(path, shape):
        alt = ms.altitude_from_name(path) if altitude_from_name else None
        alt = alt if alt is not None else altitude_m
        if alt is not None:
            return ms.altitude_ladder(alt, px_at_1m, spread)
        top = max_diameter_px if max_diameter_px is not None else 0.4 * min(shape)
        return ms.scale_ladder(min_diameter_px, max(top, min_diameter_px))

    progress = make_progress(progress_mode)
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(COLUMNS)
    progress.start("detect-images", len(images))
    n_det = 0
    for path in images:
        image = read_image(path)
        if mode == "single":
            dets = detect_snapshot(image, d1_px, d2_px, epsilon, polarity=polarity,
                                   min_score=min_score, smooth_px=smooth_px, scale=scale)
        else:
            dets = ms.detect_snapshot_multiscale(image, ladder(path, image.shape), polarity,
                                                 min_score, params)
        for d in dets:
            writer.writerow([path, f"{d.x_px:.2f}", f"{d.y_px:.2f}", d.area_px,
                             f"{d.diameter_px:.2f}", f"{d.circularity:.3f}", f"{d.score:.3f}",
                             d.polarity, f"{d.scale_px:g}"])
        n_det += len(dets)
        progress.advance(image=str(path), detections=len(dets))
    progress.close()
    write_text(output, buf.getvalue())
    click.echo(f"{n_det} detections in {len(images)} images -> {output}", err=True)
