"""Batch conversion: Dask per-task overhead against the work of a survey and of a scan.

Prints a markdown table: the scheduler's round trip for an empty task (LocalCluster on
loopback, 2 worker processes), the duration of one survey task and of one scan mosaic (from
the run state), and the wall time of a batch of small surveys with 1 or 2 local processes and
on the 2-worker cluster.

    .venv/bin/python benchmarks/batch_dask.py [--surveys 4] [--scans 3]
"""

from __future__ import annotations

import argparse
import json
import statistics
import tempfile
import time
from pathlib import Path

from clearfast_gis.batch import run_batch
from clearfast_gis.pipeline import ProcessOptions
from clearfast_gis.survey.testing import make_minimal_survey


def _noop(x):
    return x


def task_overhead_s(client, n: int = 200) -> tuple[float, float]:
    """(median round trip of one empty task submitted alone, mean cost per task in a burst)."""
    trips = []
    for i in range(50):
        t0 = time.perf_counter()
        client.submit(_noop, i, pure=False).result()
        trips.append(time.perf_counter() - t0)
    t0 = time.perf_counter()
    client.gather(client.map(_noop, range(n), pure=False))
    return statistics.median(trips), (time.perf_counter() - t0) / n


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--surveys", type=int, default=4)
    ap.add_argument("--scans", type=int, default=3)
    args = ap.parse_args()
    from distributed import Client, LocalCluster

    opts = ProcessOptions(invert=False, max_anomalies=3)
    rows = []
    with tempfile.TemporaryDirectory() as d:
        root = Path(d)
        surveys = [make_minimal_survey(root / "in" / f"s{i}", n_scans=args.scans,
                                       n_positions=4, width=32, height=24, seed=i)
                   for i in range(args.surveys)]
        for label, kw in (("local, 1 process", {"workers": 1}),
                          ("local, 2 processes", {"workers": 2})):
            t0 = time.perf_counter()
            res = run_batch(surveys, root / label.replace(" ", ""), options=opts, **kw)
            rows.append((label, time.perf_counter() - t0, res))
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                          dashboard_address=None) as cluster, Client(cluster) as client:
            one, burst = task_overhead_s(client)
            t0 = time.perf_counter()
            res = run_batch(surveys, root / "dask", scheduler=cluster.scheduler_address,
                            options=opts)
            rows.append(("Dask, 2 workers", time.perf_counter() - t0, res))
        state = json.loads((root / "dask" / "s0" / ".clearfast" / "state.json").read_text())
        scan_s = [u["seconds"] for k, u in state["units"].items() if k.startswith("scan_")]
    survey_s = [r.seconds for _, _, res in rows for r in res]
    print(f"{args.surveys} surveys of {args.scans} scans x 4 positions, 32 x 24 pixels; "
          "2 cores shared with other work (noisy)\n")
    print("| quantity | value |")
    print("| --- | --- |")
    print(f"| empty Dask task, round trip (median of 50) | {1e3 * one:.1f} ms |")
    print(f"| empty Dask task, cost per task in a burst of 200 | {1e3 * burst:.2f} ms |")
    print(f"| one scan mosaic (median) | {statistics.median(scan_s):.2f} s |")
    print(f"| one survey task (median) | {statistics.median(survey_s):.1f} s |")
    for label, wall, res in rows:
        ok = sum(r.status == "ok" for r in res)
        print(f"| batch wall time, {label} | {wall:.1f} s ({ok}/{len(res)} ok) |")


if __name__ == "__main__":
    main()
