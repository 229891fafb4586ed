"""Speed of the survey simulator: ``python benchmarks/simulate_speed.py [--trial-scans N]``.

Prints a markdown table: wall time per preset and stage, frames per second. The demo runs
three times (median); the trial runs ``--trial-scans`` scans (default 4) and is extrapolated
to its 48 scans from the per-scan rendering time (``--full-trial`` runs all 48); ``--full``
adds the 640x512 preset on the same number of scans.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from dataclasses import replace
from pathlib import Path

from clearfast_gis.simulate import preset, simulate_survey


def _run(cfg, root: Path) -> tuple[float, dict, int]:
    t0 = time.perf_counter()
    res = simulate_survey(root, cfg, seed=0, overwrite=True)
    return time.perf_counter() - t0, res.timings_s, res.n_frames


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--trial-scans", type=int, default=4)
    ap.add_argument("--full-trial", action="store_true")
    ap.add_argument("--full", action="store_true")
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        walls, last = [], None
        for k in range(3):
            wall, timings, n = _run(preset("demo"), Path(tmp) / f"demo{k}")
            walls.append(wall)
            last = (timings, n)
        rows.append(("demo", 6, last[1], statistics.median(walls), last[0], None))
        names = ["trial"] + (["full"] if args.full else [])
        for name in names:
            n_scans = 48 if args.full_trial else args.trial_scans
            cfg = replace(preset(name), n_scans=n_scans)
            wall, timings, n = _run(cfg, Path(tmp) / name)
            per_scan = (timings["render"] + timings["write"]) / n_scans
            est = None if n_scans == 48 else wall + per_scan * (48 - n_scans)
            rows.append((name, n_scans, n, wall, timings, est))
    print("| preset | scans run | frames | wall s | thermal s | scene s | render s | write s "
          "| frames/s (render) | 48-scan estimate s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, scans, n, wall, t, est in rows:
        print(f"| {name} | {scans} | {n} | {wall:.1f} | {t['thermal']:.1f} | {t['scene']:.1f} "
              f"| {t['render']:.1f} | {t['write']:.1f} | {n / t['render']:.0f} | "
              f"{'-' if est is None else f'{est:.0f}'} |")


if __name__ == "__main__":
    main()
