"""The depth's stated 1-sigma against the real errors, term by term, on processed simulated
surveys.

For every buried mine (0 < depth <= 4.5 cm) of each survey that a detection matches (within
its radius plus 5 cm) and whose depth the chain reports as ``ok``, the characterisation stage
is run again (the products are rewritten with the same values) and each inversion is taken
as the chain made it, before and after its chain terms
(:func:`clearfast_gis.thermal.error_budget.with_chain_errors`). Printed: per true depth the
bias and spread of the error against the median stated sigmas; then, for the stated total
and for each group of terms alone, q68 (the 68th percentile of ``|error| / sigma``: 1 is
honest, below 1 the sigma is too wide) and the shares of errors within 1 and 2 sigma; and
the correlation of the error with the fit's own sigma.

    python benchmarks/depth_sigma_terms.py SURVEY:PRODUCTS [SURVEY:PRODUCTS ...]
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from clearfast_gis.evaluation.truth import MINE_KINDS, nearest_match, read_truth_objects
from clearfast_gis.pipeline import anomalies, process_survey
from clearfast_gis.thermal import sitesoil
from clearfast_gis.thermal.error_budget import chain_sigmas, model_depth_variance

MAX_DEPTH_M = 0.045
"""Buried mines this deep at most (the issue's 0-4 cm, with the table's rounding)."""


def chain_inversions(survey: str, products: str) -> tuple[list, dict]:
    """The features of a survey's characterisation and, per feature id, (the fit before the
    chain terms, the result after them, the extra gain term) as the chain made them."""
    made: dict = {}
    seen: dict = {}
    add_terms, characterise = sitesoil.with_chain_errors, anomalies.characterise

    def record_terms(inv, extra_gain=0.0):
        out = add_terms(inv, extra_gain)
        made[id(out)] = (inv, out, extra_gain)
        return out

    def record(features, *args, **kwargs):
        result = characterise(features, *args, **kwargs)
        seen.update(features=features, result=result)
        return result

    sitesoil.with_chain_errors, anomalies.characterise = record_terms, record
    try:
        process_survey(survey, products, from_stage="characterisation")
    finally:
        sitesoil.with_chain_errors, anomalies.characterise = add_terms, characterise
    by_id = {fid: made[id(out)] for fid, out in seen.get("result", {}).items()}
    return seen.get("features", []), by_id


def mine_rows(survey: str, products: str) -> list[dict]:
    """One row per matched buried mine with status ``ok``: true and estimated depth, the fit's
    sigma, the chain terms (gain and offset through the fit, the model's depth terms) and the
    stated total, all m; the fit's residual rms, K."""
    features, inversions = chain_inversions(survey, products)
    if not features:
        return []
    fx, fy = np.array([f.x for f in features]), np.array([f.y for f in features])
    rows = []
    for m in read_truth_objects(survey):
        if m["kind"] not in MINE_KINDS or not 0 < m["depth_m"] <= MAX_DEPTH_M:
            continue
        j = nearest_match(fx, fy, m)
        if j is None or features[j].id not in inversions:
            continue
        fit, out, extra = inversions[features[j].id]
        if out.status != "ok":
            continue
        model = math.sqrt(model_depth_variance(fit.depth_m))
        chain = chain_sigmas(fit, extra)[0]
        rows.append({"survey": survey, "id": m["id"], "true_m": m["depth_m"],
                     "est_m": out.depth_m, "fit_m": fit.depth_sigma_m, "model_m": model,
                     "curve_m": math.sqrt(max(chain**2 - model**2, 0.0)),
                     "total_m": out.depth_sigma_m, "rms_k": fit.residual_rms_k})
    return rows


def coverage(err_m: np.ndarray, sigma_m: np.ndarray) -> tuple[float, float, float]:
    """(q68 of ``|err| / sigma``, share within 1 sigma, share within 2 sigma)."""
    a = np.abs(err_m) / sigma_m
    return float(np.quantile(a, 0.68)), float(np.mean(a <= 1)), float(np.mean(a <= 2))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("pairs", nargs="+", metavar="SURVEY:PRODUCTS")
    args = ap.parse_args()
    rows = []
    for pair in args.pairs:
        survey, products = pair.split(":", 1)
        rows += mine_rows(survey, products)
    if not rows:
        print("no buried mine with status ok")
        return
    col = {k: np.array([r[k] for r in rows]) for k in rows[0] if k not in ("survey", "id")}
    err = col["est_m"] - col["true_m"]
    print(f"{len(rows)} buried mines at 0-{100 * MAX_DEPTH_M:.1f} cm with status ok, "
          f"{len(args.pairs)} surveys\n")
    print("| true depth | mines | bias cm | sd of the error cm | median sigma: fit, total cm "
          "| within 1 sigma (total) |")
    print("|---|---:|---:|---:|---|---:|")
    for depth in np.unique(np.round(col["true_m"], 3)):
        k = np.round(col["true_m"], 3) == depth
        e = err[k]
        print(f"| {100 * depth:.0f} cm | {k.sum()} | {100 * e.mean():+.2f} | {100 * e.std():.2f} "
              f"| {100 * np.median(col['fit_m'][k]):.2f}, {100 * np.median(col['total_m'][k]):.2f} "
              f"| {coverage(e, col['total_m'][k])[1]:.2f} |")
    curve = col["curve_m"]
    terms = {
        "stated total": col["total_m"],
        "the fit alone": col["fit_m"],
        "the chain terms alone": np.hypot(curve, col["model_m"]),
        "the fit, gain and offset": np.hypot(col["fit_m"], curve),
        "the larger of fit and model, gain and offset":
            np.hypot(np.maximum(col["fit_m"], col["model_m"]), curve),
    }
    print("\n| sigma | median cm | q68 | within 1 sigma | within 2 sigma |")
    print("|---|---:|---:|---:|---:|")
    for name, s in terms.items():
        q, one, two = coverage(err, s)
        print(f"| {name} | {100 * np.median(s):.2f} | {q:.2f} | {one:.2f} | {two:.2f} |")
    r = float(np.corrcoef(np.abs(err), col["fit_m"])[0, 1])
    lo, mid, hi = np.quantile(col["rms_k"], [0.1, 0.5, 0.9]) * 1000
    print(f"\ncorrelation of |error| with the fit's sigma: {r:.2f}; the fit's residual rms "
          f"{lo:.0f} / {mid:.0f} / {hi:.0f} mK (10th / 50th / 90th percentile)")


if __name__ == "__main__":
    main()
