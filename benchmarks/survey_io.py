"""Speed of the survey readers at paper scale; prints a markdown table.

One scan of 261 frames of 640x512 uint16 (171 MB, the paper's camera), a 24 h GNSS log at 1 Hz
(86,400 GGA + RMC epochs), a 24 h 1-minute TOA5 log, a 12,672-row frames table, and
``validate_survey`` on a 2-scan survey. Run: ``.venv/bin/python benchmarks/survey_io.py``.
"""

from __future__ import annotations

import os
import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

from clearfast_gis.survey import (
    GnssLog,
    WeatherLog,
    read_frames_table,
    read_nmea,
    read_survey,
    read_toa5,
    tiff_info,
    validate_survey,
    write_frames_table,
    write_nmea,
    write_tiff_stack,
    write_toa5,
)
from clearfast_gis.survey.testing import make_minimal_survey


def _median_s(fn, repeat: int = 3) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def _drop_cache(path: Path) -> None:
    """Ask the kernel to drop the file from the page cache (no effect on tmpfs)."""
    fd = os.open(path, os.O_RDONLY)
    try:
        os.posix_fadvise(fd, 0, 0, os.POSIX_FADV_DONTNEED)
    finally:
        os.close(fd)


def main() -> None:
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        t0 = 1.79e9
        stack = np.random.default_rng(0).integers(0, 2**14, (261, 512, 640), dtype=np.uint16)
        mb = stack.nbytes / 1e6
        tif = root / "scan.tif"
        rows.append(("write_tiff_stack 261x512x640", _median_s(
            lambda: write_tiff_stack(tif, stack), 2), f"{mb:.0f} MB"))
        rows.append(("tiff_info (headers only)", _median_s(lambda: tiff_info(tif)), "261 pages"))

        def read_cold():
            _drop_cache(tif)
            from clearfast_gis.survey import read_tiff_stack
            np.asarray(read_tiff_stack(tif)).sum()

        def read_raw():
            _drop_cache(tif)
            np.fromfile(tif, np.uint16).sum()

        rows.append(("read_tiff_stack + sum all pixels",
                     _median_s(read_cold), f"{mb:.0f} MB"))
        rows.append(("np.fromfile + sum, same file (reference)",
                     _median_s(read_raw), f"{mb:.0f} MB"))

        n = 86_400
        log = GnssLog(t0 + np.arange(n, dtype=float), np.full(n, 35.17), np.full(n, 33.36),
                      np.full(n, 170.0), np.full(n, 4, np.int8), np.full(n, 14, np.int16),
                      np.full(n, 0.7))
        write_nmea(root / "g.nmea", log)
        rows.append(("read_nmea 24 h at 1 Hz", _median_s(lambda: read_nmea(root / "g.nmea"), 1),
                     f"{n} epochs, {2 * n} lines"))
        m = 1440
        w = WeatherLog(t0 + 60.0 * np.arange(m), *(np.ones(m) for _ in range(7)))
        write_toa5(root / "w.dat", w)
        rows.append(("read_toa5 24 h at 1 min", _median_s(lambda: read_toa5(root / "w.dat")),
                     f"{m} records"))
        k = 48 * 261
        write_frames_table(root / "frames.csv", {
            "scan": np.arange(k) // 261, "position": np.arange(k) % 261, "band": np.zeros(k, int),
            "time_s": t0 + np.arange(k) * 5.0, "pan_deg": np.zeros(k), "tilt_deg": np.zeros(k),
            "file": np.array([f"frames/scan_{s:03d}_b0.tif" for s in np.arange(k) // 261]),
            "page": np.arange(k) % 261})
        rows.append(("read_frames_table 48 x 261", _median_s(
            lambda: read_frames_table(root / "frames.csv")), f"{k} rows"))
        s = make_minimal_survey(root / "s", n_scans=2, n_positions=261, width=640, height=512,
                                gnss_step_s=1.0)
        rows.append(("validate_survey 2 scans x 261 frames 640x512", _median_s(
            lambda: validate_survey(s), 1), "includes 3001 s of 1 Hz NMEA"))
        sv = read_survey(s)
        rows.append(("Survey.read_scan (warm cache, memory map, sum)", _median_s(
            lambda: np.asarray(sv.read_scan(1, 0)).sum()), f"{mb:.0f} MB"))
    print("| operation | median time (s) | size |")
    print("|---|---:|---|")
    for name, t, size in rows:
        print(f"| {name} | {t:.3f} | {size} |")


if __name__ == "__main__":
    main()
