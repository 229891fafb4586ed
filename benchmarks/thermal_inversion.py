"""Accuracy of the depth / diffusivity inversion on synthetic surveys.

Truth: the twice-finer forward model; 48 scans over 24 h of the clear mid-November day at
35 N; 0.05 K noise on the centre series and 0.05/sqrt(20) K on the background ring (a mean
of ~20 pixels); TNT-filled AP (M2A4-sized, radius 5.2 cm) and AT (M6A2-sized, radius
16.85 cm) cylinders 5 and 8 cm tall at 0-15 cm in dry and in moist sand. Prints a markdown
table. Run: ``.venv/bin/python benchmarks/thermal_inversion.py`` (about 1-2 min).
"""

from __future__ import annotations

import time

import numpy as np

from clearfast_gis.thermal import (
    MATERIALS,
    BuriedObject,
    build_site_table,
    clear_sky_forcing,
    invert_anomaly,
    material_cue,
    simulate_object,
)
from clearfast_gis.timeutil import parse_utc

DEPTHS_CM = (0, 1, 2, 4, 6, 8, 10, 15)
OBJECTS = {"AP": (0.052, 0.05), "AT": (0.1685, 0.08)}
NOISE_K = 0.05
RING_PIXELS = 20


def main() -> None:
    day0 = parse_utc("2026-11-15T00:00:00Z")
    forcing = clear_sky_forcing(35.17, 33.36, day0, 86400.0)
    scans = day0 + 900.0 + 1800.0 * np.arange(48)
    noise_c = NOISE_K * np.sqrt(1 + 1 / RING_PIXELS)
    rng = np.random.default_rng(2026)
    tnt = MATERIALS["tnt"]
    rows, inv_times, table_times = [], [], []
    for soil_name in ("dry_sand", "moist_sand"):
        soil = MATERIALS[soil_name]
        for kind, (radius, height) in OBJECTS.items():
            tic = time.perf_counter()
            table = build_site_table(forcing, soil, radius, scans, height_m=height)
            table_times.append(time.perf_counter() - tic)
            for d_cm in DEPTHS_CM:
                obj = BuriedObject(radius, height, d_cm / 100, tnt)
                run = simulate_object(soil, obj, forcing, scans, refine=1)
                centre = run.surface_k[:, 0] + rng.normal(0, NOISE_K, scans.size)
                bg = run.background_k + rng.normal(0, NOISE_K / np.sqrt(RING_PIXELS), scans.size)
                tic = time.perf_counter()
                inv = invert_anomaly(scans, centre, bg, forcing, soil, radius, noise_c, table)
                inv_times.append(time.perf_counter() - tic)
                cue = material_cue(inv.alpha_m2s, inv.alpha_sigma_m2s)
                peak = np.max(np.abs(run.surface_k[:, 0] - run.background_k))
                rows.append((soil_name, kind, d_cm, peak, inv, cue["best"]))
    print("| soil | object | depth cm | peak contrast K | est. depth cm | depth err cm | "
          "sigma_d cm | alpha est / true | status | cue |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for soil_name, kind, d_cm, peak, inv, cue in rows:
        print(f"| {soil_name} | {kind} | {d_cm} | {peak:.2f} | {100 * inv.depth_m:.2f} | "
              f"{100 * inv.depth_m - d_cm:+.2f} | {100 * inv.depth_sigma_m:.2f} | "
              f"{inv.alpha_m2s / tnt.alpha_m2s:.2f} | {inv.status} | {cue} |")
    print()
    print(f"site table (150 forward runs): median {np.median(table_times):.1f} s; "
          f"inversion per anomaly: median {1000 * np.median(inv_times):.1f} ms, "
          f"max {1000 * np.max(inv_times):.1f} ms")


if __name__ == "__main__":
    main()
