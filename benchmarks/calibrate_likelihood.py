"""Fit the ``p_mine`` model (clearfast_gis/detection/likelihood.py) on processed simulated
surveys and write its parameters to ``clearfast_gis/data/likelihood.json``.

    python benchmarks/calibrate_likelihood.py --work /tmp/clearfast-bench \
        --tags demo-s10 demo-s11 ... [--write]

Each tag names ``WORK/TAG/survey`` (with ``truth/``) and ``WORK/TAG/products`` (processed);
``--pair NAME SURVEY PRODUCTS`` (repeatable) adds a survey and its products kept elsewhere.
Every detection of the products that passes the screening
(:mod:`clearfast_gis.detection.screening`) is a training row; its label is 1 when it lies
within the radius plus 5 cm of a true mine of any depth. The surveys fitted on must never be
the ones the model is scored on (``benchmarks/detection_accuracy.py`` scores other seeds).
Logistic regression: scikit-learn, L2 penalty C = 1 on standardised features.

``--check`` fits nothing: it scores the stored model on the surveys given (which must not be
the ones it was fitted on): its reliability table (of the suspects predicted p, the share
that are mines) and, per survey, the mines it expects (sum of p_mine) against those found.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from clearfast_gis.detection.likelihood import FEATURES, features, p_mine_from_features
from clearfast_gis.detection.screening import screen
from clearfast_gis.evaluation.operating import reliability_table
from clearfast_gis.evaluation.truth import MINE_KINDS, mine_match_radius_m, read_truth_objects

MODEL_VERSION = "logistic-5"


def detection_records(products: Path) -> list[dict]:
    """Every detection of a products folder as records (the ``anomalies`` layer)."""
    import geopandas as gpd

    frame = gpd.read_file(products / "anomalies.gpkg", layer="anomalies")
    recs = frame.drop(columns="geometry").to_dict("records")
    for r in recs:
        for k, v in list(r.items()):
            if isinstance(v, float) and np.isnan(v):
                r[k] = None
    return recs


def is_mine(records: list[dict], survey: Path) -> np.ndarray:
    """Per record: lies within the radius plus 5 cm of a true mine (any depth)."""
    mines = [m for m in read_truth_objects(survey) if m["kind"] in MINE_KINDS]
    out = np.zeros(len(records), dtype=bool)
    for i, r in enumerate(records):
        out[i] = any(np.hypot(r["x"] - m["x"], r["y"] - m["y"]) <= mine_match_radius_m(m)
                     for m in mines)
    return out


def training_rows(survey: Path, products: Path) -> tuple[np.ndarray, np.ndarray]:
    """Features (M, F) and labels (M,) of the screened detections of one survey."""
    n_scans = len(json.loads((products / "products.json").read_text())["scans"])
    suspects, _ = screen(detection_records(products), n_scans)
    x = np.array([features(r) for r in suspects]).reshape(-1, len(FEATURES))
    return x, is_mine(suspects, survey)


def main() -> None:
    from sklearn.linear_model import LogisticRegression

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--work", default="/tmp/clearfast-bench")
    ap.add_argument("--tags", nargs="*", default=[])
    ap.add_argument("--pair", nargs=3, action="append", default=[],
                    metavar=("NAME", "SURVEY", "PRODUCTS"))
    ap.add_argument("--write", action="store_true", help="write clearfast_gis/data/likelihood.json")
    ap.add_argument("--check", action="store_true",
                    help="score the stored model on these surveys instead of fitting")
    args = ap.parse_args()
    xs, ys = [], []
    pairs = [(t, Path(args.work) / t / "survey", Path(args.work) / t / "products")
             for t in args.tags] + [(n, Path(s), Path(p)) for n, s, p in args.pair]
    if not pairs:
        ap.error("give --tags or --pair")
    for tag, survey, products in pairs:
        x, y = training_rows(survey, products)
        xs.append(x)
        ys.append(y)
        print(f"{tag}: {len(y)} suspects, {int(y.sum())} mines")
    x, y = np.vstack(xs), np.concatenate(ys)
    if args.check:
        check(pairs, xs, ys)
        return
    mean, scale = x.mean(axis=0), x.std(axis=0)
    scale[scale == 0] = 1.0
    fit = LogisticRegression(C=1.0, max_iter=1000).fit((x - mean) / scale, y)
    model = {"version": MODEL_VERSION, "features": list(FEATURES),
             "mean": [round(float(v), 6) for v in mean],
             "scale": [round(float(v), 6) for v in scale],
             "coef": [round(float(v), 6) for v in fit.coef_[0]],
             "intercept": round(float(fit.intercept_[0]), 6),
             "fitted_on": [t for t, _, _ in pairs], "n_rows": int(len(y)), "n_mines": int(y.sum())}
    p = p_mine_from_features(x, model)
    model["reliability_in_sample"] = reliability_table(p, y)
    print(json.dumps(model, indent=1))
    if args.write:
        out = Path(__file__).resolve().parents[1] / "clearfast_gis" / "data" / "likelihood.json"
        out.write_text(json.dumps(model, indent=1) + "\n")
        print(f"written {out}")


def check(pairs: list, xs: list[np.ndarray], ys: list[np.ndarray]) -> None:
    """Print the stored model's out-of-sample reliability over the surveys and, per survey,
    the mines it expects (sum of p_mine over the screened suspects) against the mines."""
    from clearfast_gis.detection.likelihood import load_model

    model = load_model()
    fitted = set(model["fitted_on"])
    print(f"model {model['version']}; fitted on {', '.join(model['fitted_on'])}")
    for (tag, _, _), x, y in zip(pairs, xs, ys, strict=True):
        warn = "  (fitted on!)" if tag in fitted else ""
        print(f"{tag}: expected {p_mine_from_features(x, model).sum():.1f} mines, "
              f"{int(y.sum())} among {len(y)} suspects{warn}")
    p = p_mine_from_features(np.vstack(xs), model)
    y = np.concatenate(ys)
    print(f"all: expected {p.sum():.1f} mines, {int(y.sum())} among {len(y)} suspects")
    print("| p_mine | suspects | mean p_mine | share that are mines |")
    print("|---|---|---|---|")
    for row in reliability_table(p, y):
        print(f"| {row['bin']} | {row['n']} | {row['mean_p']} | {row['mine_fraction']} |")


if __name__ == "__main__":
    main()
