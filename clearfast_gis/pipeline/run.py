"""``process_survey``: the whole chain with progress, checkpoints and resume."""

from __future__ import annotations

import dataclasses
import json
import math
import time
from pathlib import Path

import numpy as np

from clearfast_gis import __version__
from clearfast_gis.errors import InvalidInput
from clearfast_gis.export.cog import band_description, read_mosaic, write_cog
from clearfast_gis.export.manifest import (
    read_products_manifest,
    write_products_manifest,
)
from clearfast_gis.geometry.gnss import platform_track, smooth_static_track, utm_epsg_for
from clearfast_gis.geometry.projection import frame_footprint
from clearfast_gis.mosaic import build_scan_mosaic, mosaic_grid, temporal_residual
from clearfast_gis.mosaic.build import FrameCorrection
from clearfast_gis.pipeline.anomalies import (
    AnomalySet,
    characterise,
    detect_on_mosaics,
    site_soil,
    suspect_records,
)
from clearfast_gis.pipeline.frames import (
    SurveyContext,
    first_scan_band_frames,
    frame_pose,
    scan_frames,
)
from clearfast_gis.pipeline.options import ProcessOptions
from clearfast_gis.pipeline.products import write_anomaly_products
from clearfast_gis.pipeline.state import RunState
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.radiometry.stage import calibration_events, weather_at
from clearfast_gis.registration import ConformalTransform, estimate_band_offsets
from clearfast_gis.timeutil import format_utc

STATE_DIR = ".clearfast"


def mosaic_rel(scan: int) -> str:
    """Relative path of a scan's mosaic in the products folder."""
    return f"mosaics/scan_{scan:03d}.tif"


def _survey_epsg(survey, gnss) -> int:
    crs = survey.manifest.get("crs") or {}
    if crs.get("epsg"):
        return int(crs["epsg"])
    ok = gnss.fix_quality > 0
    if not np.any(ok):
        raise InvalidInput("no GNSS fix to choose the UTM zone", survey.label("gnss"))
    i = int(np.flatnonzero(ok)[0])
    return utm_epsg_for(float(gnss.lat_deg[i]), float(gnss.lon_deg[i]))


def _input_key(survey, options: ProcessOptions) -> str:
    """Identity of the inputs (manifest, frame table, logs) and of the mosaic parameters."""
    import hashlib

    h = hashlib.sha256()
    h.update(json.dumps(survey.manifest, sort_keys=True).encode())
    for key in ("frames", "blackbody_frames", "blackbody_log", "gnss", "weather", "soil"):
        p = survey.path(key)
        st = p.stat()
        h.update(f"{key}:{st.st_size}:{st.st_mtime_ns}".encode())
    h.update(options.mosaic_key().encode())
    h.update(__version__.encode())
    return h.hexdigest()[:20]


def _pixel_size(survey, options: ProcessOptions) -> float:
    if options.pixel_size_m:
        return float(options.pixel_size_m)
    res = survey.mission.get("ground_resolution_m") or {}
    lo, hi = res.get("across_min"), res.get("across_max")
    if lo and hi:
        return round(0.5 * (float(lo) + float(hi)), 3)
    return 0.02


def open_context(survey_path: str | Path, progress: Progress = NULL_PROGRESS):
    """Read everything the chain needs from a survey folder (after validation)."""
    from clearfast_gis.survey import read_nmea, read_survey, read_toa5, validate_survey

    report = validate_survey(survey_path)
    if not report.valid:
        first = report.problems[0].line()
        more = f" (and {len(report.problems) - 1} more problems: run clearfast validate)" \
            if len(report.problems) > 1 else ""
        raise InvalidInput(first + more)
    for w in report.warnings:
        progress.message(f"warning: {w.line()}")
    survey = read_survey(survey_path)
    gnss = read_nmea(survey.path("gnss"), fallback_date_s=survey.start_s)
    epsg = _survey_epsg(survey, gnss)
    track = smooth_static_track(platform_track(
        gnss, epsg, float(survey.manifest["site"]["ground_altitude_m"]),
        source=survey.label("gnss")))
    weather = read_toa5(survey.path("weather"))
    events = calibration_events(survey)
    ctx = SurveyContext(survey, survey.camera, track, events, weather,
                        [ConformalTransform.identity()] * len(survey.bands))
    return ctx, epsg, report


def _scan_order(scans: np.ndarray, reference: int) -> list[int]:
    scans = [int(s) for s in scans]
    if reference not in scans:
        raise InvalidInput(f"reference scan {reference} is not in the survey", field="scans")
    return [reference] + [s for s in scans if s != reference]


def _grid(ctx: SurveyContext, epsg: int, pixel_size_m: float, reference: int):
    survey = ctx.survey
    fr = survey.frames
    rows = survey.scan_rows(reference, 0)
    fps = [frame_footprint(ctx.camera, frame_pose(ctx, fr.time_s[i], fr.pan_deg[i],
                                                  fr.tilt_deg[i]), max_range_m=60.0)
           for i in rows]
    area = survey.mission.get("area")
    clip = None
    if area and len(area) == 4:
        xmin, ymin, xmax, ymax = (float(a) for a in area)
        margin = 1.0
        clip = (xmin - margin, ymin - margin, xmax + margin, ymax + margin)
        import shapely

        if not shapely.box(*clip).intersects(shapely.unary_union(fps)):
            clip = None
    return mosaic_grid(fps, pixel_size_m, epsg, clip_to=clip)


