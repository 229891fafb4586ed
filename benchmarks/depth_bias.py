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
    python benchmarks/depth_bias.py SURVEY PRODUCTS --footprint [--also SURVEY PRODUCTS ...]
        [--band 2]
    python benchmarks/depth_bias.py SURVEY PRODUCTS --ideal [--scans 48]

``--ideal``: the forward model's own AP mine under the survey's weather and scans (depths
:data:`IDEAL_DEPTHS_M`), depth (diffusivity / truth) as the chain would invert it and with the
mine type over the footprint, without and with the ring.

``--footprint``: the chain's own measure instead, the mean over the half-maximum footprint of
the mine's RMS contrast (the pixels around the true position whose RMS deviation from the
ring over the scans exceeds half the peak's) minus the ring at 1.5-2.5 radii, inverted with
one more link of the model at a time (:data:`FOOTPRINT_VARIANTS`): an object of the
footprint's radius against the undisturbed surface (what the chain does), the nearest mine
type averaged over the footprint's disc, that against the ring's model mean (in the mine's
thermal halo), that through the mosaics' blur (none on the truth rasters), that scaled to the
apparent contrast (:mod:`clearfast_gis.thermal.apparent`). Pooled over the surveys: the mean
depth error per true depth and the median diffusivity ratio.
"""

from __future__ import annotations

import argparse

import numpy as np
import rasterio
from scipy import ndimage

from clearfast_gis.evaluation.truth import read_truth_objects
from clearfast_gis.minetypes import nearest_mine_type
from clearfast_gis.mosaic.blur import survey_blur_sigma_m
from clearfast_gis.pipeline.inputs import open_context
from clearfast_gis.survey import read_soil_log
from clearfast_gis.thermal import (
    build_site_table,
    fit_surface_parameters,
    forcing_from_weather,
    invert_anomaly,
)
from clearfast_gis.thermal.apparent import apparent_gain
from clearfast_gis.thermal.forward import simulate_background
from clearfast_gis.thermal.sitesoil import site_soil
from clearfast_gis.units import ZERO_CELSIUS_K

VARIANTS = (("thermocouple", 0.08, "disc"), ("thermocouple", 0.08, "axis"),
            ("thermocouple", 0.05, "axis"), ("background", 0.08, "axis"))
"""(surface terms from, table object height m, table centre); ``--quick``: the first two."""

RINGS = {"ring 1.5-2.5 r": (1.5, 2.5, 0.0), "ring beyond halo": (1.0, 1.0, 0.25)}


def load_stack(folder, scans, truth: bool, band: int = 1) -> tuple[np.ndarray, object]:
    """Rasters of ``band`` (1-based; N, H, W) in degrees C and their transform."""
    out = []
    for s in scans:
        p = (f"{folder}/truth/apparent_temperature/scan_{s:03d}.tif" if truth
             else f"{folder}/mosaics/scan_{s:03d}.tif")
        with rasterio.open(p) as ds:
            out.append(ds.read(band).astype(float))
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


def half_max_disc(st: np.ndarray, d: np.ndarray, r: float) -> np.ndarray:
    """The half-maximum footprint (bool, H x W) around a mine: pixels within 2 radii whose RMS
    deviation from the 1.5-2.5 radii ring exceeds half the 95th percentile over the disc,
    connected to the disc's strongest pixel."""
    ring = (d >= 1.5 * r) & (d <= 2.5 * r)
    near = d <= 2.0 * r
    dev = np.array([im[near] - np.nanmean(im[ring]) for im in st])
    amp = np.full(d.shape, np.nan)
    amp[near] = np.sqrt(np.nanmean(dev**2, axis=0))
    inside = near & (d <= r)
    peak = np.nanpercentile(amp[inside], 95)
    lab, _ = ndimage.label(np.nan_to_num(amp, nan=0.0) >= 0.5 * peak)
    seed = np.unravel_index(int(np.nanargmax(np.where(inside, amp, -np.inf))), amp.shape)
    return lab == lab[seed] if lab[seed] else inside


FOOTPRINT_VARIANTS = ("footprint-sized object, undisturbed background (the chain)",
                      "mine type over the footprint", "the same, against the ring",
                      "the same, through the mosaics' blur", "the same, apparent contrast")
