"""The whole chain on a simulated ``trial`` or ``full`` survey: time, CPU and memory per stage.

Takes an existing survey folder (``--survey``, only read) or simulates the ``--preset`` once
(cached in ``--work``), then runs ``clearfast process`` in a child process per configuration
(so that each run's peak memory is its own; products and subsets go into ``--work``) and
prints markdown tables from the ``resources`` record of each ``products.json``:

- per stage, wall / CPU / peak RSS, for each kernel set of ``--kernels`` on the same survey in
  the same run (``fast`` and ``reference``), with the end-to-end ratio and a comparison of the
  anomalies the two produce (suspects matched within 3 cm, detection scores against truth);
- per stage, its floor (:func:`floors`): the input and output it cannot avoid (raw frames
  read, mosaics read and written) and the least work per pixel (one pass over every raw pixel
  for the mosaics, one disk erosion per image and polarity for the detector), and how far the
  stage is from it;
- with ``--scaling N ...``: the fast chain on the first N scans (``subset_survey``) of the
  survey and of each ``--also`` survey (another frame size), to show time and memory against
  the number of scans and the frame size;
- with ``--workers W ...``: ``--batch`` copies of a ``--batch-scans``-scan subset converted
  by ``run_batch`` on a local Dask cluster of W single-threaded worker processes.

    python benchmarks/full_survey.py [--preset trial|full] [--survey DIR]
        [--kernels fast reference] [--scans 48] [--reference-scans 12]
        [--scaling 6 12 24 48] [--also DIR ...] [--workers 1 2] [--drift]
        [--work /tmp/clearfast-full]

e.g. the ``full`` preset end to end with the reference kernels on its first 6 scans:
``python benchmarks/full_survey.py --preset full --survey /data/full0 --reference-scans 6``.
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

import numpy as np

STAGES = ("read_and_validate", "band_coregistration", "mosaics", "attitude_adjustment",
          "residuals_and_footprint", "detection", "characterisation", "products")


def simulated(work: Path, preset_name: str, seed: int, drift: bool) -> Path:
    """The cached survey folder of ``preset_name`` (simulated on first use)."""
    from clearfast_gis.simulate import preset, simulate_survey

    survey = work / f"{preset_name}-s{seed}{'-drift' if drift else ''}" / "survey"
    if not (survey / "survey.json").exists():
        t0 = time.perf_counter()
        simulate_survey(survey, preset(preset_name), seed=seed, drift=drift)
        print(f"simulated {survey} in {time.perf_counter() - t0:.0f} s", file=sys.stderr)
    return survey


def scan_count(survey: Path) -> int:
    """Scans of the frame table."""
    return len({line.split(",", 1)[0] for line in
                (survey / "frames.csv").read_text().splitlines()[1:]})


def subset(survey: Path, n_scans: int, work: Path) -> Path:
    """``survey`` itself for all its scans, else a cached subset folder in ``work`` (links to
    the survey's files: the survey folder is only read)."""
    from clearfast_gis.survey.subset import subset_survey

    if n_scans >= scan_count(survey):
        return survey
    out = work / "subsets" / f"{survey.resolve().parent.name}-{survey.name}-{n_scans}scans"
    if not (out / "survey.json").exists():
        subset_survey(survey, out, n_scans)
    return out


def products_dir(work: Path, survey: Path, kernels: str) -> Path:
    """Where the products of ``survey`` with ``kernels`` go (in ``work``)."""
    tag = survey.name if survey.name != "survey" else survey.resolve().parent.name
    return work / "products" / f"{tag}-{kernels}"


_RUNS: dict[tuple[str, str], dict] = {}


def process(survey: Path, products: Path, kernels: str) -> dict:
    """Run ``clearfast process`` from scratch in a child process (once per invocation of this
    script for the same survey and kernels); its products.json."""
    key = (str(survey.resolve()), kernels)
    if key in _RUNS:
        return _RUNS[key]
    cmd = [sys.executable, "-m", "clearfast_gis.cli.main", "process", str(survey), "-o",
           str(products), "--no-resume", "--progress", "none", "--kernels", kernels]
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, env=os.environ | {"PYTHONWARNINGS": "ignore"})
    wall = time.perf_counter() - t0
    manifest = json.loads((products / "products.json").read_text())
    manifest["_child_wall_s"] = wall
    _RUNS[key] = manifest
    return manifest


