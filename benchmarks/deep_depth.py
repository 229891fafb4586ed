"""A deep mine's depth from its curve's shape, at its true position: what the deep cores'
depth profile (:mod:`clearfast_gis.detection.deep_depth`) makes of each buried mine of a
processed simulated survey.

For every mine at least ``--min-depth`` deep: its disc-ring contrast per scan at its true
position as the deep search measures it (bands averaged, disc of the reference AP mine's
radius, :func:`clearfast_gis.detection.deep.core_contrast`; each scan's spread from
:func:`~clearfast_gis.detection.deep.stack_match`), the gain that takes the reference mine's
modelled curve at the true depth to it (least squares with an offset), its wide ratio
(:func:`~clearfast_gis.detection.deep_depth.wide_ratio`), and the profile's depth, fit and
total sigma and status. The site soil is fitted as the chain fits it.

    python benchmarks/deep_depth.py SURVEY PRODUCTS [SURVEY PRODUCTS ...] [--min-depth 0.05]
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np
from depth_bias import survey_inputs

from clearfast_gis.detection.clutter import background_levels
from clearfast_gis.detection.deep import core_contrast, stack_match
from clearfast_gis.detection.deep_depth import (
    PROFILE_DEPTHS_M,
    deep_inversion,
    depth_profile,
    wide_ratio,
)
from clearfast_gis.evaluation.truth import MINE_KINDS, read_truth_objects
from clearfast_gis.export.cog import mosaic_stack
from clearfast_gis.minetypes import MINE_TYPES
from clearfast_gis.thermal.daycontrast import REFERENCE_RADIUS_M, reference_curves
from clearfast_gis.thermal.sitesoil import site_soil


def gain_at_truth(contrast_k: np.ndarray, model_k: np.ndarray) -> float:
    """Least-squares gain of ``model_k`` (S,) K with a free offset to ``contrast_k`` (S,) K
    over the scans with data."""
    ok = np.isfinite(contrast_k)
    design = np.stack([model_k[ok], np.ones(int(ok.sum()))], axis=1)
    return float(np.linalg.lstsq(design, contrast_k[ok], rcond=None)[0][0])


def survey_rows(survey: str, products: str, min_depth_m: float) -> list[dict]:
    """One row per mine at least ``min_depth_m`` (m) deep inside the mosaics."""
    scans, times, forcing, log = survey_inputs(survey)
    site = json.loads((Path(survey) / "survey.json").read_text())["site"]
    canopy = float(site.get("vegetation_cover", 0.0))
    stack = mosaic_stack(Path(products), scans)
    t = stack.transform
    background, _ = background_levels(stack, np.zeros(stack.shape, dtype=np.int32), t.a)
    soil, _, _ = site_soil(log, forcing, times, background, canopy)
    depths = np.asarray(PROFILE_DEPTHS_M)
    templates = reference_curves(forcing, soil, times, depths, canopy)
    radius_px = REFERENCE_RADIUS_M / t.a
    mines, cores = [], []
    for m in read_truth_objects(survey):
        row, col = int(round((t.f - m["y"]) / t.a - 0.5)), int(round((m["x"] - t.c) / t.a - 0.5))
        if (m["kind"] in MINE_KINDS and m["depth_m"] >= min_depth_m - 1e-9
                and 0 <= row < stack.shape[0] and 0 <= col < stack.shape[1]):
            mines.append(m)
            cores.append((len(cores) + 1, row, col))
    if not cores:
        return []
    sigma = stack_match(stack, templates[[int(np.argmin(np.abs(depths - 0.07)))]],
                        radius_px).sigma_k
    contrast = core_contrast(stack, cores, radius_px)
    wide = core_contrast(stack, cores, max(k.radius_m for k in MINE_TYPES) / t.a)
    out = []
    for j, m in enumerate(mines):
        c = contrast[:, j]
        if np.sum(np.isfinite(c)) < 4:
            continue
        profile = depth_profile(c, sigma, templates)
        ratio = wide_ratio(c, wide[:, j])
        inv = deep_inversion(profile, float(np.nanmedian(sigma)), ratio)
        truth = templates[int(np.argmin(np.abs(depths - m["depth_m"])))]
        out.append({"id": m["id"], "kind": m["kind"], "depth_m": m["depth_m"],
                    "gain": gain_at_truth(c, truth), "ratio": ratio,
                    "estimate_m": inv.depth_m, "fit_sigma_m": profile.fit_sigma_m,
                    "sigma_m": inv.depth_sigma_m, "status": inv.status})
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("pairs", nargs="+", metavar="SURVEY PRODUCTS")
    ap.add_argument("--min-depth", type=float, default=0.05, help="m")
    args = ap.parse_args()
    if len(args.pairs) % 2:
        ap.error("give SURVEY PRODUCTS pairs")
    print("| survey | mine | true depth cm | gain at the true depth | wide ratio | depth cm "
          "| fit sigma cm | sigma cm | abs(error) / sigma | status |\n"
          "|---|---|---|---|---|---|---|---|---|---|")
    for survey, products in zip(args.pairs[::2], args.pairs[1::2], strict=True):
        folder = Path(survey).resolve()
        name = folder.parent.name if folder.name == "survey" else folder.name
        for r in survey_rows(survey, products, args.min_depth):
            z = abs(r["estimate_m"] - r["depth_m"]) / r["sigma_m"]
            print(f"| {name} | {r['id']} | "
                  f"{100 * r['depth_m']:.0f} | {r['gain']:.2f} | {r['ratio']:.2f} | "
                  f"{100 * r['estimate_m']:.2f} | {100 * r['fit_sigma_m']:.2f} | "
                  f"{100 * r['sigma_m']:.2f} | {z:.2f} | {r['status']} |")


if __name__ == "__main__":
    main()
