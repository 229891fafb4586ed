"""The chain across weather, soils and sites: a matrix of conditions x seeds.

Each condition is a scenario (weather, soil, grass, site, date) on a preset (``--preset demo``
by default; ``trial`` for the full-scale matrix, ~12 min a survey on one core). Every survey
is simulated, processed with the default options, and scored against its truth:

- Pd: mines surface-laid or buried at most 5 cm that a suspect matches;
- false alarms per m2: suspects cued as mines that match no mine;
- centre error (RMS), depth error (MAE) of confident depths (``ok``/``at_bound``) of mines at
  0-4 cm and at all depths;
- honest statuses: the share of matched mines (any depth) whose status is honest
  (:mod:`clearfast_gis.evaluation.honesty`: a flag, or a confident depth within
  max(2 sigma, 1 cm) of the truth);
- the day's contrast the chain stated (``products.json`` ``day_contrast``: modelled contrast
  of a 10 cm AP mine at 5 cm, the noise, the deepest depth that shows) and whether the
  report warned of low contrast.

The real-weather condition forces the twin with a real station record (a CR1000 ClimaVUE50
table, Svalbard, July 2024, from ``../shared/data/real-field-files/toa5``, read by Campbell's
standard names; not copied into the repository).

    python benchmarks/conditions.py [--preset demo] [--seeds 0 1] [--only clear overcast]
        [--fills tnt comp_b plastic pine]

``--fills`` gives each mine a body drawn from those materials (the scenario's ``mine_fills``)
instead of every mine TNT-filled: the handbook spread of fills that the inversion's prior of
a mine's diffusivity states, which the single-fill twin cannot test.

Conditions run in the order listed (the most telling first).

Prints a markdown table; surveys and products are kept in ``--work`` (default
``/tmp/clearfast-conditions``) and reused when present.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

from clearfast_gis.evaluation import mine_statuses, score_against_truth
from clearfast_gis.evaluation.ranked import score_ranked
from clearfast_gis.pipeline import ProcessOptions, process_survey
from clearfast_gis.simulate import parse_scenario, preset, simulate_survey
from clearfast_gis.thermal.materials import MINE_FILLS

ROOT = Path(__file__).resolve().parents[1]
REAL_TOA5 = (ROOT.parent / "shared" / "data" / "real-field-files" / "toa5"
             / "LouisPauchet__data_SN6134_ClimatVUE_ClimatVIEW_1h.dat")
REAL_DAY = "2024-07-22T00:00:00Z"

NICOSIA = {"latitude_deg": 35.17, "longitude_deg": 33.36, "epsg": 32636}
CHAD = {"name": "N'Djamena region (simulated)", "latitude_deg": 12.1, "longitude_deg": 15.0,
        "epsg": 32633}
ANGOLA = {"name": "Cuito Cuanavale (simulated)", "latitude_deg": -15.16,
          "longitude_deg": 19.17, "epsg": 32734}
SVALBARD = {"name": "Longyearbyen (station record)", "latitude_deg": 78.22,
            "longitude_deg": 15.65, "epsg": 32633}

CONDITIONS: dict[str, dict] = {
    "clear": {},
    "overcast": {"weather": {"cloud_cover": 1.0, "air_temp_c": [11, 17]}},
    "partly cloudy 0.5": {"weather": {"cloud_cover": 0.5}},
    "after rain (8 mm, loam)": {
        "soil": {"type": "loam", "moisture": 0.35},
        "weather": {"rain": [{"start_utc": "2026-11-15T02:00:00Z", "duration_h": 1.5,
                              "total_mm": 8.0}], "cloud_cover": [[0, 0.9], [6, 0.3]]}},
    "clay": {"soil": {"type": "clay", "moisture": 0.4}},
    "grass 40 %": {"vegetation_cover": 0.4},
    "tropics, dry season (12 N, Feb)": {
        "site": CHAD, "start_utc": "2026-02-15T00:00:00Z",
        "weather": {"air_temp_c": [18, 35], "rh_pct": [15, 35]},
        "soil": {"type": "loamy_sand", "moisture": 0.15}},
    "southern summer (15 S, Jan)": {
        "site": ANGOLA, "start_utc": "2026-01-15T00:00:00Z",
        "weather": {"air_temp_c": [17, 29], "rh_pct": [55, 85], "cloud_cover": 0.3},
        "soil": {"type": "sand", "moisture": 0.3}},
    "southern winter (15 S, Jul)": {
        "site": ANGOLA, "start_utc": "2026-07-15T00:00:00Z",
        "weather": {"air_temp_c": [7, 27], "rh_pct": [20, 45]},
        "soil": {"type": "sand", "moisture": 0.1}},
    "real weather (Svalbard, 22 Jul 2024)": {
        "site": SVALBARD, "start_utc": REAL_DAY, "weather": {"file": str(REAL_TOA5)},
        "soil": {"type": "gravel", "moisture": 0.3}},
    "loam": {"soil": {"type": "loam", "moisture": 0.35}},
    "clear, sand evaporating": {"soil": {"type": "sand", "moisture": 0.3}},
    "northern summer (35 N, Jul)": {
        "site": NICOSIA, "start_utc": "2026-07-15T00:00:00Z",
        "weather": {"air_temp_c": [22, 37], "rh_pct": [30, 55]}},
    "northern winter (35 N, Jan)": {
        "site": NICOSIA, "start_utc": "2026-01-15T00:00:00Z",
        "weather": {"air_temp_c": [5, 15], "rh_pct": [65, 85]}},
    "clouds building 0.2 -> 0.9": {"weather": {"cloud_cover": [[0, 0.2], [12, 0.9],
                                                               [24, 0.5]]}},
    "windy, gusts": {"weather": {"wind_scale": 2.5, "gusts": 0.3}},
}


#: The goal's false-alarm rate: Pd is also read down the ranked list (p_mine) up to it.
MAX_FA_PER_M2 = 0.01


def score(survey: Path, products: Path) -> dict:
    """Pd, FA/m2, centre RMS, depth MAE of confident depths (0-4 cm and all), honest share."""
    s = score_against_truth(survey, products)
    statuses = mine_statuses(survey, products)
    conf = [m for m in statuses if m.confident]
    manifest = json.loads((products / "products.json").read_text())
    ranked = score_ranked(survey, products)
    return {"score": s, "honest": (sum(m.honest for m in statuses), len(statuses)),
            "pd_ranked": (ranked.pd_at(MAX_FA_PER_M2) * ranked.n_scored_mines,
                          ranked.n_scored_mines),
            "mae_shallow": [abs(m.depth_m - m.true_depth_m) for m in conf
                            if m.true_depth_m <= 0.04],
            "mae_all": [abs(m.depth_m - m.true_depth_m) for m in conf],
            "day": manifest.get("day_contrast"),
            "warned": any("low thermal contrast" in w for w in manifest.get("warnings", []))}


def _mean_cm(v: list[float]) -> str:
    return f"{100 * np.mean(v):.2f} ({len(v)})" if v else "- (0)"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--preset", default="demo")
    ap.add_argument("--seeds", type=int, nargs="+", default=[0, 1])
    ap.add_argument("--only", nargs="*", help="conditions whose name starts with these")
    ap.add_argument("--work", default="/tmp/clearfast-conditions")
    ap.add_argument("--fills", nargs="+", choices=MINE_FILLS, metavar="FILL",
                    help="draw each mine's body from these (scenario mine_fills: "
                         f"{', '.join(MINE_FILLS)}); surveys go to folders ending -fills")
    ap.add_argument("--score-only", action="store_true",
                    help="score the products already in --work (no simulation, no processing)")
    args = ap.parse_args()
    work = Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    names = [n for n in CONDITIONS
             if not args.only or any(n.startswith(o) for o in args.only)]
    print("| condition | seed | Pd (<= 5 cm) | FA/m2 | Pd at 0.01 FA/m2 (ranked) "
          "| centre RMS cm | depth MAE cm 0-4 cm (n) "
          "| depth MAE cm all (n) | honest statuses | day: AP mine at 1 / 5 cm, noise (K) "
          "| shows to | sun (clear-sky index), rain | low-contrast warning | simulate s "
          "| process s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    totals: dict[str, list[dict]] = {}
    for name in names:
        doc = {"format": "clearfast-scenario", "format_version": 1, "preset": args.preset,
               **CONDITIONS[name], **({"mine_fills": args.fills} if args.fills else {})}
        slug = "".join(c if c.isalnum() else "-" for c in name.lower()).strip("-")
        slug += "-fills" if args.fills else ""
        for seed in args.seeds:
            base = work / f"{args.preset}-{slug}-s{seed}"
            base.mkdir(parents=True, exist_ok=True)
            cfg = parse_scenario(doc, None, preset(args.preset)).config
            survey, products = base / "survey", base / "products"
            t0 = time.perf_counter()
            if args.score_only and not (products / "report.html").exists():
                continue
            if not (survey / "survey.json").exists():
                simulate_survey(survey, cfg, seed=seed)
            t_sim = time.perf_counter() - t0
            t0 = time.perf_counter()
            if not args.score_only:
                process_survey(survey, products, ProcessOptions(), from_stage="detection")
            t_proc = time.perf_counter() - t0
            r = score(survey, products)
            totals.setdefault(name, []).append(r)
            print(_row(name, str(seed), [r]) + f" {t_sim:.0f} | {t_proc:.0f} |", flush=True)
    if len(args.seeds) > 1 or args.score_only:
        print(f"\nOver seeds {' '.join(map(str, args.seeds))} (day: mean over the seeds)\n")
        print("| condition | seeds | Pd (<= 5 cm) | FA/m2 | Pd at 0.01 FA/m2 (ranked) "
              "| centre RMS cm "
              "| depth MAE cm 0-4 cm (n) | depth MAE cm all (n) | honest statuses "
              "| day: AP mine at 1 / 5 cm, noise (K) | shows to | sun (clear-sky index), rain "
              "| low-contrast warning |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for name, rs in totals.items():
            print(_row(name, str(len(rs)), rs))


def _row(name: str, seeds: str, rs: list[dict]) -> str:
    """One markdown row (without the timings) over one or several surveys' scores."""
    det = sum(r["score"].n_detected for r in rs)
    n = sum(r["score"].n_mines for r in rs)
    fa = sum(r["score"].n_false_alarms for r in rs)
    area = sum(r["score"].footprint_m2 for r in rs)
    centre = [e for r in rs for e in r["score"].centre_errors_m]
    days = [r["day"] or {} for r in rs]

    def mean_day(get) -> float:
        v = [get(d) for d in days]
        v = [x for x in v if x is not None and np.isfinite(x)]
        return float(np.mean(v)) if v else float("nan")

    def at(d: dict, depth: float):
        return dict(zip(d.get("depths_m", []), d.get("peak_contrast_k", []),
                        strict=True)).get(depth)

    deep = [d.get("deepest_showing_m") for d in days]
    deep_txt = "/".join("-" if x is None else f"{100 * x:.0f}" for x in deep) + " cm"
    csi = mean_day(lambda d: d.get("clear_sky_index"))
    warned = sum(r["warned"] for r in rs)
    found = sum(r["pd_ranked"][0] for r in rs)
    scored = sum(r["pd_ranked"][1] for r in rs)
    return (f"| {name} | {seeds} | {det}/{n} = {det / max(n, 1):.2f} | {fa / area:.3f} | "
            f"{found:.0f}/{scored} = {found / max(scored, 1):.2f} | "
            f"{100 * np.sqrt(np.mean(np.square(centre))) if centre else float('nan'):.1f} | "
            f"{_mean_cm([e for r in rs for e in r['mae_shallow']])} | "
            f"{_mean_cm([e for r in rs for e in r['mae_all']])} | "
            f"{sum(r['honest'][0] for r in rs)}/{sum(r['honest'][1] for r in rs)} | "
            f"{mean_day(lambda d: at(d, 0.01)):.2f} / {mean_day(lambda d: at(d, 0.05)):.2f}, "
            f"{mean_day(lambda d: d.get('noise_k')):.2f} | {deep_txt} | "
            f"{csi:.2f}, {mean_day(lambda d: d.get('rain_mm', 0)):.1f} mm | "
            f"{warned}/{len(rs)} |")

if __name__ == "__main__":
    main()
