"""Snapshot detector on real thermal images of buried AP landmines (Colombia data set).

Data: /work/shared/data/thermal-landmines-colombia ("Dataset of thermographic images for the
detection of buried landmines", Universidad del Valle, Cali, Data in Brief 2023; Roboflow export
"landmines_detection v1", CC BY 4.0). Credit the dataset's authors with any derived figure.

A detection matches a box when its centroid falls inside the box; detections inside a box are
never false alarms (duplicates included). Detections are ranked by score over the whole split;
Pd(FA) = boxes found / boxes, FA per image = unmatched detections / images.

Run: .venv/bin/python benchmarks/detection_colombia.py [--split valid] [--d1 41 --d2 5
     --epsilon 0.01 --smooth 3 --scale 2] (parameters tuned on train/, see docs/detection.md)
"""

from __future__ import annotations

import argparse
import glob
import re
import time
from pathlib import Path

from clearfast_gis.detection.imageio import read_image
from clearfast_gis.detection.snapshot import detect_snapshot

ROOT = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / \
    "thermal-landmines-colombia"


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


def _curve(records, n_boxes, n_images, fa_levels=(0.5, 1.0, 2.0)):
    recs = sorted(records, key=lambda r: -r[0])
    found, fa, pd_at, thr_at = set(), 0, dict.fromkeys(fa_levels, 0.0), {}
    for score, key in recs:
        if key is None:
            fa += 1
        else:
            found.add(key)
        for lvl in fa_levels:
            if fa / n_images <= lvl:
                pd_at[lvl] = len(found) / max(n_boxes, 1)
                thr_at[lvl] = score
    return pd_at, thr_at, recs


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--split", default="valid")
    ap.add_argument("--d1", type=float, default=41.0)
    ap.add_argument("--d2", type=float, default=5.0)
    ap.add_argument("--epsilon", type=float, default=0.01)
    ap.add_argument("--smooth", type=float, default=3.0)
    ap.add_argument("--scale", type=int, default=2)
    ap.add_argument("--step", type=int, default=1, help="use every step-th image")
    args = ap.parse_args()
    files = sorted(glob.glob(str(ROOT / args.split / "images" / "*.jpg")))[:: args.step]
    if not files:
        raise SystemExit(f"no images under {ROOT / args.split}")
    records, by_depth = [], {}
    n_boxes = 0
    t0 = time.perf_counter()
    for f in files:
        boxes = _boxes(f)
        depth = _depth(Path(f).name)
        d = by_depth.setdefault(depth, {"records": [], "boxes": 0, "images": 0})
        d["boxes"] += len(boxes)
        d["images"] += 1
        n_boxes += len(boxes)
        for det in detect_snapshot(read_image(f), args.d1, args.d2, args.epsilon,
                                   smooth_px=args.smooth, scale=args.scale):
            hit = [i for i, b in enumerate(boxes)
                   if b[0] <= det.x_px <= b[2] and b[1] <= det.y_px <= b[3]]
            rec = (det.score, (f, hit[0]) if hit else None)
            records.append(rec)
            d["records"].append(rec)
    elapsed = (time.perf_counter() - t0) / len(files)
    pd_at, thr_at, recs = _curve(records, n_boxes, len(files))
    print(f"split {args.split}: {len(files)} images, {n_boxes} boxes, "
          f"{len(records) / len(files):.1f} detections/image, {1000 * elapsed:.0f} ms/image; "
          f"D1={args.d1:g} D2={args.d2:g} eps={args.epsilon:g} smooth={args.smooth:g} "
          f"scale={args.scale}\n")
    print("| min score | Pd | FA / image |")
    print("|---|---|---|")
    for thr in (1, 2, 3, 4, 5, 6, 8, 10, 15):
        kept = [r for r in recs if r[0] >= thr]
        pd = len({r[1] for r in kept if r[1] is not None}) / n_boxes
        fa = sum(r[1] is None for r in kept) / len(files)
        print(f"| {thr} | {pd:.3f} | {fa:.2f} |")
    print("\n| burial depth | images | boxes | Pd @ 0.5 FA/img | Pd @ 1 FA/img | Pd @ 2 FA/img |")
    print("|---|---|---|---|---|---|")
    rows = [("all", len(files), n_boxes, pd_at)]
    for depth, d in sorted(by_depth.items()):
        rows.append((depth, d["images"], d["boxes"],
                     _curve(d["records"], d["boxes"], d["images"])[0]))
    for depth, ni, nb, p in rows:
        print(f"| {depth} | {ni} | {nb} | {p[0.5]:.3f} | {p[1.0]:.3f} | {p[2.0]:.3f} |")


if __name__ == "__main__":
    main()