def n_frames(survey: Path) -> int:
    """Rows of the frame table (frames of every band)."""
    return len((survey / "frames.csv").read_text().splitlines()) - 1


class Clock:
    """Wall and CPU seconds (this process, all threads) of the calls timed through it."""

    def __init__(self) -> None:
        self.wall = self.cpu = 0.0

    def __call__(self, fn, times: int = 1) -> float:
        """Run ``fn()``, add its wall and CPU time (``times`` over); its wall time, s."""
        def cpu() -> float:
            ru = resource.getrusage(resource.RUSAGE_SELF)
            return ru.ru_utime + ru.ru_stime

        w0, c0 = time.perf_counter(), cpu()
        fn()
        wall, used = time.perf_counter() - w0, cpu() - c0
        self.wall += times * wall
        self.cpu += times * used
        return times * wall


def floors(survey: Path, products: Path) -> dict[str, tuple[float, float, str]]:
    """Per stage, the least wall and CPU time it could take on this machine (seconds) and what
    that least is, measured on ``survey`` and the mosaics of its run in ``products``.

    - raw frames read: every frame of every band copied out of its TIFF (the page cache as the
      chain's run left it);
    - one pass over every raw pixel: counts to float32 (the least a calibration does);
    - mosaics written: one scan's COG written again, times the scans, and every scan's
      decoded copy (raw float32, :func:`clearfast_gis.export.cog.keep_decoded`) written;
    - mosaics read: every scan's decoded copy read (on threads, as the stages after the
      mosaics read them: the chain never decodes the COGs it wrote);
    - one disk erosion and one dilation (D1) per image: the first step of the top-hat and of
      the bottom-hat, OpenCV, on threads.

    The mosaics stage's floor is the first three, the residuals' the mosaics read, the
    detector's the mosaics read and the erosions; the other stages have none measured.
    """
    import tempfile

    import cv2

    from clearfast_gis.detection.morphology import disk_footprint
    from clearfast_gis.detection.voting import disk_px
    from clearfast_gis.export.cog import read_mosaic, write_cog
    from clearfast_gis.parallel import serial_kernels, thread_map
    from clearfast_gis.pipeline.options import ProcessOptions
    from clearfast_gis.survey.model import read_survey

    sv = read_survey(survey)
    n_bands = len(sv.manifest["camera"]["bands"])
    pairs = [(int(s), b) for s in sorted(sv.scans) for b in range(n_bands)]
    nbytes = []

    def read_one(pair) -> None:
        nbytes.append(np.array(sv.read_scan(*pair)).nbytes)

    def read_and_pass(pair) -> None:
        raw = np.asarray(sv.read_scan(*pair))
        np.multiply(raw, np.float32(0.01), out=np.empty(raw.shape, np.float32))

    mosaic_files = sorted((products / "mosaics").glob("scan_*.tif"))
    raw, pixel_pass, write, keep, read, morph = (Clock() for _ in range(6))
    raw(lambda: thread_map(read_one, pairs))
    pixel_pass(lambda: thread_map(read_and_pass, pairs))
    mosaics = thread_map(read_mosaic, mosaic_files)
    first = mosaics[0]
    with tempfile.TemporaryDirectory() as tmp:
        write(lambda: write_cog(Path(tmp) / "scan.tif", first.bands_c, first.transform,
                                first.epsg, first.band_descriptions), times=len(mosaic_files))
        copies = [Path(tmp) / f"{k}.f32" for k in range(len(mosaics))]
        keep(lambda: [m.bands_c.tofile(c) for m, c in zip(mosaics, copies, strict=True)])
        read(lambda: thread_map(lambda c: np.fromfile(c, dtype=np.float32), copies))
    o = ProcessOptions()
    se = disk_footprint(disk_px(o.d1_m, abs(first.transform.a)))

    def hats(img: np.ndarray) -> None:
        cv2.erode(img, se)
        cv2.dilate(img, se)

    images = [band for m in mosaics for band in m.bands_c]
    with serial_kernels():
        morph(lambda: thread_map(hats, images))
    gb = sum(nbytes) / 1e9
    n = len(mosaic_files)
    what = f"raw frames read ({gb:.1f} GB, {gb / raw.wall:.1f} GB/s): {raw.wall:.1f} s"
    return {
        "raw_read": (raw.wall, raw.cpu, what),
        "mosaics": (pixel_pass.wall + write.wall + keep.wall,
                    pixel_pass.cpu + write.cpu + keep.cpu,
                    f"{what}; read + one pass over every pixel {pixel_pass.wall:.1f} s + "
                    f"{n} COGs written {write.wall:.1f} s + their decoded copies "
                    f"{keep.wall:.1f} s"),
        "residuals_and_footprint": (read.wall, read.cpu,
                                    f"{n} decoded mosaics read {read.wall:.1f} s"),
        "detection": (read.wall + morph.wall, read.cpu + morph.cpu,
                      f"{n} decoded mosaics read {read.wall:.1f} s + D1 erosion and dilation "
                      f"of {len(images)} images {morph.wall:.1f} s"),
    }

