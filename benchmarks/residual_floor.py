"""How far the mosaics' residual misregistration measurement is from the true geometry.

For a processed simulated survey, and for each scan asked for:

- ``measured``: the residual against the reference scan that the chain measured on the mosaics
  (``products.json``, mutual information between the two mosaics);
- ``from true poses``: the misregistration against the reference that the chain's placement
  makes, traced cell by cell through each cell's source frame to ``truth/poses.csv``
  (:func:`clearfast_gis.evaluation.truth.placement_errors`): all of it (RMS over the cells), and
  its rotation-and-shift part (what ``measured`` estimates);
- ``floor``: the same measurement as ``measured``, between the scan's and the reference's
  mosaics both projected with the *true* poses (band 0, no co-registration): what the
  measurement reports when the geometry is exact, i.e. the part of it that comes from the
  thermal content of two different times rather than from placement.

    python benchmarks/residual_floor.py SURVEY PRODUCTS [--scans 3 5 7]

Prints a markdown table (default: every scan).
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from clearfast_gis.evaluation.truth import placement_errors, read_true_poses
from clearfast_gis.export.cog import read_mosaic
from clearfast_gis.export.layout import mosaic_rel
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.mosaic import FrameInput, build_scan_mosaic, temporal_residual
from clearfast_gis.mosaic.frames import air_function, scan_frames
from clearfast_gis.pipeline.inputs import open_context


def true_pose_mosaic(ctx, scan: int, grid: GroundGrid, truth: dict) -> np.ndarray:
    """Band 0 of ``scan``'s mosaic (float32 (H, W), degrees C) projected with the true poses."""
    frames = [FrameInput(f.index, f.values[:1], truth[(scan, f.index, 0)])
              for f in scan_frames(ctx, scan, air_function(ctx))]
    return build_scan_mosaic(frames, ctx.camera, grid, 1, coregister=False).values[0]


def _px(v: float | None) -> str:
    return "n/a" if v is None or math.isnan(v) else f"{v:.2f}"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("survey", type=Path)
    ap.add_argument("products", type=Path)
    ap.add_argument("--scans", type=int, nargs="*")
    ap.add_argument("--reference", type=int, help="reference scan, if products.json lacks it")
    args = ap.parse_args()
    placement = placement_errors(args.survey, args.products, reference_scan=args.reference)
    ref = placement.reference_scan
    manifest = json.loads((args.products / "products.json").read_text())
    measured = {int(r["scan"]): r.get("residual_px") for r in manifest["scans"]}
    scans = args.scans or [s for s in placement.scans if s != ref]
    m = read_mosaic(args.products / mosaic_rel(ref))
    h, w = m.bands_c[0].shape
    grid = GroundGrid(m.transform.c, m.transform.f, m.transform.a, w, h, m.epsg)
    ctx, _, _ = open_context(args.survey)
    truth = read_true_poses(args.survey)
    reference = true_pose_mosaic(ctx, ref, grid, truth)
    print(f"{args.products}: reference scan {ref}, mosaic cells {100 * grid.pixel_size:.0f} cm\n")
    print("| scan | measured px | from true poses, RMS px | from true poses, rigid part px | "
          "floor: true-pose mosaics px |")
    print("|---|---:|---:|---:|---:|")
    rows = []
    for s in scans:
        floor = temporal_residual(reference, true_pose_mosaic(ctx, s, grid, truth)).shift_px
        k = placement.scans.index(s)
        meas = measured.get(s)
        rows.append((meas, placement.relative_px[k], placement.relative_rigid_px[k], floor))
        print("| " + " | ".join([str(s)] + [_px(v) for v in rows[-1]]) + " |", flush=True)
    cols = [np.array([r[k] for r in rows if r[k] is not None and not math.isnan(r[k])])
            for k in range(4)]
    print("| median / max | " + " | ".join(
        f"{np.median(c):.2f} / {c.max():.2f}" if c.size else "n/a" for c in cols) + " |")


if __name__ == "__main__":
    main()
