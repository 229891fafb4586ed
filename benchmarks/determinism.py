"""Deterministic products: the demo survey processed several ways, compared byte for byte.

Simulates the ``demo`` preset once (cached in ``--work``), then runs ``clearfast process`` in a
child process per configuration, one after the other:

- twice with the default thread count (``--no-resume``);
- once per ``--threads N`` (``CLEARFAST_THREADS=N``);
- once killed with SIGKILL as soon as the run state records the unit ``--kill-after``
  (default ``mosaics/scan_003``: in the mosaic stage), then started again (resume).

It prints a markdown table: wall and CPU time, suspects, and how many product files (sha256;
``products.json`` and ``report.html`` without their timings, as in the resume test) differ from
the first run's.

    python benchmarks/determinism.py [--work /tmp/clearfast-det] [--threads 1 4]
        [--kill-after mosaics/scan_003]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))  # the digest helpers of the tests (one definition)

from tests.product_digests import comparable_digests  # noqa: E402


def simulated(work: Path) -> Path:
    """The cached demo survey folder (simulated on first use)."""
    from clearfast_gis.simulate import preset, simulate_survey

    survey = work / "demo-s0"
    if not (survey / "survey.json").exists():
        simulate_survey(survey, preset("demo"), seed=0)
    return survey


def _command(survey: Path, products: Path, fresh: bool) -> list[str]:
    cmd = [sys.executable, "-m", "clearfast_gis.cli.main", "process", str(survey), "-o",
           str(products), "--progress", "none"]
    return cmd + (["--no-resume"] if fresh else [])


def _child_cpu_s() -> float:
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


def run(survey: Path, products: Path, threads: int | None) -> tuple[float, float]:
    """One uninterrupted run; (wall s, CPU s)."""
    env = dict(os.environ)
    if threads is not None:
        env["CLEARFAST_THREADS"] = str(threads)
    t0, c0 = time.perf_counter(), _child_cpu_s()
    subprocess.run(_command(survey, products, fresh=True), env=env, check=True,
                   stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0, _child_cpu_s() - c0


def killed_and_resumed(survey: Path, products: Path, unit: str) -> tuple[float, float]:
    """A run killed once ``unit`` is recorded, then resumed; (wall s, CPU s) of both parts."""
    t0, c0 = time.perf_counter(), _child_cpu_s()
    # not --no-resume: the restart must find the killed run's state under the same key
    proc = subprocess.Popen(_command(survey, products, fresh=False),
                            stdout=subprocess.DEVNULL)
    state = products / ".clearfast" / "state.json"
    while True:
        if proc.poll() is not None:
            raise SystemExit(f"the run ended before recording {unit}")
        try:
            if unit in json.loads(state.read_text())["units"]:
                break
        except (OSError, ValueError, KeyError):
            pass
        time.sleep(0.05)
    proc.kill()
    proc.wait()
    subprocess.run(_command(survey, products, fresh=False), check=True,
                   stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0, _child_cpu_s() - c0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--work", type=Path, default=Path("/tmp/clearfast-det"))
    ap.add_argument("--threads", type=int, nargs="*", default=[1, 4])
    ap.add_argument("--kill-after", default="mosaics/scan_003")
    args = ap.parse_args()
    survey = simulated(args.work)
    configs = [("run 1", None), ("run 2", None)] + [(f"{n} thread(s)", n) for n in args.threads]
    rows = []
    reference = None
    for name, threads in configs + [(f"killed after {args.kill_after}, resumed", "kill")]:
        products = args.work / name.replace(" ", "_").replace(",", "").replace("(s)", "")
        if products.exists():
            subprocess.run(["rm", "-rf", str(products)], check=True)
        if threads == "kill":
            wall, cpu = killed_and_resumed(survey, products, args.kill_after)
        else:
            wall, cpu = run(survey, products, threads)
        digests = comparable_digests(products)
        reference = reference or digests
        differ = sorted(k for k in reference.keys() | digests.keys()
                        if reference.get(k) != digests.get(k))
        n_suspects = _suspects(products)
        rows.append((name, wall, cpu, n_suspects, len(digests), differ))
        print(f"{name}: {wall:.1f} s, {len(differ)} file(s) differ", file=sys.stderr)
    print("| run | wall s | CPU s | suspects | product files | differ from run 1 |")
    print("|---|---:|---:|---:|---:|---|")
    for name, wall, cpu, n, files, differ in rows:
        print(f"| {name} | {wall:.1f} | {cpu:.1f} | {n} | {files} | "
              f"{len(differ)}{' (' + ', '.join(differ[:4]) + ')' if differ else ''} |")


def _suspects(products: Path) -> int:
    import pyogrio

    return int(pyogrio.read_info(products / "anomalies.gpkg", layer="suspects")["features"])


if __name__ == "__main__":
    main()
