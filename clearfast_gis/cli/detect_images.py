"""``clearfast detect-images``: anomaly detection in plain thermal snapshots."""

from __future__ import annotations

import csv
import io

import click

from clearfast_gis.atomic import write_text
from clearfast_gis.cli.options import make_progress, progress_opt
from clearfast_gis.errors import ClearfastError

COLUMNS = ["image", "x_px", "y_px", "area_px", "diameter_px", "circularity", "score"]


@click.command("detect-images")
@click.argument("images", nargs=-1, required=True,
                type=click.Path(dir_okay=False))
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False),
              help="Detections CSV, one row per detection.")
@click.option("--d1-px", type=float, default=41.0, show_default=True,
              help="Top-hat disk diameter D1 (working pixels), above the largest object.")
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
def command(images, output, d1_px, d2_px, epsilon, min_score, polarity, smooth_px, scale,
            progress_mode):
    """Detect warm (or cool) blobs in IMAGE... (PNG, JPEG, TIFF) and write a CSV with
    columns image, x_px, y_px, area_px, diameter_px, circularity, score."""
    from clearfast_gis.detection.imageio import read_image
    from clearfast_gis.detection.snapshot import detect_snapshot

    if not d1_px > d2_px >= 1:
        raise ClearfastError(f"need --d1-px > --d2-px >= 1, got {d1_px} and {d2_px}",
                             exit_code=2)
    if not 0 <= epsilon < 0.5:
        raise ClearfastError(f"--epsilon must be in [0, 0.5), got {epsilon}", exit_code=2)
    progress = make_progress(progress_mode)
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(COLUMNS)
    progress.start("detect-images", len(images))
    n_det = 0
    for path in images:
        image = read_image(path)
        dets = detect_snapshot(image, d1_px, d2_px, epsilon, polarity=polarity,
                               min_score=min_score, smooth_px=smooth_px, scale=scale)
        for d in dets:
            writer.writerow([path, f"{d.x_px:.2f}", f"{d.y_px:.2f}", d.area_px,
                             f"{d.diameter_px:.2f}", f"{d.circularity:.3f}", f"{d.score:.3f}"])
        n_det += len(dets)
        progress.advance(image=str(path), detections=len(dets))
    progress.close()
    write_text(output, buf.getvalue())
    click.echo(f"{n_det} detections in {len(images)} images -> {output}", err=True)
