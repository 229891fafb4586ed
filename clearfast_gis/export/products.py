"""Writing the anomaly products: ``anomalies.gpkg``, ``report.html``, ``products.json``."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd

from clearfast_gis import __version__
from clearfast_gis.export.mine_action import mine_indications
from clearfast_gis.solar import mean_solar_hour
from clearfast_gis.timeutil import format_utc


def label_outlines(labels: np.ndarray, transform) -> dict[int, object]:
    """Outline polygon (survey CRS) of every labelled anomaly: id -> shapely geometry."""
    import rasterio.features
    import shapely
    from shapely.geometry import shape

    parts: dict[int, list] = {}
    mask = labels > 0
    for geom, value in rasterio.features.shapes(labels.astype(np.int32), mask=mask,
                                                transform=transform, connectivity=8):
        parts.setdefault(int(value), []).append(shape(geom))
    return {k: shapely.unary_union(v) for k, v in parts.items()}


def footprint_polygon(valid: np.ndarray, transform, simplify_m: float):
    """The union of cells with data as one (multi)polygon, simplified by ``simplify_m``."""
    import rasterio.features
    import shapely
    from shapely.geometry import shape

    polys = [shape(g) for g, v in rasterio.features.shapes(
        valid.astype(np.uint8), mask=valid, transform=transform) if v == 1]
    if not polys:
        return shapely.Polygon()
    return shapely.unary_union(polys).simplify(simplify_m)


def write_footprint_geojson(path: Path, valid: np.ndarray, transform, epsg: int,
                            survey_id: str) -> Path:
    """The mosaics' footprint (cells with data) as a GeoJSON polygon in the survey CRS."""
    import json

    import shapely

    from clearfast_gis.atomic import write_text

    geom = footprint_polygon(valid, transform, 2 * abs(transform.a))
    doc = {"type": "FeatureCollection", "name": "footprint",
           "crs": {"type": "name", "properties": {"name": f"urn:ogc:def:crs:EPSG::{epsg}"}},
           "features": [{"type": "Feature",
                         "properties": {"survey_id": survey_id, "area_m2": float(geom.area)},
                         "geometry": shapely.geometry.mapping(geom)}]}
    text = json.dumps(doc)
    if path.exists() and path.read_text() == text:
        return path  # unchanged: a resumed run leaves finished products untouched
    return write_text(path, text)


def _markers_frame(survey, epsg: int, matches):
    import geopandas as gpd

    from clearfast_gis.geometry.gnss import lonlat_to_crs
    from clearfast_gis.survey import read_markers

    crs = f"EPSG:{epsg}"
    if "markers" not in survey.manifest["files"]:
        return gpd.GeoDataFrame({"marker_id": [], "description": [], "found": [],
                                 "found_x": [], "found_y": [], "offset_m": []},
                                geometry=gpd.GeoSeries([], crs=crs), crs=crs)
    m = read_markers(survey.path("markers"), survey.label("markers"))
    x, y = lonlat_to_crs(np.asarray(m.lon_deg), np.asarray(m.lat_deg), epsg)
    found = {mm.marker_id: mm for mm in matches}
    ids = [str(i) for i in m.id]

    def col(attr):
        return [getattr(found[i], attr) if i in found else None for i in ids]

    return gpd.GeoDataFrame({"marker_id": ids,
                             "description": [str(d) for d in m.description],
                             "found": [i in found for i in ids],
                             "found_x": col("found_x"), "found_y": col("found_y"),
                             "offset_m": col("offset_m")},
                            geometry=gpd.points_from_xy(x, y), crs=crs)


def _marker_rms_m(matches) -> float | None:
    if not matches:
        return None
    return float(np.sqrt(np.mean([m.offset_m ** 2 for m in matches])))


def _marker_fact(matches) -> str:
    rms = _marker_rms_m(matches)
    return "none found" if rms is None else f"{len(matches)} ({100 * rms:.1f} cm)"


def _pick_day_night(times_s: np.ndarray, lon_deg: float) -> tuple[int, int]:
    """The scans nearest 13 h and 3 h mean solar time (the report's day and night maps)."""
    hour = mean_solar_hour(times_s, lon_deg)
    day = int(np.argmin(np.abs(hour - 13.0)))
    night = int(np.argmin(np.minimum(np.abs(hour - 3.0), 24 - np.abs(hour - 3.0))))
    return day, night


