"""The whole chain on the simulated ``trial`` survey: time, CPU and memory per stage.

Simulates the ``trial`` preset once (cached in ``--work``), then runs ``clearfast process`` in a
child process per configuration (so that each run's peak memory is its own) and prints
markdown tables from the ``resources`` record of each ``products.json``:

- per stage, wall / CPU / peak RSS, for each kernel set of ``--kernels`` on the same survey in
  the same run (``fast`` and ``reference``), with the end-to-end ratio and a comparison of the
  anomalies the two produce (suspects matched within 3 cm, detection scores against truth);
- with ``--scaling N ...``: the fast chain on the first N scans (``subset_survey``), to show
  time against the number of scans and frames;
- with ``--workers W ...``: ``--batch`` copies of a ``--batch-scans``-scan subset converted
  by ``run_batch`` on a local Dask cluster of W single-threaded worker processes.

    python benchmarks/full_survey.py [--kernels fast reference] [--scans 48]
        [--scaling 6 12 24 48] [--workers 1 2] [--drift] [--work /tmp/clearfast-full]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

STAGES = ("read_and_validate", "band_coregistration", "mosaics", "attitude_adjustment",
          "residuals_and_footprint", "detection", "characterisation", "products")


def simulated(work: Path, seed: int, drift: bool) -> Path:
    """The cached ``trial`` survey folder (simulated on first use)."""
    from clearfast_gis.simulate import preset, simulate_survey

    survey = work / f"trial-s{seed}{'-drift' if drift else ''}" / "survey"
    if not (survey / "survey.json").exists():
        t0 = time.perf_counter()
        simulate_survey(survey, preset("trial"), seed=seed, drift=drift)
        print(f"simulated {survey} in {time.perf_counter() - t0:.0f} s", file=sys.stderr)
    return survey


def subset(survey: Path, n_scans: int) -> Path:
    """``survey`` itself for all its scans, else a cached subset folder beside it."""
    from clearfast_gis.survey.subset import subset_survey

    n_all = len({line.split(",", 1)[0] for line in
                 (survey / "frames.csv").read_text().splitlines()[1:]})
    if n_scans >= n_all:
        return survey
    out = survey.parent / f"survey-{n_scans}scans"
    if not (out / "survey.json").exists():
        subset_survey(survey, out, n_scans)
    return out


def process(survey: Path, products: Path, kernels: str) -> dict:
    """Run ``clearfast process`` from scratch in a child process; its products.json."""
    cmd = [sys.executable, "-m", "clearfast_gis.cli.main", "process", str(survey), "-o",
           str(products), "--no-resume", "--progress", "none", "--kernels", kernels]
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, env=os.environ | {"PYTHONWARNINGS": "ignore"})
    wall = time.perf_counter() - t0
    manifest = json.loads((products / "products.json").read_text())
    manifest["_child_wall_s"] = wall
    return manifest


def n_frames(survey: Path) -> int:
    """Rows of the frame table (frames of every band)."""
    return len((survey / "frames.csv").read_text().splitlines()) - 1


def stage_table(runs: dict[str, dict]) -> None:
    """Per-stage wall / CPU / peak of each kernel set, side by side."""
    names = list(runs)
    print("| stage | " + " | ".join(f"{k} wall s | {k} CPU s | {k} peak MiB" for k in names)
          + (" | ratio |" if len(names) == 2 else " |"))
    print("|---" * (1 + 3 * len(names) + (len(names) == 2)) + "|")
    res = {k: runs[k]["resources"] for k in names}
    for st in [*STAGES, "total"]:
        cells = []
        for k in names:
            r = res[k]["total"] if st == "total" else res[k]["stages"].get(st)
            cells += ([f"{r['wall_s']:.1f}", f"{r['cpu_s']:.1f}", f"{r['peak_rss_mb']:.0f}"]
                      if r else ["", "", ""])
        ratio = ""
        if len(names) == 2:
            a = res[names[0]]["total" if st == "total" else "stages"]
            b = res[names[1]]["total" if st == "total" else "stages"]
            ra, rb = (a, b) if st == "total" else (a.get(st), b.get(st))
            if ra and rb and ra["wall_s"] > 0:
                ratio = f"{rb['wall_s'] / ra['wall_s']:.1f}x"
        print(f"| {st} | " + " | ".join(cells) + (f" | {ratio} |" if len(names) == 2 else " |"))


def suspects_xy(products: Path) -> np.ndarray:
    """Suspect centres (E, N) in the survey CRS, metres."""
    import geopandas as gpd

    g = gpd.read_file(products / "anomalies.gpkg", layer="suspects")
    c = g.geometry.centroid
    return np.column_stack([c.x, c.y]) if len(g) else np.zeros((0, 2))


def compare_anomalies(a: Path, b: Path, tol_m: float = 0.03) -> str:
    """How many suspects of ``a`` have one of ``b`` within ``tol_m``, and vice versa."""
    pa, pb = suspects_xy(a), suspects_xy(b)
    if not len(pa) or not len(pb):
        return f"{len(pa)} vs {len(pb)} suspects"
    d = np.hypot(pa[:, None, 0] - pb[None, :, 0], pa[:, None, 1] - pb[None, :, 1])
    ab = int(np.sum(d.min(axis=1) <= tol_m))
    ba = int(np.sum(d.min(axis=0) <= tol_m))
    return (f"{ab}/{len(pa)} suspects of the first run within {100 * tol_m:.0f} cm of one of "
            f"the second, {ba}/{len(pb)} the other way")


def score_line(survey: Path, products: Path) -> str:
    """Detection scores against the simulated truth."""
    from clearfast_gis.evaluation.truth import score_against_truth

    s = score_against_truth(survey, products)
    centre = float(np.sqrt(np.mean(np.square(s.centre_errors_m)))) if s.centre_errors_m \
        else float("nan")
    return (f"Pd {s.n_detected}/{s.n_mines}, FA {s.false_alarms_per_m2:.3f}/m2, "
            f"centre RMS {100 * centre:.1f} cm")


def workers_table(survey: Path, work: Path, workers: list[int], n_surveys: int,
                  n_scans: int) -> None:
    """Batch conversion of ``n_surveys`` subsets on a local Dask cluster of W workers."""
    from distributed import Client, LocalCluster

    from clearfast_gis.batch import run_batch
    from clearfast_gis.survey.subset import subset_survey

    part = subset(survey, n_scans)
    copies = []
    for i in range(n_surveys):
        out = work / "batch-in" / f"copy{i}"
        if not (out / "survey.json").exists():
            subset_survey(part, out, n_scans)
        copies.append(out)
    print(f"\n{n_surveys} surveys of {n_scans} scans, Dask LocalCluster, one Dask thread per "
          "worker, the cores' threads shared between the workers (CLEARFAST_THREADS)\n")
    print("| workers | wall s | speed-up |")
    print("|---|---|---|")
    base = None
    for w in workers:
        # the worker processes inherit the thread cap: the cores are shared between them
        os.environ["CLEARFAST_THREADS"] = str(max(1, (os.cpu_count() or 1) // w))
        with LocalCluster(n_workers=w, threads_per_worker=1, processes=True,
                          host="127.0.0.1", dashboard_address=None) as cluster, \
                Client(cluster):
            t0 = time.perf_counter()
            res = run_batch(copies, work / f"batch-out-{w}", scheduler=cluster.scheduler_address,
                            resume=False)
            wall = time.perf_counter() - t0
        ok = sum(r.status == "ok" for r in res)
        base = base or wall
        print(f"| {w} | {wall:.0f} ({ok}/{len(res)} ok) | {base / wall:.2f}x |")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--work", default="/tmp/clearfast-full")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--drift", action="store_true")
    ap.add_argument("--kernels", nargs="*", default=["fast", "reference"],
                    choices=["fast", "reference"])
    ap.add_argument("--scans", type=int, default=48, help="scans of the kernel comparison")
    ap.add_argument("--scaling", type=int, nargs="*", default=[])
    ap.add_argument("--workers", type=int, nargs="*", default=[])
    ap.add_argument("--batch", type=int, default=4)
    ap.add_argument("--batch-scans", type=int, default=4)
    args = ap.parse_args()
    work = Path(args.work)
    survey = simulated(work, args.seed, args.drift)
    part = subset(survey, args.scans)
    runs: dict[str, dict] = {}
    for k in args.kernels:
        runs[k] = process(part, part.parent / f"products-{part.name}-{k}", k)
    if runs:
        print(f"{part} ({n_frames(part)} frames), kernels side by side, load "
              f"{os.getloadavg()[0]:.1f} at the end\n")
        stage_table(runs)
        for k in runs:
            print(f"\n- {k}: child wall {runs[k]['_child_wall_s']:.0f} s; "
                  + score_line(part, part.parent / f"products-{part.name}-{k}"))
        if len(runs) == 2:
            a, b = (part.parent / f"products-{part.name}-{k}" for k in runs)
            print(f"- anomalies: {compare_anomalies(a, b)}")
    if args.scaling:
        print("\n| scans | frames | wall s | CPU s | peak MiB | ms per frame |")
        print("|---|---|---|---|---|---|")
        for n in args.scaling:
            sub = subset(survey, n)
            m = process(sub, sub.parent / f"products-{sub.name}-fast", "fast")
            tot, nf = m["resources"]["total"], n_frames(sub)
            print(f"| {n} | {nf} | {tot['wall_s']:.0f} | {tot['cpu_s']:.0f} | "
                  f"{tot['peak_rss_mb']:.0f} | {1e3 * tot['wall_s'] / nf:.1f} |")
    if args.workers:
        workers_table(survey, work, args.workers, args.batch, args.batch_scans)


if __name__ == "__main__":
    main()
