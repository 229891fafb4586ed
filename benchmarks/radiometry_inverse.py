"""Speed and accuracy of the radiometry kernels on one 640x512 frame.

Prints a markdown table: median time over repeats and the largest error against the exact
inverse (Newton on the closed-form band integral) over 230-350 K.

    .venv/bin/python benchmarks/radiometry_inverse.py [--repeat 21] [--band 8 12]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from _timing import median_ms

from clearfast_gis.radiometry import (
    BandTable,
    CalibrationEvent,
    apparent_temperature_paper,
    band_radiance,
    paper_table,
    raw_to_apparent,
)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=21)
    ap.add_argument("--band", type=float, nargs=2, default=(8.0, 12.0))
    args = ap.parse_args()
    lo, hi = args.band
    t0 = time.perf_counter()
    table = BandTable(lo, hi)
    build_s = time.perf_counter() - t0
    rng = np.random.default_rng(0)
    t_true = rng.uniform(230.0, 350.0, (512, 640))
    rad64 = band_radiance(t_true, lo, hi)
    rad32 = rad64.astype(np.float32)
    exact = table.temperature_exact(rad32.astype(np.float64))
    t_paper, l_paper = paper_table(table)
    lut_l = table.inverse_radiance0 + table.inverse_step * np.arange(table.inverse_t_k.size)

    rows = []

    def add(name: str, fn, inverse: bool = True) -> None:
        ms = median_ms(fn, args.repeat)
        err = f"{1e3 * np.nanmax(np.abs(fn() - exact)):.4f}" if inverse else "-"
        rows.append((name, f"{ms:.2f}", err))

    add(f"fast inverse: uniform-in-radiance LUT ({table.inverse_t_k.size} nodes), numba",
        lambda: table.temperature(rad32))
    add("np.interp on the same LUT", lambda: np.interp(rad32, lut_l, table.inverse_t_k))
    add("paper: 0.1 K table + linear interpolation (np.interp)",
        lambda: apparent_temperature_paper(rad32, table))
    add("np.interp on the 0.1 K table, float32 out",
        lambda: np.interp(rad32, l_paper, t_paper).astype(np.float32))
    add("exact: Newton on the closed form", lambda: table.temperature_exact(rad32))
    add("forward: BandTable.radiance (cubic Hermite, numba)", lambda: table.radiance(t_true),
        inverse=False)
    add("forward: band_radiance (closed-form series, numpy)",
        lambda: band_radiance(t_true, lo, hi), inverse=False)
    raw = rng.integers(6000, 9000, (512, 640)).astype(np.uint16)
    ev = CalibrationEvent(0.0, 0, np.full((512, 640), 9000.0), np.full((512, 640), 7000.0),
                          300.0, 290.0)
    cal = ev.gain_offset(table)
    add("raw_to_apparent: counts -> Eq.1 -> Eq.4 -> Eq.5 (one frame)",
        lambda: raw_to_apparent(raw, cal, 0.96, 290.0, table), inverse=False)

    print(f"Band {lo:g}-{hi:g} um, 640x512 float32 radiances of 230-350 K, median of "
          f"{args.repeat}; BandTable build {build_s:.2f} s; LUT midpoint error bound "
          f"{1e3 * table.inverse_error_k:.4f} mK.\n")
    print("| operation | median ms | max error vs exact, mK |")
    print("|---|---:|---:|")
    for r in rows:
        print(f"| {r[0]} | {r[1]} | {r[2]} |")


if __name__ == "__main__":
    main()