def _geopackage_and_overview(products: Path, survey, anomalies, records: list[dict], stack,
                             valid: np.ndarray, times_s: np.ndarray, transform, epsg: int
                             ) -> tuple[list[dict], dict, bytes]:
    """Write ``anomalies.gpkg``; return the ranked suspects, the expected operating curve and
    the report's overview figure (PNG)."""
    import geopandas as gpd

    from clearfast_gis.evaluation.operating import expected_operating_curve
    from clearfast_gis.export import default_styles, suspects_frame, write_geopackage
    from clearfast_gis.report.figures import mosaic_panel_png

    crs = f"EPSG:{epsg}"
    pixel = abs(transform.a)
    outlines = label_outlines(anomalies.labels, transform)
    every = suspects_frame(records, epsg, products / "anomalies.gpkg")
    ranked = sorted((r for r in records if r.get("set_aside_reason") is None),
                    key=lambda r: r["priority"])
    suspects = suspects_frame(ranked, epsg, products / "anomalies.gpkg")
    candidates = suspects_frame([r for r in records if r.get("set_aside_reason") is not None],
                                epsg, products / "anomalies.gpkg")
    ids = [f.id for f in anomalies.features]
    outline_geoms = [outlines.get(i) for i in ids]
    anomalies_layer = gpd.GeoDataFrame(
        every.drop(columns="geometry").reset_index(drop=True),
        geometry=gpd.GeoSeries(outline_geoms, crs=crs), crs=crs)
    footprint_m2 = float(valid.sum() * pixel * pixel)
    curve = expected_operating_curve(np.array([r["p_mine"] for r in ranked]), footprint_m2)
    footprint = gpd.GeoDataFrame(
        {"survey_id": [survey.manifest["survey_id"]],
         "area_m2": [footprint_m2],
         "n_scans": [int(stack.n_scans)]},
        geometry=gpd.GeoSeries([footprint_polygon(valid, transform, 2 * pixel)], crs=crs),
        crs=crs)
    layers = {"anomalies": anomalies_layer, "suspects": suspects, "candidates": candidates,
              "markers": _markers_frame(survey, epsg, anomalies.markers), "footprint": footprint}
    write_geopackage(products / "anomalies.gpkg", layers, default_styles(layers),
                     timestamp_s=float(survey.end_s))

    # the report's overview
    lon = float(survey.manifest["site"]["longitude_deg"])
    day, night = _pick_day_night(times_s, lon)
    # the overview draws the suspects (not the set-aside candidates) and labels only the mine
    # indications, as the planner's map does, so that labels never bury the map
    shown = [(rec, geom) for rec, geom in zip(records, outline_geoms, strict=True)
             if rec.get("set_aside_reason") is None and geom is not None and not geom.is_empty]
    indication = mine_indications(pd.DataFrame(
        {"p_mine": [rec.get("p_mine") for rec, _ in shown],
         "class_cue": [rec["class_cue"] for rec, _ in shown]}, dtype=object).infer_objects())
    outline_xy, labels_txt, cols = [], [], []
    for (rec, geom), is_mine in zip(shown, indication, strict=True):
        g = max(getattr(geom, "geoms", [geom]), key=lambda p: p.area)
        outline_xy.append(np.asarray(g.exterior.coords))
        labels_txt.append(rec["anomaly_id"].rsplit("-", 1)[-1] if is_mine else "")
        cols.append("#e31a1c" if is_mine else
                    "#969696" if rec["class_cue"] == "clutter" else "#ff7f00")
    overview = mosaic_panel_png([stack.scan(day)[0], stack.scan(night)[0]],
                                [times_s[day], times_s[night]], transform, outline_xy,
                                labels_txt, cols, epsg)
    return ranked, curve, overview


def _curve_inputs(records: list[dict], anomalies, times_s: np.ndarray) -> list:
    """Each anomaly's contrast curve (with the model's fit when it has one), for the
    report's figures."""
    from clearfast_gis.report.figures import CurveInput

    out = []
    for rec, f in zip(records, anomalies.features, strict=True):
        inv = anomalies.inversions.get(f.id)
        c = np.asarray(f.contrast_k, dtype=float)
        c = c[:, 0] if c.ndim == 2 else c
        model = None if inv is None else np.asarray(inv.model_contrast_k)
        model_t = None
        if model is not None and model.shape == times_s.shape:
            model_t = times_s
        elif model is not None:
            model = None
        title = f"{rec['anomaly_id']}  {rec['class_cue']}  status {rec['status']}"
        out.append(CurveInput(times_s, c, model_t, model, title))
    return out


