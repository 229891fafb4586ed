"""The chain's contrast curves against the model's at the truth, mine by mine.

For every mine of processed simulated surveys that a detection matches (within its radius
plus 5 cm), the contrast curve the chain measured (mean over the detection's half-maximum
footprint minus its background ring, band 1) is regressed on the curve the characterisation
models for that detection (the nearest mine type over the footprint, against the ring,
through the mosaics' blur, times the apparent gain) at the mine's *true* depth and
diffusivity: ``measured = k model + c``. A slope ``k`` of 1 means the model of the measure is
complete; its mean and spread are the gain term of ``clearfast_gis.thermal.error_budget``.
The summary is of the mines modelled as their type (not of those whose footprint is of no
type's size). The characterisation stage of each survey is run again (the products are
rewritten, with the same values) to take its inputs.

    python benchmarks/chain_curve_gain.py SURVEY:PRODUCTS [SURVEY:PRODUCTS ...]
"""

from __future__ import annotations

import argparse

import numpy as np

from clearfast_gis.evaluation.truth import MINE_KINDS, nearest_match, read_truth_objects
from clearfast_gis.pipeline import anomalies, process_survey
from clearfast_gis.thermal.canopy import under_canopy
from clearfast_gis.thermal.measure import anomaly_measure
from clearfast_gis.thermal.sitesoil import chain_site_table, first_band
from clearfast_gis.thermal.table import contrast_spline

MAX_DEPTH_M = 0.055
"""Mines this deep at most."""


def characterisation_inputs(survey: str, products: str) -> dict:
    """The arguments the chain's characterisation stage passes to ``characterise``."""
    seen: dict = {}
    chain = anomalies.characterise

    def spy(features, times_s, forcing, soil, progress=None, canopy=0.0, gain=None,
            blur_m=None):
        seen.update(features=features, times_s=times_s, forcing=forcing, soil=soil,
                    canopy=canopy, gain=gain, blur_m=blur_m)
        return chain(features, times_s, forcing, soil, canopy=canopy, gain=gain,
                     blur_m=blur_m)

    anomalies.characterise = spy
    try:
        process_survey(survey, products, from_stage="characterisation")
    finally:
        anomalies.characterise = chain
    return seen


def mine_slopes(survey: str, products: str) -> list[tuple[str, float, float, float, str]]:
    """(mine id, true depth m, slope k, intercept c K, model object) of every matched mine;
    the model object is the mine type's name or ``footprint`` (a cylinder of the footprint's
    size, :func:`clearfast_gis.thermal.measure.anomaly_measure`)."""
    c = characterisation_inputs(survey, products)
    feats = c["features"]
    fx, fy = np.array([f.x for f in feats]), np.array([f.y for f in feats])
    forcing = under_canopy(c["forcing"], c["canopy"])
    t = c["times_s"]
    gain = np.ones(t.shape) if c["gain"] is None else np.asarray(c["gain"])
    tables: dict = {}
    out = []
    for m in read_truth_objects(survey):
        if m["kind"] not in MINE_KINDS or m["depth_m"] > MAX_DEPTH_M or not feats:
            continue
        j = nearest_match(fx, fy, m)
        if j is None:
            continue
        me = anomaly_measure(feats[j])
        key = (me.radius_m, me.height_m)
        if key not in tables:
            tables[key] = chain_site_table(forcing, c["soil"], me.radius_m, t, c["canopy"],
                                           me.height_m)
        tab = tables[key]
        blur = 0.0 if c["blur_m"] is None else float(np.asarray(c["blur_m"])[j])
        grid = tab.contrast_for(me.radius_m, t, me.over_m, me.ring_m, blur) * gain
        model = contrast_spline(tab.depths_m, tab.log10_alpha, grid)(
            np.array([[m["depth_m"], np.log10(m["diffusivity_m2s"])]]))[0]
        obs = first_band(feats[j].centre_k) - first_band(feats[j].ring_k)
        ok = np.isfinite(obs)
        (k, c0), *_ = np.linalg.lstsq(np.stack([model[ok], np.ones(ok.sum())], axis=1),
                                      obs[ok], rcond=None)
        out.append((m["id"], m["depth_m"], float(k), float(c0),
                    me.kind.name if me.kind is not None else "footprint"))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("pairs", nargs="+", metavar="SURVEY:PRODUCTS")
    args = ap.parse_args()
    print("| survey | mine | true depth cm | model object | slope k | intercept K |\n"
          "|---|---|---|---|---|---|")
    ks: dict[str, list[float]] = {}
    for pair in args.pairs:
        survey, products = pair.split(":")
        for mid, depth, k, c0, model in mine_slopes(survey, products):
            if model != "footprint":  # the summary is of the mine types' model
                ks.setdefault(mid[:2], []).append(k)
            print(f"| {survey} | {mid} | {100 * depth:.0f} | {model} | {k:.3f} | {c0:+.3f} |")
    every = [k for v in ks.values() for k in v]
    print("\n| mines | n | mean k | sd k | rms of k - 1 |\n|---|---|---|---|---|")
    for name, v in sorted(ks.items()) + [("all", every)]:
        v = np.asarray(v)
        print(f"| {name} | {v.size} | {v.mean():.3f} | {v.std(ddof=1):.3f} | "
              f"{np.sqrt(np.mean((v - 1) ** 2)):.3f} |")


if __name__ == "__main__":
    main()
