"""The chain on a simulated radiometric-camera survey (issue 20): simulate the demo as a camera
writes it (``--camera-format``), import it, process it, and compare with the truth.

    python benchmarks/camera_survey.py --format flir-rjpeg tlinear [--seed 0]

Prints one markdown row per format: import wall time, mosaic error against
``truth/apparent_temperature`` per scan (mean, RMS, 4x4-cell block RMS; median and worst over
the scans) and the truth score (detection, false alarms, centre and depth errors). Folders
are kept in ``--work`` (default ``/tmp/clearfast-bench-camera``) and reused when present.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

from clearfast_gis.cameras.survey_import import ImportSpec, import_survey
from clearfast_gis.cli.import_survey import read_layout
from clearfast_gis.evaluation.truth import score_against_truth
from clearfast_gis.pipeline import process_survey
from clearfast_gis.simulate import preset, simulate_survey
from clearfast_gis.simulate.camera_files import radiometric_camera_config, write_camera_folder

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from tests.pipeline.test_end_to_end import block_mean, truth_on_mosaic_grid


def run(fmt: str, seed: int, work: Path) -> str:
    folder, survey, products = (work / f"{fmt}-{seed}-{k}" for k in ("camera", "survey",
                                                                    "products"))
    if not (folder / "import.json").exists():
        res = simulate_survey(folder, radiometric_camera_config(preset("demo")), seed=seed,
                              overwrite=True)
        write_camera_folder(res.root, res.twin, fmt)
    t0 = time.perf_counter()
    if not survey.exists():
        import_survey(ImportSpec(**read_layout(folder)), survey)
    t_import = time.perf_counter() - t0
    if not (products / "products.json").exists():
        process_survey(survey, products)
    means, rms, blocks = [], [], []
    for scan in range(6):
        m, t = truth_on_mosaic_grid(folder, products, scan)
        ok = np.isfinite(m) & np.isfinite(t)
        err = m[ok] - t[ok]
        means.append(err.mean())
        rms.append(np.sqrt(np.mean(err**2)))
        mb, tb = (block_mean(np.where(ok, a, np.nan), 4) for a in (m, t))
        both = np.isfinite(mb) & np.isfinite(tb)
        blocks.append(np.sqrt(np.mean((mb[both] - tb[both]) ** 2)))
    s = score_against_truth(survey, products, truth=folder)
    depth = np.sqrt(np.mean(np.square(s.depth_errors_m))) * 100 if s.depth_errors_m else None
    return (f"| {fmt} seed {seed} | {t_import:.0f} s | {np.median(means):+.3f} / "
            f"{max(means, key=abs):+.3f} | {np.median(rms):.2f} / {max(rms):.2f} | "
            f"{np.median(blocks):.2f} / {max(blocks):.2f} | {s.n_detected}/{s.n_mines} | "
            f"{s.n_false_alarms} | {np.sqrt(np.mean(np.square(s.centre_errors_m))) * 100:.1f} cm"
            f" | {'n/a' if depth is None else f'{depth:.1f} cm'} |")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--format", nargs="+", default=["flir-rjpeg", "tlinear"])
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--work", type=Path, default=Path("/tmp/clearfast-bench-camera"))
    a = ap.parse_args()
    print("| survey | import | mosaic mean error K (median / worst) | RMS K | 4x4 blocks RMS K "
          "| detected | false alarms | centre RMS | depth RMS |")
    print("|---|---|---|---|---|---|---|---|---|")
    for fmt in a.format:
        print(run(fmt, a.seed, a.work), flush=True)


if __name__ == "__main__":
    main()