def _correction_dict(c: FrameCorrection) -> dict:
    return dataclasses.asdict(c) | {"metric": None if math.isnan(c.metric) else c.metric}


def _correction_from(d: dict) -> FrameCorrection:
    d = dict(d)
    d["metric"] = math.nan if d.get("metric") is None else d["metric"]
    return FrameCorrection(**d)


def _air_function(ctx: SurveyContext):
    label = ctx.survey.label("weather")
    return lambda t: weather_at(ctx.weather, t, source=label)


def _band_offsets(ctx: SurveyContext, state: RunState, reference: int, progress: Progress):
    rec = state.done("bands")
    n = len(ctx.survey.bands)
    if rec is not None:
        return [ConformalTransform(**t) for t in rec["offsets"]]
    if n == 1:
        offsets = [ConformalTransform.identity()]
    else:
        progress.start("band co-registration", 1)
        stacks = first_scan_band_frames(ctx, reference, _air_function(ctx))
        offsets = estimate_band_offsets(stacks)
        progress.advance()
        progress.close()
    state.finish("bands", {"offsets": [
        {k: (v if not (isinstance(v, float) and math.isnan(v)) else 0.0)
         for k, v in dataclasses.asdict(t).items()} for t in offsets]})
    return offsets


def process_survey(survey_path: str | Path, products: str | Path,
                   options: ProcessOptions | None = None, resume: bool = True,
                   progress: Progress = NULL_PROGRESS) -> dict:
    """Run the chain from a survey folder to a products folder.

    Parameters
    ----------
    survey_path : path
        Survey folder (``survey.json``).
    products : path
        Products folder (created).
    options : ProcessOptions, optional
        Default parameters when omitted.
    resume : bool
        Keep finished, unchanged stages of an earlier run of the same inputs and parameters.
    progress : Progress

    Returns
    -------
    dict
        The products manifest (``products.json`` content).
    """
    options = ProcessOptions() if options is None else options
    t_all = time.perf_counter()
    products = Path(products)
    timings: dict[str, float] = {}
    t0 = time.perf_counter()
    ctx, epsg, report = open_context(survey_path, progress)
    survey = ctx.survey
    timings["read_and_validate"] = time.perf_counter() - t0
    key = _input_key(survey, options)
    state = RunState(products, key if resume else key + f"-fresh-{time.time_ns()}")
    if not resume:
        state.units = {}
    ref = int(options.reference_scan)
    order = _scan_order(survey.scans, ref)

    t0 = time.perf_counter()
    ctx.band_offsets = _band_offsets(ctx, state, ref, progress)
    timings["band_coregistration"] = time.perf_counter() - t0

    pixel = _pixel_size(survey, options)
    grid = _grid(ctx, epsg, pixel, ref)
    descriptions = [band_description(b.name, b.lambda_min_um, b.lambda_max_um)
                    for b in survey.bands]
    air_at = _air_function(ctx)
    t0 = time.perf_counter()
    n_pos = len(survey.positions)
    progress.start("mosaics", len(order) * n_pos)
    reference_values = None
    predicted = None
    scan_records: dict[int, dict] = {}
    for scan in order:
        unit = f"scan_{scan:03d}"
        rel = mosaic_rel(scan)
        rec = state.done(unit)
        if rec is not None:
            progress.advance(n_pos, scan=scan, resumed=True)
            corrections = {int(k): _correction_from(v) for k, v in rec["corrections"].items()}
        else:
            t_scan = time.perf_counter()
            frames = scan_frames(ctx, scan, air_at, atmosphere=options.atmosphere)
            m = build_scan_mosaic(frames, ctx.camera, grid, len(survey.bands),
                                  coregister=options.coregister, reference=reference_values,
                                  predicted=predicted, max_shift_m=options.max_shift_m,
                                  max_angle_deg=options.max_angle_deg,
                                  seam_balance=options.seam_balance, progress=progress)
            t_start, t_mean = _scan_time(survey, scan)
            residual = None
            if reference_values is not None and options.coregister:
                r = temporal_residual(reference_values[0], m.values[0])
                residual = None if math.isnan(r.shift_px) else r.shift_px
            write_cog(products / rel, m.values, grid.transform, epsg, descriptions,
                      tags={"CLEARFAST_SURVEY_ID": survey.manifest["survey_id"],
                            "CLEARFAST_SCAN": scan,
                            "CLEARFAST_SEAM_BALANCE": options.seam_balance},
                      scan_time_s=t_mean)
            np.save(_source_path(products, scan), m.source)
            corrections = m.corrections
            rec = {"scan": scan, "time_s": t_mean, "start_s": t_start,
                   "corrections": {str(k): _correction_dict(v) for k, v in corrections.items()},
                   "residual_px": residual, "seconds": time.perf_counter() - t_scan,
                   "seam_gains": {str(k): list(v) for k, v in m.seam_gains.items()}}
            state.finish(unit, rec, [rel])
        scan_records[scan] = rec
        if scan == ref:
            reference_values = read_mosaic(products / rel).bands_c
        predicted = corrections
    progress.close()
    timings["mosaics"] = time.perf_counter() - t0

    manifest = _anomaly_stage(ctx, survey, products, options, state, scan_records, epsg,
                              grid, report, timings, progress)
    timings["total"] = time.perf_counter() - t_all
    manifest["timings_s"] = {k: round(v, 3) for k, v in timings.items()}
    write_products_manifest(products, manifest)
    return manifest


