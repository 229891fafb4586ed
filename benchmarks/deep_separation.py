"""How well the stack's matched filter (``clearfast_gis.detection.deep``) separates deep mines
from the background of a processed simulated survey.

For every mine of the survey deeper than ``--min-depth``: the best score and its explained
share within 5 cm of the true position. For the background: the local peaks of the score
(one per 0.45 m, as the chain takes them) that reach ``--score`` with ``--explained``,
counted per m2 and sorted by what lies under them: a truth object (mine, stone, marker,
vegetation, ...), the halo of one (within 0.45 m of its edge), or bare soil texture.

    python benchmarks/deep_separation.py SURVEY PRODUCTS [--score 6] [--explained 0.85]
"""

from __future__ import annotations

import argparse

import numpy as np
from contrast_gain import cell_centres
from depth_bias import survey_inputs
from scipy import ndimage

from clearfast_gis.detection.classify import AT_DIAMETER_M
from clearfast_gis.detection.clutter import background_levels
from clearfast_gis.detection.deep import (
    DEEP_DEPTHS_M,
    MIN_EXPLAINED,
    MIN_SCANS,
    MIN_SCORE,
    stack_match,
)
from clearfast_gis.evaluation.truth import read_truth_objects
from clearfast_gis.export.cog import mosaic_stack
from clearfast_gis.thermal.daycontrast import REFERENCE_RADIUS_M, reference_curves
from clearfast_gis.thermal.sitesoil import site_soil

HALO_M = AT_DIAMETER_M[1]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("survey")
    ap.add_argument("products")
    ap.add_argument("--min-depth", type=float, default=0.05, help="m")
    ap.add_argument("--score", type=float, default=MIN_SCORE)
    ap.add_argument("--explained", type=float, default=MIN_EXPLAINED)
    args = ap.parse_args()
    scans, times, forcing, log = survey_inputs(args.survey)
    stack = mosaic_stack(args.products, scans)
    px = float(stack.transform.a)
    background, _ = background_levels(stack, np.zeros(stack.shape, np.int32), px)
    soil, _, _ = site_soil(log, forcing, times, background)
    match = stack_match(stack, reference_curves(forcing, soil, times, DEEP_DEPTHS_M),
                        REFERENCE_RADIUS_M / px)
    score = np.where(np.isfinite(match.score), match.score, -np.inf)
    x, y = cell_centres(stack.transform, stack.shape)
    truth = read_truth_objects(args.survey)
    edge = np.full(stack.shape, np.inf)  # distance to the nearest object's edge, m
    for t in truth:
        edge = np.minimum(edge, np.hypot(x - t["x"], y - t["y"]) - 0.5 * t["diameter_m"])
    print(f"{len(scans)} scans; | mine | depth cm | score | explained |\n|---|---|---|---|")
    for t in truth:
        if t["kind"] in ("ap_mine", "at_mine") and t["depth_m"] >= args.min_depth:
            near = np.hypot(x - t["x"], y - t["y"]) <= 0.05
            i = np.argmax(np.where(near, score, -np.inf))
            print(f"| {t['id']} | {100 * t['depth_m']:.0f} | {score.flat[i]:.1f} | "
                  f"{match.explained.flat[i]:.2f} |")
    size = max(3, int(round(HALO_M / px)) | 1)
    peaks = (score == ndimage.maximum_filter(score, size=size)) & (match.scans >= MIN_SCANS) \
        & (score >= args.score) & (match.explained >= args.explained)
    area = float(np.count_nonzero(match.scans > 0)) * px * px
    on = peaks & (edge <= 0.05)
    halo = peaks & (edge > 0.05) & (edge <= HALO_M)
    soil_peaks = peaks & (edge > HALO_M)
    top = np.sort(score[soil_peaks])[::-1][:5]
    print(f"\nbackground peaks >= {args.score:g} with >= {args.explained:g} explained, over "
          f"{area:.0f} m2: on a truth object (mines too) {on.sum()}, in its halo "
          f"{halo.sum()}, soil texture {soil_peaks.sum()} "
          f"({soil_peaks.sum() / area:.3f} per m2; highest "
          f"{', '.join(f'{v:.1f}' for v in top) or '-'})")


if __name__ == "__main__":
    main()