"""The ``--footprint`` variants, each adding one link to the one before."""


def footprint_case(survey, products, band: int) -> list[tuple]:
    """Rows (source, variant, true depth m, depth error m, diffusivity / truth) of one survey's
    mines at most 8.5 cm deep (``--footprint``)."""
    scans, times, forcing, log = survey_inputs(survey)
    mines = [m for m in read_truth_objects(survey)
             if m["kind"] in ("ap_mine", "at_mine") and m["depth_m"] <= 0.085]
    ctx, _, _ = open_context(survey)
    rows = []
    # the truth rasters hold the first band only
    for source in ("truth raster", "mosaics") if band == 1 else ("mosaics",):
        st, tr = load_stack(survey if source == "truth raster" else products, scans,
                            source == "truth raster", band)
        ps = tr.a
        r_idx, c_idx = np.mgrid[0:st.shape[1], 0:st.shape[2]]
        xc, yc = tr.c + (c_idx + 0.5) * ps, tr.f - (r_idx + 0.5) * ps
        background = np.array([np.nanmedian(im) for im in st])
        soil, _, _ = site_soil(log, forcing, times, background)
        lims = ctx.survey.bands[band - 1]
        gain = apparent_gain(background + ZERO_CELSIUS_K,
                             simulate_background(soil, forcing, times).surface_k,
                             lims.lambda_min_um, lims.lambda_max_um)
        tables: dict = {}
        for m in mines:
            r = 0.5 * m["diameter_m"]
            d = np.hypot(xc - m["x"], yc - m["y"])
            foot = half_max_disc(st, d, r)
            r_foot = float(np.sqrt(foot.sum() / np.pi) * ps)
            ring = (d >= 1.5 * r) & (d <= 2.5 * r)
            c = np.array([np.nanmean(im[foot]) for im in st]) + ZERO_CELSIUS_K
            g = np.array([np.nanmean(im[ring]) for im in st]) + ZERO_CELSIUS_K
            kind = nearest_mine_type(2 * r_foot)
            blur = 0.0 if source == "truth raster" else float(
                survey_blur_sigma_m(ctx, m["x"], m["y"], ps)[0])
            ring_m = (1.5 * r, 2.5 * r)
            for k, name in enumerate(FOOTPRINT_VARIANTS):
                radius, height = (r_foot, 0.08) if k == 0 else (kind.radius_m, kind.height_m)
                key = (round(radius, 3), height)
                if key not in tables:
                    tables[key] = build_site_table(forcing, soil, key[0], times,
                                                   height_m=height, centre="disc")
                inv = invert_anomaly(times, c, g, forcing, soil, key[0], noise_k=0.05,
                                     table=tables[key], over_m=r_foot if k else None,
                                     ring_m=ring_m if k >= 2 else None,
                                     blur_m=blur if k >= 3 else 0.0,
                                     gain=gain if k >= 4 else None)
                rows.append((source, name, m["depth_m"], inv.depth_m - m["depth_m"],
                             inv.alpha_m2s / m["diffusivity_m2s"]))
    return rows


IDEAL_DEPTHS_M = (0.0, 0.01, 0.02, 0.03, 0.05, 0.07)
"""Depths of the ``--ideal`` AP mine, m."""


