"""Snapshot detector on real thermal images of buried AP landmines (Colombia data set).

Data: /work/shared/data/thermal-landmines-colombia ("Dataset of thermographic images for the
detection of buried landmines", Universidad del Valle, Cali, Data in Brief 2023; Roboflow export
"landmines_detection v1", CC BY 4.0). Credit the dataset's authors with any derived figure.

A detection matches a box when its centroid falls inside the box; detections inside a box are
never false alarms (duplicates included). Detections are ranked by score over the whole split;
Pd(FA) = boxes found / boxes, FA per image = unmatched detections / images.

Run:
  .venv/bin/python benchmarks/detection_colombia.py --split valid            # multi-scale
  .venv/bin/python benchmarks/detection_colombia.py --split valid --mode single
  .venv/bin/python benchmarks/detection_colombia.py --tune --step 10         # grid on train/
  .venv/bin/python benchmarks/detection_colombia.py --split valid --altitude  # ladder from name

``--tune`` runs the documented grid (smoothing ratio x area power x noise x polarity) on train/
only (every 10th image: 76 images, 81 boxes) and prints Pd at 0.5/1/2 FA per image for each
point; the defaults of :class:`clearfast_gis.detection.multiscale.MultiScaleParams` come from it
(see docs/detection.md). valid/ is never used for tuning.
"""

from __future__ import annotations

import argparse
import dataclasses
import glob
import re
import time
from pathlib import Path

import numpy as np

from clearfast_gis.detection.imageio import read_image
from clearfast_gis.detection.multiscale import (
    MultiScaleParams,
    altitude_from_name,
    altitude_ladder,
    robust_sigma,
    scale_candidates,
    scale_ladder,
    suppress_overlaps,
)
from clearfast_gis.detection.snapshot import detect_snapshot, gaussian_nan, shrink

ROOT = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / \
    "thermal-landmines-colombia"
FA_LEVELS = (0.5, 1.0, 2.0)
ALTITUDE_BINS = ((0.0, 1.0), (1.0, 2.0), (2.0, 4.0), (4.0, 7.0), (7.0, 12.0))


def _boxes(image_path: str) -> list[tuple[float, float, float, float]]:
    label = Path(image_path.replace("/images/", "/labels/")).with_suffix(".txt")
    out = []
    for line in label.read_text().splitlines():
        if line.strip():
            _, cx, cy, w, h = map(float, line.split())
            out.append(((cx - w / 2) * 640, (cy - h / 2) * 640, (cx + w / 2) * 640,
                        (cy + h / 2) * 640))
    return out


def _depth(name: str) -> str:
    m = re.search(r"(\d+)_?cm_depth", name)
    return f"{m.group(1)} cm" if m else "unknown"


def _altitude_bin(name: str) -> str:
    alt = altitude_from_name(name)
    if alt is None:
        return "unknown"
    for lo, hi in ALTITUDE_BINS:
        if lo <= alt < hi:
            return f"{lo:g}-{hi:g} m"
    return f">= {ALTITUDE_BINS[-1][1]:g} m"


def _records(files, boxes, dets_per_image):
    """(score, key) per detection; key = (image, box index) or None for a false alarm."""
    out = []
    for f, bx, dets in zip(files, boxes, dets_per_image, strict=True):
        for d in dets:
            hit = [i for i, b in enumerate(bx) if b[0] <= d.x_px <= b[2] and b[1] <= d.y_px <= b[3]]
            out.append((d.score, (f, hit[0]) if hit else None))
    return out


def _curve(records, n_boxes, n_images, fa_levels=FA_LEVELS):
    """Pd at each FA/image level, ranking the detections by score over the split."""
    found, fa, pd_at = set(), 0, dict.fromkeys(fa_levels, 0.0)
    for _, key in sorted(records, key=lambda r: -r[0]):
        if key is None:
            fa += 1
        else:
            found.add(key)
        for lvl in fa_levels:
            if fa / n_images <= lvl:
                pd_at[lvl] = len(found) / max(n_boxes, 1)
    return pd_at


def _files(split: str, step: int) -> list[str]:
    files = sorted(glob.glob(str(ROOT / split / "images" / "*.jpg")))[::step]
    if not files:
        raise SystemExit(f"no images under {ROOT / split}")
    return files


def _rescore(d, params: MultiScaleParams, power: float, sigma_ratio: float):
    """The same candidate with another area power and noise (other terms unchanged)."""
    return dataclasses.replace(
        d, score=d.score * d.area_px ** (power - params.area_power) * sigma_ratio)