def stage_table(runs: dict[str, dict],
                floor: dict[str, tuple[float, float, str]] | None = None) -> None:
    """Per-stage wall / CPU / peak of each kernel set, side by side, and the floor of each
    stage (with the first run's wall and CPU time over it)."""
    names = list(runs)
    floor = floor or {}
    print("| stage | " + " | ".join(f"{k} wall s | {k} CPU s | {k} peak MiB" for k in names)
          + (" | ratio" if len(names) == 2 else "")
          + (" | floor wall s | floor CPU s | over floor (wall, CPU) |" if floor else " |"))
    print("|---" * (1 + 3 * len(names) + (len(names) == 2) + 3 * bool(floor)) + "|")
    res = {k: runs[k]["resources"] for k in names}
    for st in [*STAGES, "total"]:
        cells = []
        for k in names:
            r = res[k]["total"] if st == "total" else res[k]["stages"].get(st)
            cells += ([f"{r['wall_s']:.1f}", f"{r['cpu_s']:.1f}", f"{r['peak_rss_mb']:.0f}"]
                      if r else ["", "", ""])
        if len(names) == 2:
            a = res[names[0]]["total" if st == "total" else "stages"]
            b = res[names[1]]["total" if st == "total" else "stages"]
            ra, rb = (a, b) if st == "total" else (a.get(st), b.get(st))
            cells.append(f"{rb['wall_s'] / ra['wall_s']:.1f}x"
                         if ra and rb and ra["wall_s"] > 0 else "")
        if floor:
            fw, fc = ((sum(v[0] for k, v in floor.items() if k != "raw_read"),
                       sum(v[1] for k, v in floor.items() if k != "raw_read"))
                      if st == "total" else floor.get(st, (None, None))[:2])
            r = res[names[0]]["total"] if st == "total" else res[names[0]]["stages"].get(st)
            cells += ([f"{fw:.1f}", f"{fc:.1f}",
                       f"{r['wall_s'] / fw:.1f}x, {r['cpu_s'] / max(fc, 1e-3):.1f}x"]
                      if fw and r else ["", "", ""])
        print(f"| {st} | " + " | ".join(cells) + " |")
    for k, (_, _, what) in floor.items():
        print(f"- floor of {k}: {what}")


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

    part = subset(survey, n_scans, work)
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


def frame_size(survey: Path) -> str:
    """The camera's frame size, ``WxH``."""
    w, h = json.loads((survey / "survey.json").read_text())["camera"]["resolution"]
    return f"{w}x{h}"


