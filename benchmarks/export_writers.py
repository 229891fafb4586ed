"""Speed of the product writers (COG mosaics, GeoPackage, mine-action export).

Run: ``.venv/bin/python benchmarks/export_writers.py`` (prints a markdown table; medians of
``--repeat`` runs).
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

import numpy as np
from affine import Affine


def median_s(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def suspects_records(n: int, rng: np.random.Generator) -> list[dict]:
    cues = ["at_mine", "ap_mine", "clutter", "unknown"]
    return [{"anomaly_id": f"A{i:05d}", "x": 532780.0 + rng.uniform(0, 20),
             "y": 3891955.0 + rng.uniform(0, 30), "area_m2": 0.05, "diameter_m": 0.25,
             "circularity": 0.8, "depth_m": 0.03, "depth_sigma_m": 0.005,
             "diffusivity_m2s": 1e-7, "status": "ok", "polarity": "hot",
             "class_cue": cues[i % 4], "cue_confidence": 0.7, "n_scans": 48, "fix_quality": 4}
            for i in range(n)]


def main() -> None:
    import geopandas as gpd
    import shapely

    from clearfast_gis.export import (
        default_styles,
        export_mine_action,
        suspects_frame,
        write_cog,
        write_geopackage,
        write_products_manifest,
    )

    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for h, w in ((600, 400), (2000, 2000)):
            bands = rng.normal(15, 2, (1, h, w)).astype(np.float32)
            bands[:, : h // 5] = np.nan
            t = median_s(lambda b=bands: write_cog(
                tmp / "m.tif", b, Affine(0.05, 0, 532780, 0, -0.05, 3891985), 32636,
                ["LW1 8.0-9.2 um"], scan_time_s=1.79e9), args.repeat)
            rows.append((f"write_cog, 1 band {w}x{h} float32 + overviews", t))
        for n in (10, 1000):
            recs = suspects_records(n, rng)
            t = median_s(lambda r=recs: suspects_frame(r, 32636), args.repeat)
            rows.append((f"suspects_frame (schema validation), {n} suspects", t))
            frame = suspects_frame(recs, 32636)
            styles = {"suspects": default_styles()["suspects"]}
            t = median_s(lambda f=frame, s=styles: write_geopackage(tmp / "anomalies.gpkg",
                                                                  {"suspects": f}, s),
                         args.repeat)
            rows.append((f"write_geopackage + layer_styles, {n} suspects", t))
            write_products_manifest(tmp, {
                "survey_id": "bench", "crs": {"epsg": 32636},
                "time": {"start_utc": "2026-11-15T00:00:00Z", "end_utc": "2026-11-16T00:00:00Z"},
                "software": {"name": "clearfast-gis", "version": "0.1.0"}})
            # the export also needs the survey footprint (the surveyed-area record)
            footprint = gpd.GeoDataFrame(
                {"scans": [60]}, geometry=[shapely.box(532780, 3891965, 532800, 3891985)],
                crs=32636)
            write_geopackage(tmp / "anomalies.gpkg", {"suspects": frame, "footprint": footprint})
            t = median_s(lambda: export_mine_action(tmp, tmp / "ma", include_all=True),
                         args.repeat)
            rows.append((f"export_mine_action (GeoPackage + CSV + XLSX, all suspects as "
                         f"evidence, hazard proposals), {n} suspects", t))
    print("| operation | median |")
    print("|---|---|")
    for name, t in rows:
        print(f"| {name} | {t * 1000:.0f} ms |")


if __name__ == "__main__":
    main()
