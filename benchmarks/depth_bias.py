"""Causes of the depth bias between the mosaics and the inversion, one link at a time.

For every mine of a processed simulated survey at most 8 cm deep, the contrast curve is
taken at the mine's *true* position (no detection or centroid error) from the truth
apparent-temperature rasters (``truth/apparent_temperature``, band 1, no sensor or mosaic) or
from the mosaics, in two ways: the value on the axis (cells within 0.2 radius) or the mean over
the disc; minus a ring at 1.5-2.5 radii (the chain's) or 25-35 cm beyond the rim (outside the
thermal halo). Each is inverted with the site soil's surface terms fitted to the shallowest
thermocouple (the chain) or to the mosaics' median background (before), and a table for an
8 cm or a 5 cm object. Prints the mean depth error for the mines at 0-4 cm per variant
(and at 6-8 cm where the survey has them). The table's contrast is the axis value or the
mean over the object's disc (``build_site_table(centre=...)``).

    python benchmarks/depth_bias.py SURVEY PRODUCTS [--quick]
"""

from __future__ import annotations

import argparse

import numpy as np
import rasterio

from clearfast_gis.evaluation.truth import read_truth_objects
from clearfast_gis.pipeline.inputs import open_context
from clearfast_gis.survey import read_soil_log
from clearfast_gis.thermal import (
    build_site_table,
    fit_surface_parameters,
    forcing_from_weather,
    invert_anomaly,
)
from clearfast_gis.thermal.sitesoil import site_soil
from clearfast_gis.units import ZERO_CELSIUS_K

VARIANTS = (("thermocouple", 0.08, "disc"), ("thermocouple", 0.08, "axis"),
            ("thermocouple", 0.05, "axis"), ("background", 0.08, "axis"))
"""(surface terms from, table object height m, table centre); ``--quick``: the first two."""

RINGS = {"ring 1.5-2.5 r": (1.5, 2.5, 0.0), "ring beyond halo": (1.0, 1.0, 0.25)}


def load_stack(folder, scans, truth: bool) -> tuple[np.ndarray, object]:
    """Band-1 rasters (N, H, W) in degrees C and their transform."""
    out = []
    for s in scans:
        p = (f"{folder}/truth/apparent_temperature/scan_{s:03d}.tif" if truth
             else f"{folder}/mosaics/scan_{s:03d}.tif")
        with rasterio.open(p) as ds:
            out.append(ds.read(1).astype(float))
            transform = ds.transform
    st = np.array(out)
    return (st - ZERO_CELSIUS_K if np.nanmedian(st) > 200 else st), transform


def survey_inputs(survey) -> tuple[list[int], np.ndarray, object, object]:
    """A survey's scans, their mean frame times (UTC epoch s), its forcing and soil log."""
    ctx, _, _ = open_context(survey)
    sv, fr = ctx.survey, ctx.survey.frames
    scans = list(sv.scans)
    times = np.array([fr.time_s[fr.scan == s].mean() for s in scans])
    return (scans, times, forcing_from_weather(ctx.weather),
            read_soil_log(sv.path("soil"), sv.label("soil")))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("survey")
    ap.add_argument("products")
    ap.add_argument("--quick", action="store_true", help="the chain's soil and height only")
    args = ap.parse_args()
    scans, times, forcing, log = survey_inputs(args.survey)
    mines = [m for m in read_truth_objects(args.survey)
             if m["kind"] in ("ap_mine", "at_mine") and m["depth_m"] <= 0.085]
    rows = []
    for source in ("truth raster", "mosaics"):
        st, tr = load_stack(args.survey if source == "truth raster" else args.products, scans,
                            source == "truth raster")
        ps = tr.a
        r_idx, c_idx = np.mgrid[0:st.shape[1], 0:st.shape[2]]
        xc, yc = tr.c + (c_idx + 0.5) * ps, tr.f - (r_idx + 0.5) * ps
        background = np.array([np.nanmedian(im) for im in st])
        soil_tc, _, _ = site_soil(log, forcing, times, background)
        soil_bg, _ = fit_surface_parameters(soil_tc, forcing, times, background + ZERO_CELSIUS_K)
        soils = {"thermocouple": soil_tc, "background": soil_bg}
        for soil_name, height, table_centre in VARIANTS[:2] if args.quick else VARIANTS:
            soil = soils[soil_name]
            tables = {}
            for m in mines:
                r = 0.5 * m["diameter_m"]
                h = height if m["kind"] == "ap_mine" else max(height, 0.094)
                if (r, h) not in tables:
                    tables[r, h] = build_site_table(forcing, soil, r, times, height_m=h,
                                                    centre=table_centre)
                d = np.hypot(xc - m["x"], yc - m["y"])
                for ext, sel in (("axis", d <= max(0.75 * ps, 0.2 * r)), ("disc", d <= r)):
                    for ring_name, (a, b, extra) in RINGS.items():
                        ring = (d >= a * r + extra) & (d <= b * r + extra + (0.1 if extra
                                                                              else 0))
                        c = np.array([np.nanmean(im[sel]) for im in st]) + ZERO_CELSIUS_K
                        g = np.array([np.nanmean(im[ring]) for im in st]) + ZERO_CELSIUS_K
                        inv = invert_anomaly(times, c, g, forcing, soil, r, noise_k=0.05,
                                             table=tables[r, h])
                        rows.append((source, soil_name, height, table_centre, ext, ring_name,
                                     m["id"], m["depth_m"], inv.depth_m,
                                     inv.alpha_m2s / m["diffusivity_m2s"]))
    print("| contrast from | surface terms from | table height cm | table centre | centre | "
          "ring | depth bias 0-4 cm (cm) | MAE 0-4 cm (cm) | diffusivity / truth (median) | "
          "within 25 % | n | depth bias 6-8 cm (n) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    keys = list(dict.fromkeys(r[:6] for r in rows))
    for k in keys:
        sel = [r for r in rows if r[:6] == k and r[7] <= 0.045]
        deep = [r[8] - r[7] for r in rows if r[:6] == k and r[7] > 0.055]
        err = np.array([r[8] - r[7] for r in sel])
        ratio = np.array([r[9] for r in sel])
        print(f"| {k[0]} | {k[1]} | {100 * k[2]:.0f} | {k[3]} | {k[4]} | {k[5]} | "
              f"{100 * err.mean():+.2f} | {100 * np.abs(err).mean():.2f} | "
              f"{np.median(ratio):.2f} | {np.mean(np.abs(ratio - 1) <= 0.25):.2f} | {len(sel)} | "
              f"{100 * np.mean(deep) if deep else float('nan'):+.2f} ({len(deep)}) |")


if __name__ == "__main__":
    main()