def write_anomaly_products(products: Path, ctx, survey, anomalies, records: list[dict],
                           stack, valid: np.ndarray, times_s: np.ndarray, transform,
                           epsg: int,
                           scan_records: dict[int, dict], report, options, fixq: dict,
                           timings: dict) -> dict:
    """Write the GeoPackage, the report and return the products manifest.

    Parameters
    ----------
    products : Path
        Products folder.
    anomalies : AnomalySet
    records : list of dict
        ``suspects`` attribute records, in the order of ``anomalies.features``.
    stack : ScanStack
        Mosaics, degrees C (the report's day and night scans read from it).
    valid : bool (H, W)
        Cells seen by at least one scan (band 0), the footprint.
    times_s : float64 (N,)
        Scan times.
    transform : affine.Affine
        Mosaic grid transform.
    epsg : int
    scan_records : dict
        Per-scan records of the run state (time, corrections, residual).
    report : ValidationReport
    options : ProcessOptions
    fixq : dict
        GNSS fix-quality summary.
    timings : dict
        Stage timings so far, seconds.
    """
    from clearfast_gis.detection.likelihood import likelihood_model_id
    from clearfast_gis.parallel import ProcessChunks
    from clearfast_gis.report import ReportData, write_report
    from clearfast_gis.report.figures import contrast_curves_png, operating_curve_png
    from clearfast_gis.report.html import diffusivity_text

    pixel = abs(transform.a)
    # the contrast curves are drawn in worker processes (matplotlib holds the GIL throughout)
    # while this one writes the GeoPackage and draws the overview
    with ProcessChunks(contrast_curves_png, _curve_inputs(records, anomalies, times_s)
                       ) as drawing:
        ranked, curve, overview = _geopackage_and_overview(
            products, survey, anomalies, records, stack, valid, times_s, transform, epsg)
        curves = dict(zip((rec["anomaly_id"] for rec in records), drawing.result(),
                          strict=True))
    residuals = [r.get("residual_px") for r in scan_records.values()
                 if r.get("residual_px") is not None]
    applied = sum(1 for r in scan_records.values() for c in r["corrections"].values()
                  if c.get("applied"))
    total = sum(len(r["corrections"]) for r in scan_records.values())
    warnings = [w.line() for w in report.warnings]
    if fixq["degraded"]:
        warnings.append(
            f"RTK-DGPS not fixed (quality != 4) for {100 * (1 - fixq['rtk_fixed_share']):.1f} "
            "% of the frames: positions there are degraded")
    warnings.extend(anomalies.notes)
    day_fact = day_contrast_text(anomalies.day)
    if anomalies.day is not None and weak_day(anomalies.day):
        warnings.append(f"low thermal contrast: {weak_day_text(anomalies.day)}; {day_fact}")
    facts = [
        ("frames", str(len(survey.frames))), ("scans", str(stack.n_scans)),
        ("positions per scan", str(len(survey.positions))),
        ("bands", ", ".join(b.name for b in survey.bands)),
        ("mosaic pixel size", f"{pixel:.3f} m"),
        ("RTK-fixed share at frame times", f"{100 * fixq['rtk_fixed_share']:.1f} %"),
        ("frames co-registered (MI)", f"{applied} of {total}"),
        ("scan-to-reference residual (median / max)",
         f"{np.median(residuals):.2f} / {np.max(residuals):.2f} px" if residuals else "n/a"),
        ("known markers found (RMS offset)", _marker_fact(anomalies.markers)),
        ("seam balancing", "on (temperatures adjusted)" if options.seam_balance else "off"),
        ("soil diffusivity (thermocouples)",
         diffusivity_text(anomalies.soil_alpha_m2s, anomalies.soil_alpha_sigma_m2s) + " mm²/s"
         if math.isfinite(anomalies.soil_alpha_m2s) else "n/a"),
        ("thermal contrast of the day (model of the logged weather, 10 cm AP mine)", day_fact),
    ]
    data = ReportData(survey.manifest["survey_id"], survey.manifest["site"].get("name", ""),
                      epsg, float(times_s.min()), float(times_s.max()), ranked, overview,
                      curves, facts, warnings, dict(timings), options.as_dict(),
                      candidates=[r for r in records if r.get("set_aside_reason") is not None],
                      operating_curve=curve, operating_png=operating_curve_png(curve))
    write_report(products, data)

    manifest = base_manifest(survey, epsg, options, scan_records, fixq)
    manifest["warnings"] = warnings  # input problems processed through (gaps, missing frames)
    manifest["markers"] = {"found": len(anomalies.markers),
                           "rms_offset_m": _marker_rms_m(anomalies.markers)}
    if anomalies.day is not None:
        manifest["day_contrast"] = anomalies.day.as_dict()
    manifest["suspects"] = {"n_suspects": len(ranked), "n_candidates": len(records) - len(ranked),
                            "likelihood_model": likelihood_model_id(),
                            "operating_curve": curve}
    manifest["products"] = {"anomalies": "anomalies.gpkg", "report": "report.html",
                            "mosaics": "mosaics/", "footprint": "footprint.geojson"}
    return manifest