def scaling_table(surveys: list[Path], scans: list[int], work: Path) -> None:
    """The fast chain on the first N scans of each survey: time and memory against the number
    of scans and the frame size."""
    print("\n| survey | frame | scans | frames | wall s | CPU s | peak MiB | detection peak MiB "
          "| ms per frame | CPU ns per raw pixel |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for survey in surveys:
        w, h = (int(v) for v in frame_size(survey).split("x"))
        for n in scans:
            sub = subset(survey, n, work)
            m = process(sub, products_dir(work, sub, "fast"), "fast")
            tot, nf = m["resources"]["total"], n_frames(sub)
            det = m["resources"]["stages"].get("detection", {}).get("peak_rss_mb", float("nan"))
            print(f"| {survey.name} | {w}x{h} | {n} | {nf} | "
                  f"{tot['wall_s']:.0f} | {tot['cpu_s']:.0f} | {tot['peak_rss_mb']:.0f} | "
                  f"{det:.0f} | {1e3 * tot['wall_s'] / nf:.1f} | "
                  f"{1e9 * tot['cpu_s'] / (nf * w * h):.0f} |")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--work", default="/tmp/clearfast-full",
                    help="products, subsets and simulated surveys")
    ap.add_argument("--preset", default="trial", choices=["trial", "full"])
    ap.add_argument("--survey", type=Path, help="an existing survey folder (only read)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--drift", action="store_true")
    ap.add_argument("--kernels", nargs="*", default=["fast", "reference"],
                    choices=["fast", "reference"])
    ap.add_argument("--scans", type=int, default=48, help="scans of the fast run")
    ap.add_argument("--reference-scans", type=int,
                    help="scans of the side-by-side kernel comparison (default --scans)")
    ap.add_argument("--no-floors", action="store_true", help="skip the floors")
    ap.add_argument("--scaling", type=int, nargs="*", default=[])
    ap.add_argument("--also", type=Path, nargs="*", default=[],
                    help="other survey folders (other frame sizes) for --scaling")
    ap.add_argument("--workers", type=int, nargs="*", default=[])
    ap.add_argument("--batch", type=int, default=4)
    ap.add_argument("--batch-scans", type=int, default=4)
    args = ap.parse_args()
    work = Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    survey = args.survey or simulated(work, args.preset, args.seed, args.drift)
    part = subset(survey, args.scans, work)
    ref_part = subset(survey, args.reference_scans or args.scans, work)
    runs: dict[str, dict] = {}
    if "fast" in args.kernels:
        runs["fast"] = process(part, products_dir(work, part, "fast"), "fast")
        floor = None if args.no_floors else floors(part, products_dir(work, part, "fast"))
        print(f"{part} ({frame_size(part)}, {n_frames(part)} frames), the fast kernels, load "
              f"{os.getloadavg()[0]:.1f} at the end\n")
        stage_table(runs, floor)
        print(f"- fast: child wall {runs['fast']['_child_wall_s']:.0f} s; "
              + score_line(part, products_dir(work, part, "fast")))
    if "reference" in args.kernels:
        side = {}
        for k in args.kernels:
            side[k] = runs[k] if k in runs and ref_part == part else \
                process(ref_part, products_dir(work, ref_part, k), k)
        print(f"\n{ref_part} ({frame_size(ref_part)}, {n_frames(ref_part)} frames), kernels "
              f"side by side, load {os.getloadavg()[0]:.1f} at the end\n")
        stage_table(side)
        for k in side:
            print(f"\n- {k}: child wall {side[k]['_child_wall_s']:.0f} s; "
                  + score_line(ref_part, products_dir(work, ref_part, k)))
        if len(side) == 2:
            a, b = (products_dir(work, ref_part, k) for k in side)
            print(f"- anomalies: {compare_anomalies(a, b)}")
    if args.scaling:
        scaling_table([survey, *args.also], args.scaling, work)
    if args.workers:
        workers_table(survey, work, args.workers, args.batch, args.batch_scans)


if __name__ == "__main__":
    main()
