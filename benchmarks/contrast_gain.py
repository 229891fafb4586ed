"""The chain's curve terms: mosaic contrast against the truth raster's, mine by mine.

For every mine at most 5 cm deep of processed simulated surveys, the contrast curve (mean over
the mine's disc minus the ring at 1.5-2.5 radii, band 1, at the mine's *true* position) of
the mosaics is regressed on that of the truth apparent-temperature rasters (no sensor, no
mosaic): the slope is the gain the blur and registration leave, the intercept the offset of
the ring's level, the residual the scan-to-scan scatter. The spread of the slopes and the rms
of the intercepts are the curve terms of ``clearfast_gis.thermal.error_budget``.

    python benchmarks/contrast_gain.py SURVEY:PRODUCTS [SURVEY:PRODUCTS ...]
"""

from __future__ import annotations

import argparse

import numpy as np
from depth_bias import load_stack

from clearfast_gis.evaluation.truth import read_truth_objects
from clearfast_gis.pipeline.inputs import open_context

MAX_DEPTH_M = 0.055
"""Mines this deep at most (their contrast stands well above the clutter)."""


def cell_centres(transform, shape: tuple[int, int]) -> tuple[np.ndarray, np.ndarray]:
    """Map x, y (m) of every cell of a raster of ``shape`` (H, W)."""
    r, c = np.mgrid[0:shape[0], 0:shape[1]]
    return transform.c + (c + 0.5) * transform.a, transform.f - (r + 0.5) * transform.a


def disc_contrast(stack: np.ndarray, xy: tuple[np.ndarray, np.ndarray], mine: dict
                  ) -> np.ndarray:
    """Per scan: mean over the mine's disc minus the mean of the ring at 1.5-2.5 radii, K."""
    r = 0.5 * mine["diameter_m"]
    d = np.hypot(xy[0] - mine["x"], xy[1] - mine["y"])
    disc, ring = d <= r, (d >= 1.5 * r) & (d <= 2.5 * r)
    return np.array([np.nanmean(im[disc]) - np.nanmean(im[ring]) for im in stack])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("pairs", nargs="+", metavar="SURVEY:PRODUCTS")
    args = ap.parse_args()
    print("| survey | mine | depth cm | gain | offset K | scatter K | peak contrast K |\n"
          "|---|---|---|---|---|---|---|")
    rows = []
    for pair in args.pairs:
        survey, products = pair.split(":")
        ctx, _, _ = open_context(survey)
        scans = list(ctx.survey.scans)
        mosaic, mt = load_stack(products, scans, False)
        truth, tt = load_stack(survey, scans, True)
        xy_m, xy_t = cell_centres(mt, mosaic.shape[1:]), cell_centres(tt, truth.shape[1:])
        for m in read_truth_objects(survey):
            if m["kind"] not in ("ap_mine", "at_mine") or m["depth_m"] > MAX_DEPTH_M:
                continue
            cm, ct = disc_contrast(mosaic, xy_m, m), disc_contrast(truth, xy_t, m)
            ok = np.isfinite(cm) & np.isfinite(ct)
            a = np.stack([ct[ok], np.ones(ok.sum())], axis=1)
            (gain, offset), *_ = np.linalg.lstsq(a, cm[ok], rcond=None)
            scatter = float(np.std(cm[ok] - a @ np.array([gain, offset]), ddof=2))
            rows.append((gain, offset, scatter))
            print(f"| {survey} | {m['id']} | {100 * m['depth_m']:.0f} | {gain:.3f} | "
                  f"{offset:+.4f} | {scatter:.4f} | {np.nanmax(np.abs(ct)):.3f} |")
    g, o, sc = (np.array(v) for v in zip(*rows, strict=True))
    print(f"\n{len(g)} mines: gain {g.mean():.3f} +- {g.std():.3f}, offset rms "
          f"{np.sqrt(np.mean(o ** 2)):.4f} K, scatter median {np.median(sc):.4f} K")


if __name__ == "__main__":
    main()