def ideal_case(survey, n_scans: int = 0) -> None:
    """Print the ``--ideal`` table: an AP mine (M2A4, TNT) in the twin's site soil under the
    survey's logged weather, at its scan times, its exact radial profile from the forward
    model (no sensor, no mosaic), measured as the chain measures it (half-maximum footprint of
    the RMS contrast, minus the ring at 1.5-2.5 footprint radii or not) and inverted with the
    chain's soil (fitted to the survey's thermocouple). ``n_scans`` > 0: that many scans
    evenly over the survey's period instead of its own."""
    from clearfast_gis.minetypes import MINE_TYPES
    from clearfast_gis.simulate.surface import soils
    from clearfast_gis.thermal.forward import BuriedObject, simulate_object
    from clearfast_gis.thermal.materials import MATERIALS

    scans, times, forcing, log = survey_inputs(survey)
    if n_scans > 0:
        times = np.linspace(times.min(), times.max(), n_scans)
    soil, _, _ = site_soil(log, forcing, times, np.full(times.size, np.nan))
    ap, tnt = MINE_TYPES[0], MATERIALS["tnt"]
    radii = np.linspace(0.0, 0.3, 601)
    type_table = build_site_table(forcing, soil, ap.radius_m, times, height_m=ap.height_m,
                                  centre="disc")

    def mean(prof, a, b):
        sel = (radii >= a) & (radii <= b)
        w = radii[sel] + 1e-9
        return (prof[:, sel] * w).sum(axis=1) / w.sum()

    print("| true depth cm | footprint radius cm | footprint-sized object, no ring | "
          "mine type over the footprint, no ring | footprint-sized, ring not modelled | "
          "mine type, ring modelled |")
    print("|---|---|---|---|---|---|")
    for depth in IDEAL_DEPTHS_M:
        run = simulate_object(soils()["site"], BuriedObject(ap.radius_m, ap.height_m, depth,
                                                            tnt), forcing, times, radii_m=radii)
        prof = np.asarray(run.surface_k) - np.asarray(run.background_k)[:, None]
        amp = np.sqrt(np.mean(prof**2, axis=0))
        r_half = float(radii[np.nonzero(amp >= 0.5 * amp[0])[0].max()])
        ring = (1.5 * r_half, 2.5 * r_half)
        own = build_site_table(forcing, soil, r_half, times, height_m=ap.height_m,
                               centre="disc")
        cells = []
        for curve, table, radius, over, ring_m in (
                (mean(prof, 0, r_half), own, r_half, None, None),
                (mean(prof, 0, r_half), type_table, ap.radius_m, r_half, None),
                (mean(prof, 0, r_half) - mean(prof, *ring), own, r_half, None, None),
                (mean(prof, 0, r_half) - mean(prof, *ring), type_table, ap.radius_m, r_half,
                 ring)):
            inv = invert_anomaly(times, curve, np.zeros_like(curve), forcing, soil, radius,
                                 noise_k=0.02, table=table, over_m=over, ring_m=ring_m)
            cells.append(f"{100 * inv.depth_m:.2f} ({inv.alpha_m2s / tnt.alpha_m2s:.2f})")
        print(f"| {100 * depth:.0f} | {100 * r_half:.1f} | " + " | ".join(cells) + " |")


def footprint_table(rows: list[tuple]) -> None:
    """Print the pooled depth bias by true depth and variant."""
    print("| contrast from | model | true depth cm | n | depth bias cm | "
          "diffusivity / truth (median) |")
    print("|---|---|---|---|---|---|")
    for source in dict.fromkeys(r[0] for r in rows):
        for name in FOOTPRINT_VARIANTS:
            for depth in sorted({r[2] for r in rows}):
                sel = [r for r in rows if r[:3] == (source, name, depth)]
                if not sel:
                    continue
                err = np.array([r[3] for r in sel])
                print(f"| {source} | {name} | {100 * depth:.0f} | {len(sel)} | "
                      f"{100 * err.mean():+.2f} | {np.median([r[4] for r in sel]):.2f} |")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("survey")
    ap.add_argument("products")
    ap.add_argument("--quick", action="store_true", help="the chain's soil and height only")
    ap.add_argument("--footprint", action="store_true",
                    help="the chain's half-maximum footprint measure, before and now")
    ap.add_argument("--band", type=int, default=1,
                    help="band of the rasters (1-based; --footprint only; the truth rasters "
                    "hold band 1)")
    ap.add_argument("--also", nargs=2, action="append", default=[],
                    metavar=("SURVEY", "PRODUCTS"), help="more surveys, pooled (--footprint)")
    ap.add_argument("--ideal", action="store_true",
                    help="the forward model's own AP mine, measured as the chain measures it")
    ap.add_argument("--scans", type=int, default=0,
                    help="--ideal: this many scans evenly over the survey's period")
    args = ap.parse_args()
    if args.ideal:
        ideal_case(args.survey, args.scans)
        return
    if args.footprint:
        footprint_table([row for survey, products in [(args.survey, args.products)]
                         + args.also for row in footprint_case(survey, products, args.band)])
        return
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