def _source_path(products: Path, scan: int) -> Path:
    p = products / STATE_DIR / f"source_{scan:03d}.npy"
    p.parent.mkdir(parents=True, exist_ok=True)
    return p


def _scan_time(survey, scan: int) -> tuple[float, float]:
    t = survey.frames.time_s[survey.frames.scan == scan]
    return float(t.min()), float(t.mean())


def _load_stack(products: Path, scans: list[int]) -> tuple[np.ndarray, object]:
    mos = [read_mosaic(products / mosaic_rel(s)) for s in scans]
    return np.stack([m.bands_c for m in mos]).astype(np.float32), mos[0]


def _anomaly_stage(ctx, survey, products: Path, options: ProcessOptions, state: RunState,
                   scan_records: dict[int, dict], epsg: int, grid, report, timings: dict,
                   progress: Progress) -> dict:
    from clearfast_gis.survey import read_soil_log
    from clearfast_gis.thermal import forcing_from_weather

    scans = sorted(scan_records)
    times = np.array([scan_records[s]["time_s"] for s in scans])
    lon = float(survey.manifest["site"]["longitude_deg"])
    t0 = time.perf_counter()
    stack, first = _load_stack(products, scans)
    labels, feats = detect_on_mosaics(stack, times, first.transform, grid.pixel_size, lon,
                                      options.d1_m, options.d2_m, options.epsilon,
                                      options.level, options.gamma, options.max_anomalies,
                                      progress=progress)
    timings["detection"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    notes: list[str] = []
    inversions = {}
    alpha = sigma = math.nan
    if options.invert and feats:
        forcing = forcing_from_weather(ctx.weather)
        soil_log = read_soil_log(survey.path("soil"), survey.label("soil"))
        background = np.nanmedian(np.where(labels[None] > 0, np.nan, stack[:, 0]), axis=(1, 2))
        soil, alpha, sigma = site_soil(soil_log, forcing, times, background)
        inversions = characterise(feats, times, forcing, soil, progress=progress)
    elif not options.invert:
        notes.append("thermal characterisation switched off")
    timings["characterisation"] = time.perf_counter() - t0
    anomalies = AnomalySet(labels, feats, inversions, alpha, sigma, notes)
    fixq = _fix_quality_summary(ctx)
    code = survey.manifest["survey_id"]
    records = suspect_records(anomalies, times, lon, fixq["worst_during_frames"], code)
    t0 = time.perf_counter()
    manifest = write_anomaly_products(products, ctx, survey, anomalies, records, stack, times,
                                      first.transform, epsg, scan_records, report, options,
                                      fixq, timings)
    timings["products"] = time.perf_counter() - t0
    state.finish("anomalies", {"n": len(records), "key": options.detection_key()},
                 ["anomalies.gpkg"])
    return manifest


def _fix_quality_summary(ctx: SurveyContext) -> dict:
    t = ctx.survey.frames.time_s
    q = ctx.track.fix_quality_at(t)
    values, counts = np.unique(q, return_counts=True)
    return {"counts_at_frames": {str(int(v)): int(c) for v, c in zip(values, counts,
                                                                        strict=True)},
            "rtk_fixed_share": float(np.mean(q == 4)) if q.size else 0.0,
            "worst_during_frames": int(q.min()) if q.size else None,
            "degraded": bool(np.any(q != 4))}


def redetect(products: str | Path, options: ProcessOptions,
             progress: Progress = NULL_PROGRESS) -> dict:
    """Re-run detection and characterisation on existing mosaics with new parameters.

    The survey folder recorded in ``products.json`` supplies the logs.
    """
    products = Path(products)
    manifest = read_products_manifest(products)
    survey_path = manifest.get("survey_path")
    if not survey_path or not Path(survey_path).exists():
        raise InvalidInput("the survey folder recorded in products.json is not available",
                           products / "products.json", "survey_path")
    old = manifest.get("parameters", {})
    keep = {k: old[k] for k in ("pixel_size_m", "coregister", "max_shift_m", "max_angle_deg",
                                "seam_balance", "reference_scan", "atmosphere") if k in old}
    opts = dataclasses.replace(options, **keep)
    return process_survey(survey_path, products, opts, resume=True, progress=progress)


__all__ = ["format_utc", "process_survey", "redetect"]
