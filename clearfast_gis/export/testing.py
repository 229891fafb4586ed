"""A small but realistic products folder made with the product writers, for tests and demos.

:func:`make_demo_products` writes what the pipeline writes, on a synthetic 20 m x 30 m site in
Cyprus (EPSG:32636): a few scan mosaics over a diurnal cycle with warm/cold discs for buried
mines and clutter, the suspects with their attributes and contrast curves, anomaly outlines,
markers, the footprint, ``products.json`` and the contrast-curve figures.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from affine import Affine

from clearfast_gis import __version__
from clearfast_gis.detection.features import FOUND_BY_SCANS
from clearfast_gis.export.cog import band_description, write_cog
from clearfast_gis.export.geopackage import write_geopackage
from clearfast_gis.export.layout import mosaic_name
from clearfast_gis.export.manifest import write_products_manifest
from clearfast_gis.export.styles import default_styles
from clearfast_gis.export.suspects import contrast_series_text, suspects_frame
from clearfast_gis.timeutil import format_utc, parse_utc

SITE_LAT_DEG, SITE_LON_DEG = 35.17, 33.36
EPSG = 32636
START_UTC = "2026-11-15T00:00:00Z"


@dataclass(frozen=True)
class DemoObject:
    """A synthetic object: offset from the site origin (m), size, thermal behaviour, inversion."""

    anomaly_id: str
    dx_m: float
    dy_m: float
    diameter_m: float
    amplitude_k: float  # daytime contrast; negative = cool by day
    class_cue: str
    status: str
    depth_m: float | None
    diffusivity_m2s: float | None
    fix_quality: int = 4


OBJECTS = (
    DemoObject("A001", 4.0, 6.0, 0.34, 2.2, "at_mine", "ok", 0.010, 1.0e-7),
    DemoObject("A002", 12.0, 9.0, 0.32, 0.9, "at_mine", "ok", 0.045, 1.1e-7),
    DemoObject("A003", 7.5, 15.0, 0.12, 1.4, "ap_mine", "ok", 0.020, 1.0e-7),
    DemoObject("A004", 15.0, 18.5, 0.11, 0.6, "ap_mine", "at_bound", 0.15, 1.0e-6, 5),
    DemoObject("A005", 5.0, 22.0, 0.22, -1.1, "clutter", "ok", 0.0, 1.4e-6),
    DemoObject("A006", 16.0, 25.0, 0.15, -0.3, "clutter", "weak_contrast", None, None),
    DemoObject("A007", 10.0, 3.5, 0.26, 0.8, "unknown", "not_characterised", None, None),
    DemoObject("A008", 3.0, 11.0, 0.18, 1.0, "unknown", "ok", 0.030, 4.0e-7),
)


@dataclass(frozen=True)
class DemoProducts:
    """What :func:`make_demo_products` wrote."""

    root: Path
    epsg: int
    scan_times_s: tuple[float, ...]
    n_suspects: int
    n_markers: int
    pixel_size_m: float


def _site_origin() -> tuple[float, float]:
    from pyproj import Transformer

    e, n = Transformer.from_crs(4326, EPSG, always_xy=True).transform(SITE_LON_DEG, SITE_LAT_DEG)
    return float(np.floor(e)), float(np.floor(n))


def _background_c(hour_utc: np.ndarray) -> np.ndarray:
    # local solar time ~ UTC + 2.2 h; surface peak about 13:00 local
    return 14.0 + 7.0 * np.cos(2 * np.pi * (hour_utc + 2.2 - 13.0) / 24.0)


def _object_contrast_k(obj: DemoObject, hour_utc: float) -> float:
    return obj.amplitude_k * np.cos(2 * np.pi * (hour_utc + 2.2 - 13.5) / 24.0)


def make_demo_products(root: str | os.PathLike, n_scans: int = 4, pixel_size_m: float = 0.05,
                       seed: int = 0, figures: bool = True) -> DemoProducts:
    """Write a demo products folder into ``root`` (created if missing).

    Parameters
    ----------
    root : path
        Products folder.
    n_scans : int
        Number of scan mosaics, evenly spread over 24 h from 2026-11-15T00:00Z.
    pixel_size_m : float
        Mosaic pixel size, metres (20 m x 30 m area).
    seed : int
        Noise seed; identical seeds give identical mosaics.
    figures : bool
        Also write the contrast-curve PNGs (``figures/contrast_<id>.png``, needs matplotlib).

    Returns
    -------
    DemoProducts
    """
    import geopandas as gpd
    import shapely
    from scipy.special import expit

    root = Path(root)
    rng = np.random.default_rng(seed)
    e0, n0 = _site_origin()
    width, height = round(20.0 / pixel_size_m), round(30.0 / pixel_size_m)
    x0, y0 = e0, n0 + 30.0
    transform = Affine(pixel_size_m, 0.0, x0, 0.0, -pixel_size_m, y0)
    cols, rows = np.meshgrid(np.arange(width), np.arange(height))
    xs = x0 + (cols + 0.5) * pixel_size_m
    ys = y0 - (rows + 0.5) * pixel_size_m
    # oblique view from a lift south of the area: a trapezoid, narrower near the lift
    footprint = shapely.Polygon([(e0 + 3.0, n0 + 0.5), (e0 + 17.0, n0 + 0.5),
                                 (e0 + 19.5, n0 + 29.5), (e0 + 0.5, n0 + 29.5)])
    inside = shapely.contains_xy(footprint, xs, ys)
    texture = 0.4 * np.sin(xs / 2.3) * np.cos(ys / 3.1)
    start_s = parse_utc(START_UTC)
    times_s = tuple(start_s + k * 86400.0 / n_scans for k in range(n_scans))
    descriptions = [band_description("LW1", 8.0, 9.2)]

    series = {obj.anomaly_id: [] for obj in OBJECTS}
    scans = []
    for k, t_s in enumerate(times_s):
        hour = (t_s - start_s) / 3600.0
        field_c = _background_c(np.array(hour)) + texture
        field_c = field_c + rng.normal(0.0, 0.05, size=field_c.shape)
        for obj in OBJECTS:
            r = np.hypot(xs - (e0 + obj.dx_m), ys - (n0 + obj.dy_m))
            disc = expit((obj.diameter_m / 2 - r) / (0.15 * pixel_size_m + 0.01))
            field_c = field_c + _object_contrast_k(obj, hour) * disc
        field_c = np.where(inside, field_c, np.nan).astype(np.float32)
        name = mosaic_name(k)
        write_cog(root / "mosaics" / name, field_c[np.newaxis], transform, EPSG, descriptions,
                  {"CLEARFAST_SCAN": str(k)}, scan_time_s=t_s)
        scans.append({"scan": k, "time_utc": format_utc(t_s, "seconds"), "file": f"mosaics/{name}"})
        for obj in OBJECTS:
            r = np.hypot(xs - (e0 + obj.dx_m), ys - (n0 + obj.dy_m))
            centre = field_c[r <= max(obj.diameter_m / 4, pixel_size_m)]
            ring = field_c[(r > obj.diameter_m) & (r < obj.diameter_m + 0.5)]
            series[obj.anomaly_id].append(float(np.nanmean(centre) - np.nanmean(ring)))

    records = []
    for obj in OBJECTS:
        contrast = np.array(series[obj.anomaly_id])
        day = float(contrast[len(contrast) // 2]) if len(contrast) > 1 else float(contrast[0])
        night = float(contrast[0])
        figure = f"figures/contrast_{obj.anomaly_id}.png" if figures else None
        records.append({
            "anomaly_id": obj.anomaly_id, "x": e0 + obj.dx_m, "y": n0 + obj.dy_m,
            "area_m2": float(np.pi * obj.diameter_m ** 2 / 4), "diameter_m": obj.diameter_m,
            "circularity": 0.9, "depth_m": obj.depth_m,
            "depth_sigma_m": None if obj.depth_m is None else 0.004 + 0.1 * obj.depth_m,
            "diffusivity_m2s": obj.diffusivity_m2s,
            "diffusivity_sigma_m2s": None if obj.diffusivity_m2s is None
            else 0.2 * obj.diffusivity_m2s,
            "status": obj.status, "polarity": "hot" if obj.amplitude_k > 0 else "cold",
            "class_cue": obj.class_cue,
            "cue_confidence": float(np.clip(0.4 + 0.25 * abs(obj.amplitude_k), 0.0, 0.99)),
            "n_scans": n_scans, "contrast_day_k": day, "contrast_night_k": night,
            "fix_quality": obj.fix_quality, "figure": figure,
            "contrast_series": contrast_series_text([s["time_utc"] for s in scans], contrast),
            "found_by": FOUND_BY_SCANS,
        })
        if figures:
            _contrast_figure(root / figure, [(t - start_s) / 3600.0 for t in times_s],
                             contrast, obj.anomaly_id)
    suspects = suspects_frame(records, EPSG)
    anomalies = gpd.GeoDataFrame(
        {"anomaly_id": [o.anomaly_id for o in OBJECTS],
         "polarity": ["hot" if o.amplitude_k > 0 else "cold" for o in OBJECTS],
         "area_m2": [float(np.pi * o.diameter_m ** 2 / 4) for o in OBJECTS]},
        geometry=[shapely.Point(e0 + o.dx_m, n0 + o.dy_m).buffer(o.diameter_m / 2, 16)
                  for o in OBJECTS], crs=EPSG)
    marker_xy = [(2.0, 1.5), (18.0, 1.5), (19.0, 28.5), (1.0, 28.5)]
    markers = gpd.GeoDataFrame(
        {"marker_id": [f"M{i + 1}" for i in range(len(marker_xy))],
         "description": ["surveyed reference stake"] * len(marker_xy)},
        geometry=[shapely.Point(e0 + dx, n0 + dy) for dx, dy in marker_xy], crs=EPSG)
    foot = gpd.GeoDataFrame({"scans": [n_scans]}, geometry=[footprint], crs=EPSG)
    layers = {"anomalies": anomalies, "suspects": suspects, "markers": markers,
              "footprint": foot}
    write_geopackage(root / "anomalies.gpkg", layers, default_styles(layers))
    write_products_manifest(root, {
        "survey_id": "demo-seed0" if seed == 0 else f"demo-seed{seed}",
        "created_utc": format_utc(times_s[-1] + 3600.0, "seconds"),
        "crs": {"epsg": EPSG},
        "time": {"start_utc": START_UTC, "end_utc": format_utc(start_s + 86400.0, "seconds")},
        "software": {"name": "clearfast-gis", "version": __version__},
        "bands": [{"name": "LW1", "lambda_min_um": 8.0, "lambda_max_um": 9.2}],
        "parameters": {"pixel_size_m": pixel_size_m, "seed": seed},
        "timings_s": {"demo_products": 0.0},
        "scans": scans,
        "products": {"anomalies": "anomalies.gpkg", "mosaics": "mosaics"},
    })
    return DemoProducts(root, EPSG, times_s, len(records), len(markers), pixel_size_m)


def _contrast_figure(path: Path, hours: list[float], contrast_k: np.ndarray, label: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from clearfast_gis.atomic import atomic_path

    fig, ax = plt.subplots(figsize=(3.2, 2.2), dpi=80)
    ax.plot(hours, contrast_k, "o-", color="#c0392b")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("hours since survey start (UTC)")
    ax.set_ylabel("contrast (K)")
    ax.set_title(label)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png")
    plt.close(fig)
