"""Why a deep mine is missed or mis-characterised: each mine's contrast against the day's
clutter, the detector's hat at it, what was detected there, and the inversion at its true
position.

For every mine of a processed simulated survey: the peak of its disc-minus-ring contrast on
the truth rasters and on the mosaics (band 1, true position); per scan the top-hat (or
bottom-hat) by reconstruction with the chain's D1 at the mine over the image's clutter
(``detection.clutter.image_clutter_k``; the detector's cut is ``threshold_snr`` = 4 of them)
and the number of scans above the cut; the detection whose outline holds the mine (its
half-maximum footprint and why it was set aside, if it was); and the chain's inversion
(site soil, disc table, chain error terms) of the mosaics' curve at the true position.

    python benchmarks/deep_mines.py SURVEY PRODUCTS [--min-depth 0.04]
"""

from __future__ import annotations

import argparse

import geopandas as gpd
import numpy as np
from contrast_gain import cell_centres, disc_contrast
from depth_bias import load_stack, survey_inputs
from shapely.geometry import Point

from clearfast_gis.detection.clutter import THRESHOLD_SNR, image_clutter_k
from clearfast_gis.detection.morphology import (
    bottom_hat_by_reconstruction,
    top_hat_by_reconstruction,
)
from clearfast_gis.evaluation.truth import read_truth_objects
from clearfast_gis.pipeline import ProcessOptions
from clearfast_gis.thermal import build_site_table, invert_anomaly
from clearfast_gis.thermal.error_budget import with_chain_errors
from clearfast_gis.thermal.sitesoil import CHAIN_TABLE_CENTRE, site_soil


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("survey")
    ap.add_argument("products")
    ap.add_argument("--min-depth", type=float, default=0.04, help="m")
    args = ap.parse_args()
    scans, times, forcing, log = survey_inputs(args.survey)
    mosaic, mt = load_stack(args.products, scans, False)
    truth, tt = load_stack(args.survey, scans, True)
    xy_m, xy_t = cell_centres(mt, mosaic.shape[1:]), cell_centres(tt, truth.shape[1:])
    soil, _, _ = site_soil(log, forcing, times, np.array([np.nanmedian(im) for im in mosaic]))
    d1_px = ProcessOptions().d1_m / mt.a
    hats, clutter = [], []
    for im in mosaic.astype(np.float32):
        clutter.append(image_clutter_k(im, mt.a))
        hats.append(np.fmax(top_hat_by_reconstruction(im, d1_px),
                            bottom_hat_by_reconstruction(im, d1_px)) / clutter[-1])
    anomalies = gpd.read_file(f"{args.products}/anomalies.gpkg", layer="anomalies")
    print(f"clutter {min(clutter):.3f}-{max(clutter):.3f} K; cut {THRESHOLD_SNR:g} sigmas\n")
    print("| mine | depth cm | peak contrast truth / mosaics K | best hat (scans >= cut) | "
          "detected as | inverted at the true position |\n|---|---|---|---|---|---|")
    tables = {}
    for m in read_truth_objects(args.survey):
        if m["kind"] not in ("ap_mine", "at_mine") or m["depth_m"] < args.min_depth:
            continue
        r = 0.5 * m["diameter_m"]
        disc = np.hypot(xy_m[0] - m["x"], xy_m[1] - m["y"]) <= r
        best = np.array([np.nanmax(h[disc]) if np.isfinite(h[disc]).any() else np.nan
                         for h in hats])
        c_m, c_t = disc_contrast(mosaic, xy_m, m), disc_contrast(truth, xy_t, m)
        hit = anomalies[anomalies.geometry.distance(Point(m["x"], m["y"])) < 0.01]
        found = "nothing" if hit.empty else "; ".join(
            f"{a.diameter_m:.2f} m across ({a.set_aside_reason or 'suspect'})"
            for a in hit.itertuples())
        if r not in tables:
            tables[r] = build_site_table(forcing, soil, r, times, centre=CHAIN_TABLE_CENTRE)
        inv = with_chain_errors(invert_anomaly(times, c_m, np.zeros_like(c_m), forcing, soil,
                                               r, table=tables[r]))
        print(f"| {m['id']} | {100 * m['depth_m']:.0f} | {np.nanmax(np.abs(c_t)):.3f} / "
              f"{np.nanmax(np.abs(c_m)):.3f} | {np.nanmax(best):.1f} "
              f"({int(np.sum(best >= THRESHOLD_SNR))} of {len(best)}) | {found} | "
              f"{100 * inv.depth_m:.2f} +- {100 * inv.depth_sigma_m:.2f} cm, {inv.status} |")


if __name__ == "__main__":
    main()