def tune(step: int) -> None:
    """Grid on train/ only: smooth_ratio {0.15, 0.25} x area_power {0, 0.1, 0.2} x noise
    {std, mad} x polarity {hot, both}, ladder 16-256 px. Candidates are computed once per
    smoothing ratio (both polarities, both noise estimates) and rescored, so the grid costs two
    detector passes over the images."""
    files = _files("train", step)
    boxes = [_boxes(f) for f in files]
    n_boxes = sum(len(b) for b in boxes)
    ladder = scale_ladder(16.0, 256.0)
    print(f"tuning on train/: {len(files)} images, {n_boxes} boxes, ladder "
          f"{[float(d) for d in ladder]}\n")
    print("| smooth ratio | area power | noise | polarity | Pd @ 0.5 FA/img | Pd @ 1 | Pd @ 2 |")
    print("|---|---|---|---|---|---|---|")
    for smooth in (0.15, 0.25):
        params = MultiScaleParams(smooth_ratio=smooth, noise="std")
        cands = []
        for f in files:
            image = read_image(f)
            per_image = []
            for d in ladder:
                fct = max(1, int(d // params.work_px))
                work = gaussian_nan(shrink(image, fct) if fct > 1 else image,
                                    smooth * d / fct)
                ratio = float(np.nanstd(work)) / max(robust_sigma(work), 1e-9)
                per_image += [(c, ratio) for c in scale_candidates(image, d, "both", params)]
            cands.append(per_image)
        for power in (0.0, 0.1, 0.2):
            for noise in ("std", "mad"):
                for polarity in ("hot", "both"):
                    dets = [suppress_overlaps(
                        [_rescore(c, params, power, r if noise == "mad" else 1.0)
                         for c, r in cs if polarity == "both" or c.polarity == "warm"],
                        params.overlap) for cs in cands]
                    p = _curve(_records(files, boxes, dets), n_boxes, len(files))
                    print(f"| {smooth:g} | {power:g} | {noise} | {polarity} | {p[0.5]:.3f} | "
                          f"{p[1.0]:.3f} | {p[2.0]:.3f} |", flush=True)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--split", default="valid")
    ap.add_argument("--mode", choices=("multiscale", "single"), default="multiscale")
    ap.add_argument("--polarity", choices=("hot", "cold", "both"), default="hot")
    ap.add_argument("--altitude", action="store_true",
                    help="multi-scale ladder around the size expected from the file name's "
                         "altitude (--px-at-1m, --spread); full ladder when absent")
    ap.add_argument("--px-at-1m", type=float, default=250.0)
    ap.add_argument("--spread", type=float, default=8.0)
    ap.add_argument("--d1", type=float, default=41.0, help="single mode")
    ap.add_argument("--d2", type=float, default=5.0, help="single mode")
    ap.add_argument("--epsilon", type=float, default=0.01, help="single mode")
    ap.add_argument("--smooth", type=float, default=3.0, help="single mode")
    ap.add_argument("--scale", type=int, default=2, help="single mode")
    ap.add_argument("--step", type=int, default=1, help="use every step-th image")
    ap.add_argument("--tune", action="store_true", help="run the tuning grid on train/")
    args = ap.parse_args()
    if args.tune:
        tune(args.step)
        return
    files = _files(args.split, args.step)
    boxes = [_boxes(f) for f in files]
    dets, times, cpu = [], [], []
    for f in files:
        image = read_image(f)
        t0, c0 = time.perf_counter(), time.process_time()
        if args.mode == "single":
            d = detect_snapshot(image, args.d1, args.d2, args.epsilon, polarity=args.polarity,
                                smooth_px=args.smooth, scale=args.scale)
        else:
            from clearfast_gis.detection.multiscale import detect_snapshot_multiscale

            alt = altitude_from_name(f) if args.altitude else None
            ladder = altitude_ladder(alt, args.px_at_1m, args.spread) if alt else None
            d = detect_snapshot_multiscale(image, ladder, polarity=args.polarity)
        times.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
        dets.append(d)
    records = _records(files, boxes, dets)
    n_boxes = sum(len(b) for b in boxes)
    what = (f"D1={args.d1:g} D2={args.d2:g} eps={args.epsilon:g} smooth={args.smooth:g} "
            f"scale={args.scale}" if args.mode == "single" else
            f"multiscale {MultiScaleParams()}" + (f", altitude ladder {args.px_at_1m:g} px at "
                                                  f"1 m, spread {args.spread:g}"
                                                  if args.altitude else ""))
    print(f"split {args.split}: {len(files)} images, {n_boxes} boxes, "
          f"{len(records) / len(files):.1f} detections/image, median "
          f"{1000 * np.median(times):.0f} ms/image (p90 {1000 * np.percentile(times, 90):.0f}, "
          f"CPU median {1000 * np.median(cpu[1:] or cpu):.0f} ms, first image excluded); "
          f"polarity {args.polarity}; {what}\n")
    ranked = sorted(records, key=lambda r: -r[0])
    print("| FA / image | Pd | score threshold |")
    print("|---|---|---|")
    for lvl in (0.1, 0.25, 0.5, 1.0, 2.0, 5.0):
        found, fa, pd, thr = set(), 0, 0.0, float("inf")
        for score, key in ranked:
            if key is None:
                fa += 1
            else:
                found.add(key)
            if fa / len(files) <= lvl:
                pd, thr = len(found) / n_boxes, score
        print(f"| {lvl:g} | {pd:.3f} | {thr:.2f} |")
    for title, keyfn in (("burial depth", _depth), ("altitude", _altitude_bin)):
        groups: dict[str, list[int]] = {}
        for i, f in enumerate(files):
            groups.setdefault(keyfn(Path(f).name), []).append(i)
        print(f"\n| {title} | images | boxes | Pd @ 0.5 FA/img | Pd @ 1 FA/img | Pd @ 2 FA/img |")
        print("|---|---|---|---|---|---|")
        rows = [("all", list(range(len(files))))] + sorted(groups.items())
        for name, idx in rows:
            nb = sum(len(boxes[i]) for i in idx)
            p = _curve(_records([files[i] for i in idx], [boxes[i] for i in idx],
                                [dets[i] for i in idx]), nb, len(idx))
            print(f"| {name} | {len(idx)} | {nb} | {p[0.5]:.3f} | {p[1.0]:.3f} | "
                  f"{p[2.0]:.3f} |")


if __name__ == "__main__":
    main()
