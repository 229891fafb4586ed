"""Detection and characterisation accuracy against simulated ground truth, over seeds.

Simulates surveys (``--preset``, ``--seeds``, optionally ``--drift``), processes each, and
scores the suspects against ``truth/objects.csv``: detection probability for mines
surface-laid or buried <= 5 cm, false alarms (suspects cued as mines that match no mine) per
m2 of footprint, centre error, diameter error, depth error of characterised mines; the scans'
residual misregistration against the reference scan as the chain measured it on the mosaics
(``products.json``) and as the placement errors against the true poses make it
(:func:`~clearfast_gis.evaluation.truth.placement_errors`). With
``--sweep`` it also re-runs the detector over a small grid of (epsilon, level) on the same
mosaics (without the thermal characterisation) to show the trade-off.

    python benchmarks/detection_accuracy.py --preset demo --seeds 0 1 2 [--drift] [--sweep]
        [--scenario FILE]

``--scenario FILE`` places the scenario file's objects (and overrides) instead of the preset's
draw, e.g. AP mines at 6, 7 and 8 cm (``benchmarks/scenarios/deep_demo.json``).

Prints a markdown table. Simulated surveys and products are kept in ``--work`` (default
``/tmp/clearfast-bench``) and reused when present (``--redo-anomalies`` re-runs the anomaly
stage on kept mosaics). Surveys simulated and processed elsewhere are scored as they are with
``--pair NAME SURVEY PRODUCTS`` (repeatable; nothing is simulated or processed for them):

    python benchmarks/detection_accuracy.py --seeds --fast \
        --pair trial-s0 /data/trial0 /data/p_trial0 --pair trial-s1-drift ...

A second table scores the ranked suspect list and the depths
(:func:`clearfast_gis.evaluation.ranked.score_ranked`): Pd of mines at most 5 cm deep at
<= 0.01 false alarms per m2 going down the list by ``p_mine``; depth mean absolute error at
0-4 cm, 6-8 cm and of surface-laid mines; deep mines characterised wrongly (``ok`` and more
than 2 cm off); the share of characterised mines within 1 and 2 sigma; the share of 0-4 cm
mines whose diffusivity is within 25 %; the 68th percentile of abs(depth error) / sigma (1
for honest sigmas: the factor they would have to be scaled by). Pooled over the seeds, and
the reliability table of ``p_mine`` (of the suspects predicted p, how many are mines). Score
it only on seeds the likelihood model was not fitted on
(``clearfast_gis/data/likelihood.json`` ``fitted_on``).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import time
from pathlib import Path

import numpy as np

from clearfast_gis.detection.likelihood import load_model
from clearfast_gis.evaluation.operating import reliability_table
from clearfast_gis.evaluation.ranked import score_ranked
from clearfast_gis.evaluation.truth import placement_errors, score_against_truth
from clearfast_gis.pipeline import ProcessOptions, process_survey, redetect
from clearfast_gis.simulate import load_scenario, preset, simulate_survey


def rms(v):
    return float(np.sqrt(np.mean(np.square(v)))) if len(v) else float("nan")


def _spread(v) -> str:
    """'median / max (n above 0.5)' of residuals in pixels."""
    v = np.asarray(v, dtype=float)
    if not v.size:
        return "n/a"
    return f"{np.median(v):.2f} / {v.max():.2f} ({int(np.sum(v > 0.5))})"


def depth_figures(depths) -> dict:
    """Depth and diffusivity figures of matched mines (DepthRow list)."""
    ok = [d for d in depths if d.status == "ok" and np.isfinite(d.depth_m)]

    def mae(lo, hi):
        v = [abs(d.depth_m - d.true_depth_m) for d in ok
             if lo - 1e-9 <= d.true_depth_m <= hi + 1e-9]
        return (100 * float(np.mean(v)) if v else float("nan")), len(v)

    z = np.array([abs(d.depth_m - d.true_depth_m) / d.depth_sigma_m for d in ok
                  if d.depth_sigma_m > 0])
    # surface-laid mines estimated at the depth bound 0 have no error whatever their sigma
    zb = np.array([abs(d.depth_m - d.true_depth_m) / d.depth_sigma_m for d in ok
                   if d.depth_sigma_m > 0 and d.true_depth_m > 1e-9])
    shallow = [d for d in ok if d.true_depth_m <= 0.04 + 1e-9 and np.isfinite(d.alpha_m2s)]
    alpha_ok = [abs(d.alpha_m2s / d.true_alpha_m2s - 1) <= 0.25 for d in shallow]
    za = np.array([abs(np.log(d.alpha_m2s / d.true_alpha_m2s))
                   / (d.alpha_sigma_m2s / d.alpha_m2s) for d in shallow if d.alpha_sigma_m2s > 0])
    deep = [d for d in depths if d.true_depth_m >= 0.05]
    wrong = sum(1 for d in deep if d.status == "ok" and abs(d.depth_m - d.true_depth_m) > 0.02)
    return {"mae_0_4": mae(0.0, 0.04), "mae_6_8": mae(0.06, 0.08), "mae_0": mae(0.0, 0.0),
            "within1": float(np.mean(z <= 1)) if z.size else float("nan"),
            "within2": float(np.mean(z <= 2)) if z.size else float("nan"), "n_z": int(z.size),
            "z68": float(np.quantile(z, 0.683)) if z.size else float("nan"),
            "z68_buried": float(np.quantile(zb, 0.683)) if zb.size else float("nan"),
            "n_buried": int(zb.size),
            "alpha25": float(np.mean(alpha_ok)) if alpha_ok else float("nan"),
            "alpha_within1": float(np.mean(za <= 1)) if za.size else float("nan"),
            "n_alpha": len(alpha_ok), "deep_wrong": wrong, "n_deep": len(deep),
            "n_matched": len(depths), "n_ok": len(ok)}


def _z68(f: dict) -> str:
    """The 68th percentile of abs(error) / sigma: all characterised mines; buried ones (n)."""
    return f"{f['z68']:.2f}; {f['z68_buried']:.2f} ({f['n_buried']})"


def print_mines(ranked) -> None:
    """Every matched mine: true and estimated depth, sigma, status, diffusivity ratio."""
    print("\n| survey | mine | true depth cm | depth cm | sigma cm | abs(error) / sigma | status "
          "| diffusivity / truth |\n|---|---|---|---|---|---|---|---|")
    for tag, r in ranked:
        for d in sorted(r.depths, key=lambda d: d.true_depth_m):
            z = abs(d.depth_m - d.true_depth_m) / d.depth_sigma_m if d.depth_sigma_m > 0 else 0
            print(f"| {tag} | {d.mine_id} | {100 * d.true_depth_m:.0f} | {100 * d.depth_m:.2f} "
                  f"| {100 * d.depth_sigma_m:.2f} | {z:.2f} | {d.status} | "
                  f"{d.alpha_m2s / d.true_alpha_m2s:.2f} |")


def print_ranked(ranked) -> None:
    """The ranked-list and depth table, pooled row, and the reliability table."""
    if not ranked:
        return
    print("\n| survey | suspects / candidates | Pd (<= 5 cm) at <= 0.01 FA/m2 by p_mine | "
          "Pd, whole list | depth MAE 0-4 cm, cm (n) | 6-8 cm (n) | surface-laid (n) | "
          "deep mines ok but > 2 cm off (of) | within 1 / 2 sigma (n) | 68th percentile of "
          "abs(error) / sigma; buried mines only (n) | diffusivity within 25 % at 0-4 cm; within "
          "1 sigma (n) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    pooled = []
    for tag, r in ranked:
        f = depth_figures(r.depths)
        pooled.extend(r.depths)
        print(f"| {tag} | {len(r.p_mine)} / {r.n_candidates} ({r.n_candidate_mines} mines) | "
              f"{r.pd_at(0.01):.2f} ({r.n_scored_mines}) | "
              f"{r.pd[-1]:.2f} | {f['mae_0_4'][0]:.2f} ({f['mae_0_4'][1]}) | "
              f"{f['mae_6_8'][0]:.2f} ({f['mae_6_8'][1]}) | {f['mae_0'][0]:.2f} "
              f"({f['mae_0'][1]}) | {f['deep_wrong']} ({f['n_deep']}) | {f['within1']:.2f} / "
              f"{f['within2']:.2f} ({f['n_z']}) | {_z68(f)} | {f['alpha25']:.2f}; "
              f"{f['alpha_within1']:.2f} ({f['n_alpha']}) |")
    f = depth_figures(pooled)
    n_mines = sum(r.n_scored_mines for _, r in ranked)
    found = sum(r.pd_at(0.01) * r.n_scored_mines for _, r in ranked)
    print(f"| pooled | | {found / max(n_mines, 1):.2f} ({n_mines}) | | "
          f"{f['mae_0_4'][0]:.2f} ({f['mae_0_4'][1]}) | {f['mae_6_8'][0]:.2f} "
          f"({f['mae_6_8'][1]}) | {f['mae_0'][0]:.2f} ({f['mae_0'][1]}) | {f['deep_wrong']} "
          f"({f['n_deep']}) | {f['within1']:.2f} / {f['within2']:.2f} ({f['n_z']}) | "
          f"{_z68(f)} | {f['alpha25']:.2f}; {f['alpha_within1']:.2f} ({f['n_alpha']}) |")
    p = np.concatenate([r.p_mine for _, r in ranked])
    y = np.concatenate([r.is_mine for _, r in ranked])
    print("\n| p_mine | suspects | mean p_mine | share that are mines |\n|---|---|---|---|")
    for row in reliability_table(p, y):
        mp = "-" if row["mean_p"] is None else f"{row['mean_p']:.2f}"
        mf = "-" if row["mine_fraction"] is None else f"{row['mine_fraction']:.2f}"
        print(f"| {row['bin']} | {row['n']} | {mp} | {mf} |")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--preset", default="demo")
    ap.add_argument("--seeds", type=int, nargs="*", default=[0, 1, 2])
    ap.add_argument("--pair", nargs=3, action="append", default=[],
                    metavar=("NAME", "SURVEY", "PRODUCTS"),
                    help="score an existing survey and its products as they are")
    ap.add_argument("--drift", action="store_true")
    ap.add_argument("--scenario", help="scenario file: its objects and overrides (docs/"
                                       "simulator.md) instead of the preset's draw")
    ap.add_argument("--sweep", action="store_true")
    ap.add_argument("--work", default="/tmp/clearfast-bench")
    ap.add_argument("--redo-anomalies", action="store_true")
    ap.add_argument("--rerank", action="store_true",
                    help="screen and rank the detections again under the current likelihood "
                         "model (products made before a refit)")
    ap.add_argument("--mines", action="store_true",
                    help="list every matched mine's depth, sigma and status")
    ap.add_argument("--fast", action="store_true",
                    help="skip the placement errors against the true poses")
    args = ap.parse_args()
    ranked = []
    model = load_model() if args.rerank else None
    work = Path(args.work)
    rows = []
    sweep: dict[tuple, list] = {}
    scen = load_scenario(args.scenario, preset(args.preset)) if args.scenario else None
    config = scen.config if scen else preset(args.preset)
    stem = f"-{Path(args.scenario).stem}" if args.scenario else ""
    for seed in args.seeds:
        tag = f"{args.preset}{stem}-s{seed}{'-drift' if args.drift else ''}"
        survey, products = work / tag / "survey", work / tag / "products"
        t0 = time.perf_counter()
        if not (survey / "survey.json").exists():
            simulate_survey(survey, config, seed=seed, drift=args.drift,
                            objects=list(scen.objects) if scen else None,
                            draw_clutter=scen.draw_clutter if scen else False)
        t_sim = time.perf_counter() - t0
        t0 = time.perf_counter()
        manifest = process_survey(survey, products, ProcessOptions(),
                                  from_stage="detection" if args.redo_anomalies else None)
        t_proc = time.perf_counter() - t0
        s = score_against_truth(survey, products)
        ranked.append((tag, score_ranked(survey, products, model)))
        if args.fast:
            continue
        res = [r["residual_px"] for r in manifest["scans"] if r.get("residual_px") is not None]
        rows.append((tag, s, t_sim, t_proc, manifest.get("markers", {}), res,
                     placement_errors(survey, products)))
        if args.sweep:
            for eps in (0.005, 0.01, 0.02):
                for frac in (0.25, 0.5):
                    n_img = len(manifest["scans"]) * len(manifest["bands"])
                    lvl = max(1, int(round(frac * n_img)))
                    redetect(products, dataclasses.replace(ProcessOptions(), epsilon=eps,
                                                           level=lvl, invert=False))
                    sweep.setdefault((eps, frac), []).append(score_against_truth(survey,
                                                                                  products))
            process_survey(survey, products, ProcessOptions())  # restore the defaults
    model = load_model() if args.rerank else None
    for name, survey, products in args.pair:
        s = score_against_truth(survey, products)
        ranked.append((name, score_ranked(survey, products, model)))
        if not args.fast:
            manifest = json.loads((Path(products) / "products.json").read_text())
            res = [r["residual_px"] for r in manifest["scans"]
                   if r.get("residual_px") is not None]
            rows.append((name, s, float("nan"), float("nan"), manifest.get("markers", {}), res,
                         placement_errors(survey, products)))
    print("| survey | Pd (<= 5 cm) | FA/m2 | centre RMS cm | diameter RMS % | depth RMS cm "
          "(n) | markers RMS cm | residual vs reference px, measured (median / max, > 0.5) "
          "| misregistration from the true poses px, RMS over the cells (median / max, > 0.5) "
          "| placement RMS cm "
          "(worst scan) | simulate s | process s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for tag, s, ts, tp, mk, res, pl in rows:
        mrms = mk.get("rms_offset_m")
        rel = np.array([v for v in pl.relative_px if np.isfinite(v)])
        absm = np.array(pl.abs_rms_m)
        print(f"| {tag} | {s.n_detected}/{s.n_mines} = {s.detection_probability:.2f} | "
              f"{s.false_alarms_per_m2:.3f} | {100 * rms(s.centre_errors_m):.1f} | "
              f"{100 * rms(s.diameter_rel_errors):.0f} | {100 * rms(s.depth_errors_m):.2f} "
              f"({len(s.depth_errors_m)}) | {'-' if mrms is None else f'{100 * mrms:.1f}'} | "
              f"{_spread(res)} | {_spread(rel)} | "
              f"{100 * np.sqrt(np.mean(absm ** 2)):.2f} ({100 * absm.max():.2f}) | "
              f"{ts:.0f} | {tp:.0f} |")
    print_ranked(ranked)
    if args.mines:
        print_mines(ranked)
    for tag, s, *_ in rows:
        if s.missed:
            print(f"\n{tag} missed: {', '.join(s.missed)}")
    if sweep:
        print("\n| epsilon | level (fraction of images) | Pd | FA/m2 |\n|---|---|---|---|")
        for (eps, frac), scores in sorted(sweep.items()):
            nd = sum(s.n_detected for s in scores)
            nm = sum(s.n_mines for s in scores)
            fa = sum(s.n_false_alarms for s in scores)
            area = sum(s.footprint_m2 for s in scores)
            print(f"| {eps} | {frac} | {nd}/{nm} = {nd / max(nm, 1):.2f} | {fa / area:.3f} |")


if __name__ == "__main__":
    main()