def weak_day(day) -> bool:
    """True when a mine 5 cm deep would not show on the day (its delivered contrast below the
    detector's cut in too many scans)."""
    return not (day.deepest_showing_m >= WEAK_DAY_DEPTH_M - 1e-9)


#: A day is dull when a 10 cm AP mine this deep would not show, m (the depth down to which
#: the project states its accuracy).
WEAK_DAY_DEPTH_M = 0.05


def weak_day_text(day) -> str:
    """What a dull day means for the map: the depth below which mines can be missed."""
    deep = day.deepest_showing_m
    if not math.isfinite(deep):
        return "even a mine at 1 cm may not show: an empty map here does not mean no mines"
    return (f"mines deeper than about {100 * deep:.0f} cm may not show: below that an empty "
            "map does not mean no mines")


def day_contrast_text(day) -> str:
    """One line on the day's contrast for the report (``n/a`` without characterisation)."""
    if day is None:
        return "n/a (not characterised)"
    peaks = ", ".join(f"{day.contrast_at(d):.2f} K at {100 * d:.0f} cm" for d in (0.01, 0.05, 0.10))
    deep = day.deepest_showing_m
    shows = (f"mines show down to about {100 * deep:.0f} cm" if math.isfinite(deep)
             else "not even a mine at 1 cm shows")
    sky = ("" if not math.isfinite(day.clear_sky_index)
           else f"; sun {100 * day.clear_sky_index:.0f} % of a clear sky")
    rain = f"; rain {day.rain_mm:.1f} mm" if day.rain_mm > 0 else ""
    return (f"modelled peak {peaks}, of which the mosaics keep about "
            f"{100 * day.delivered_fraction:.0f} %, against a noise of {day.noise_k:.2f} K: "
            f"{shows} ({day.show_snr:g} noise sigmas in {100 * day.show_share:.0f} % of the "
            f"scans, the detector's cut){sky}{rain}")


def base_manifest(survey, epsg: int, options, scan_records: dict[int, dict], fixq: dict
                  ) -> dict:
    """The products manifest common to every stage: inputs, parameters, scans, CRS.

    Each scan records its time, file, the residual misregistration against the reference
    scan (pixels) and that scan's number, the platform attitude fitted for it with the ties
    behind the fit, and how many frames an individual MI correction moved.
    """
    from clearfast_gis.export.manifest import sha256_file
    from clearfast_gis.radiometry.camera_check import camera_blackbody_check

    scans = [{"scan": int(s), "time_utc": format_utc(r["time_s"]),
              "file": f"mosaics/scan_{int(s):03d}.tif",
              "residual_px": r.get("residual_px"),
              "reference_scan": r.get("reference_scan"),
              "attitude": r.get("attitude"),
              "frames_corrected": sum(1 for c in r.get("corrections", {}).values()
                                      if c.get("applied"))}
             for s, r in sorted(scan_records.items())]
    inputs = {}
    root = Path(survey.root).resolve()  # survey.path() resolves; the root may be relative
    for key in ("survey", "mission", "frames", "blackbody_frames", "blackbody_log", "gnss",
                "weather", "soil"):
        if key != "survey" and key not in survey.manifest["files"]:
            continue  # no blackbodies with a radiometric camera
        p = root / "survey.json" if key == "survey" else survey.path(key)
        inputs[p.relative_to(root).as_posix()] = sha256_file(p)
    return {
        "survey_id": survey.manifest["survey_id"],
        "crs": {"epsg": int(epsg)},
        "time": {"start_utc": format_utc(float(survey.start_s)),
                 "end_utc": format_utc(float(survey.end_s))},
        "software": {"name": "clearfast-gis", "version": __version__},
        "survey_path": str(Path(survey.root).resolve()),
        "inputs": inputs,
        **({"camera_check": check} if (check := camera_blackbody_check(survey)) else {}),
        "parameters": options.as_dict(),
        "bands": [{"name": b.name, "lambda_min_um": b.lambda_min_um,
                   "lambda_max_um": b.lambda_max_um} for b in survey.bands],
        "scans": scans,
        "fix_quality": fixq,
    }
