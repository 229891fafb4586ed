"""``process_survey``: the whole chain with progress, checkpoints and resume."""

from __future__ import annotations

import dataclasses
import json
import math
import time
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path

import numpy as np

from clearfast_gis import __version__, kernels
from clearfast_gis.atomic import atomic_path
from clearfast_gis.attitude import ReferenceMosaic, reposed, reposed_in_time, scan_attitude
from clearfast_gis.detection.likelihood import screen_and_rank
from clearfast_gis.detection.markers import markers_in_mosaics, split_markers
from clearfast_gis.detection.voting import detect_on_mosaics
from clearfast_gis.errors import InvalidInput
from clearfast_gis.export.cog import band_description, read_mosaic, write_cog
from clearfast_gis.export.manifest import (
    read_products_manifest,
    write_products_manifest,
)
from clearfast_gis.export.records import suspect_records
from clearfast_gis.geometry.gnss import platform_track, smooth_static_track, utm_epsg_for
from clearfast_gis.geometry.projection import frame_footprint
from clearfast_gis.mosaic import build_scan_mosaic, mosaic_grid, temporal_residual
from clearfast_gis.mosaic.build import FrameCorrection
from clearfast_gis.parallel import serial_kernels, thread_imap, thread_map
from clearfast_gis.pipeline.adjustment import (
    adjust_survey_attitude,
    placement_attitude,
    stored_model,
)
from clearfast_gis.pipeline.anomalies import AnomalySet
from clearfast_gis.pipeline.frames import (
    SurveyContext,
    first_scan_band_frames,
    frame_pose,
    scan_frames,
)
from clearfast_gis.pipeline.options import MOSAIC_PARAMETERS, ProcessOptions
from clearfast_gis.pipeline.products import base_manifest as _base_manifest
from clearfast_gis.pipeline.products import write_anomaly_products, write_footprint_geojson
from clearfast_gis.pipeline.resources import StageMeter, cpu_seconds
from clearfast_gis.pipeline.state import STATE_DIR, RunState
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.radiometry.stage import calibration_events, weather_at
from clearfast_gis.registration import ConformalTransform, estimate_band_offsets
from clearfast_gis.thermal.sitesoil import characterise, site_soil
from clearfast_gis.timeutil import format_utc


def mosaic_rel(scan: int) -> str:
    """Relative path of a scan's mosaic in the products folder."""
    return f"mosaics/scan_{scan:03d}.tif"


def _survey_epsg(survey, gnss) -> int:
    crs = survey.manifest.get("crs") or {}
    if crs.get("epsg"):
        return int(crs["epsg"])
    ok = gnss.usable
    if not np.any(ok):
        raise InvalidInput("no GNSS fix to choose the UTM zone", survey.label("gnss"))
    i = int(np.flatnonzero(ok)[0])
    return utm_epsg_for(float(gnss.lat_deg[i]), float(gnss.lon_deg[i]))


def _input_key(survey, options: ProcessOptions, station_profile: str | Path | None = None
               ) -> str:
    """Identity of the inputs (manifest, frame table, logs, station profile) and of the mosaic
    parameters."""
    import hashlib

    h = hashlib.sha256()
    h.update(json.dumps(survey.manifest, sort_keys=True).encode())
    for key in ("frames", "blackbody_frames", "blackbody_log", "gnss", "weather", "soil"):
        p = survey.path(key)
        st = p.stat()
        h.update(f"{key}:{st.st_size}:{st.st_mtime_ns}".encode())
    if station_profile is not None:
        h.update(Path(station_profile).read_bytes())
    elif "station_profile" in survey.manifest["files"]:
        h.update(survey.path("station_profile").read_bytes())
    h.update(options.mosaic_key().encode())
    h.update(__version__.encode())
    return h.hexdigest()[:20]


MIN_DEFAULT_PIXEL_M = 0.02
"""Finest default mosaic cell, metres: five cells across the smallest AP mine (10.4 cm)."""


def _pixel_size(survey, options: ProcessOptions) -> float:
    """Mosaic cell size: the option, else the mission's mean across-track ground resolution,
    not finer than :data:`MIN_DEFAULT_PIXEL_M` (finer cells cost memory and time without
    helping the detection of mines; frames are low-pass filtered to the cell size)."""
    if options.pixel_size_m:
        return float(options.pixel_size_m)
    res = survey.mission.get("ground_resolution_m") or {}
    lo, hi = res.get("across_min"), res.get("across_max")
    if lo and hi:
        return max(MIN_DEFAULT_PIXEL_M, round(0.5 * (float(lo) + float(hi)), 3))
    return MIN_DEFAULT_PIXEL_M


def open_context(survey_path: str | Path, progress: Progress = NULL_PROGRESS,
                 station_profile: str | Path | None = None):
    """Read everything the chain needs from a survey folder (after validation);
    ``station_profile`` overrides the one ``survey.json`` names."""
    from clearfast_gis.survey import read_nmea, read_survey, read_toa5, validate_survey
    from clearfast_gis.survey.nmea import gnss_checksums
    from clearfast_gis.survey.station_profiles import read_station_profile

    report = validate_survey(survey_path, station_profile=station_profile)
    if not report.valid:
        first = report.problems[0].line()
        more = f" (and {len(report.problems) - 1} more problems: run clearfast validate)" \
            if len(report.problems) > 1 else ""
        raise InvalidInput(first + more)
    for w in report.warnings:
        progress.message(f"warning: {w.line()}")
    survey = read_survey(survey_path)
    gnss = read_nmea(survey.path("gnss"), fallback_date_s=survey.start_s,
                     checksums=gnss_checksums(survey.manifest))
    epsg = _survey_epsg(survey, gnss)
    track = smooth_static_track(platform_track(
        gnss, epsg, float(survey.manifest["site"]["ground_altitude_m"]),
        source=survey.label("gnss")))
    if station_profile is not None:
        survey.use_station_profile(read_station_profile(station_profile))
    weather = read_toa5(survey.path("weather"), survey.label("weather"),
                        survey.station_profile)
    events = calibration_events(survey)
    _check_blackbody_pairs(events, survey)
    ctx = SurveyContext(survey, survey.camera, track, events, weather,
                        [ConformalTransform.identity()] * len(survey.bands))
    return ctx, epsg, report


MIN_BLACKBODY_DIFFERENCE_K = 1.0
"""Blackbodies closer than this in temperature give no usable two-point calibration (the
heated one runs ~10 K above the ambient one), kelvin."""


def _check_blackbody_pairs(events, survey) -> None:
    """Refuse a degenerate blackbody pair (same temperature, or same counts everywhere)."""
    from clearfast_gis.radiometry.calibration import DEFAULT_MIN_CONTRAST_COUNTS

    for ev in events:
        when = format_utc(ev.time_s, "seconds")
        if not abs(ev.t_bb1_k - ev.t_bb2_k) >= MIN_BLACKBODY_DIFFERENCE_K:
            raise InvalidInput(
                f"degenerate blackbody pair at {when}: blackbodies 1 and 2 at "
                f"{ev.t_bb1_k - 273.15:.2f} and {ev.t_bb2_k - 273.15:.2f} C (they must differ "
                f"by >= {MIN_BLACKBODY_DIFFERENCE_K:g} K)", survey.label("blackbody_log"))
        contrast = float(np.nanmedian(np.abs(np.asarray(ev.bb1_mean, dtype=float)
                                             - np.asarray(ev.bb2_mean, dtype=float))))
        if not contrast >= DEFAULT_MIN_CONTRAST_COUNTS:
            raise InvalidInput(
                f"degenerate blackbody pair at {when} band {ev.band}: the images of "
                f"blackbodies 1 and 2 differ by {contrast:.1f} counts (median), below "
                f"{DEFAULT_MIN_CONTRAST_COUNTS:g}", survey.label("blackbody_frames"))


def _temporal_residuals(products: Path, scan_records: dict[int, dict], ref: int,
                        measure: bool) -> np.ndarray:
    """Residual misregistration of every scan's mosaic against the reference scan's (pixels),
    stored in ``scan_records[scan]["residual_px"]`` (None for the reference itself or when it
    cannot be measured). Each mosaic is read once.

    Returns
    -------
    bool (H, W)
        Cells seen by at least one scan (band 0), for the footprint.
    """
    reference = read_mosaic(products / mosaic_rel(ref)).bands_c[0] if measure else None

    def residual(scan: int) -> tuple[float | None, np.ndarray]:
        mosaic = read_mosaic(products / mosaic_rel(scan)).bands_c[0]
        if reference is None or scan == ref:
            return None, np.isfinite(mosaic)
        r = temporal_residual(reference, mosaic)
        return (None if math.isnan(r.shift_px) else r.shift_px), np.isfinite(mosaic)

    scans = sorted(scan_records)
    seen = None
    for scan, (value, finite) in zip(scans, thread_imap(residual, scans), strict=True):
        scan_records[scan]["residual_px"] = value
        scan_records[scan]["reference_scan"] = ref
        seen = finite if seen is None else seen | finite
    return seen


def _neighbour(scan: int, done: dict[int, tuple]) -> tuple:
    """Attitude of the processed scan nearest ``scan`` (zero attitude if none)."""
    if not done:
        return (0.0, 0.0, 0.0)
    return done[min(done, key=lambda s: abs(s - scan))]


def _reference_scan(survey, options: ProcessOptions) -> int:
    """The reference scan: the option, or the scan nearest local solar noon."""
    if options.reference_scan is not None:
        return int(options.reference_scan)
    from clearfast_gis.thermal import sun_times

    site = survey.manifest["site"]
    scans = sorted(int(s) for s in survey.scans)
    times = np.array([_scan_time(survey, s)[1] for s in scans])
    noon = np.array([sun_times(float(site["latitude_deg"]), float(site["longitude_deg"]),
                               float(t))[1] for t in times])
    return scans[int(np.argmin(np.abs(times - noon)))]


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


class _ScanJob:
    """Builds one scan's mosaic (attitude fit, projection, COG, run-state record)."""

    def __init__(self, ctx, grid, epsg, descriptions, air_at, marker_xy, options, products,
                 state, progress) -> None:
        self.ctx, self.grid, self.epsg = ctx, grid, epsg
        self.descriptions, self.air_at, self.marker_xy = descriptions, air_at, marker_xy
        self.options, self.products, self.state, self.progress = (options, products, state,
                                                                  progress)
        self._plan: list[int] = []
        self._pending: dict[int, Future] = {}
        self._pool = ThreadPoolExecutor(1, thread_name_prefix="clearfast-frames")
        self._writer = ThreadPoolExecutor(1, thread_name_prefix="clearfast-writer")
        self._writing: tuple | None = None
        self._last: tuple | None = None  # (scan, values, source) of the last scan built

    def plan(self, scans: list[int]) -> None:
        """The scans about to be built, in order: while one is registered and projected, the
        next one's frames are calibrated on a helper thread (the kernels release the GIL)."""
        self._plan = list(scans)

    def close(self) -> None:
        """Finish the scan being written, stop the helper threads (frames calibrated ahead
        are dropped)."""
        for f in self._pending.values():
            f.cancel()
        self._pending.clear()
        self._pool.shutdown(wait=True)
        try:
            self.flush()
        finally:
            self._writer.shutdown(wait=True)
            self._last = None

    def _calibrated(self, scan: int) -> list:
        """Apparent-temperature frames of ``scan``, computing the planned next scan's
        meanwhile."""
        pending = self._pending.pop(scan, None)
        frames = pending.result() if pending is not None else self._frames(scan)
        if scan in self._plan:
            k = self._plan.index(scan)
            if k + 1 < len(self._plan) and self._plan[k + 1] not in self._pending:
                nxt = self._plan[k + 1]
                self._pending[nxt] = self._pool.submit(self._frames, nxt)
        return frames

    def _frames(self, scan: int) -> list:
        """All apparent-temperature frames of ``scan`` (:func:`scan_frames`)."""
        return list(scan_frames(self.ctx, scan, self.air_at,
                                atmosphere=self.options.atmosphere))

    def frame_times(self, scan: int, frames) -> np.ndarray:
        """Time (UTC epoch s) of each frame of ``frames`` (band 0 of its position)."""
        fr = self.ctx.survey.frames
        rows = self.ctx.survey.scan_rows(scan, 0)
        by_pos = dict(zip(fr.position[rows].tolist(), fr.time_s[rows].tolist(), strict=True))
        return np.array([by_pos[f.index] for f in frames], dtype=float)

    def reference(self, scan: int, rec: dict, model) -> ReferenceMosaic:
        """A finished scan's mosaic, source map and placement, to register against."""
        survey, ctx = self.ctx.survey, self.ctx
        fr = survey.frames
        rows = survey.scan_rows(scan, 0)
        by_pos = {int(p): int(r) for p, r in zip(fr.position[rows], rows, strict=True)}

        def frame_at(position: int):
            r = by_pos[position]
            t = float(fr.time_s[r])
            return t, frame_pose(ctx, t, fr.pan_deg[r], fr.tilt_deg[r]).with_attitude(
                placement_attitude(rec, model, np.array([t]))[0])

        if self._last is not None and self._last[0] == scan:
            values, source = self._last[1], self._last[2]
        else:
            self.flush()
            values = read_mosaic(self.products / mosaic_rel(scan)).bands_c
            source = np.load(_source_path(self.products, scan))
        return ReferenceMosaic(scan, values, source, frame_at)

    def build(self, scan: int, references: list[ReferenceMosaic], init_attitude: tuple,
              refit_from: int | None = None, model=None, fitted: dict | None = None,
              adjusted: int = 1) -> dict:
        """Mosaic ``scan``, its attitude fitted against ``references`` (the neighbouring
        scan's mosaic, and the reference scan's so that errors do not accumulate) and the
        markers, or placed with the survey-wide attitude ``model`` (node times, nodes) of the
        adjustment (then ``fitted`` is the scan's earlier record, whose fit is kept, and
        ``adjusted`` the level recorded: 1 for the first adjustment, 2 for the refined one);
        write the COG and record the unit (on the writer thread, see :meth:`flush`)."""
        ctx, options, survey = self.ctx, self.options, self.ctx.survey
        t_scan = time.perf_counter()
        frames = self._calibrated(scan)
        times = self.frame_times(scan, frames)
        fit = None
        attitude = init_attitude
        if model is not None:
            placed = reposed_in_time(frames, times, *model)
        else:
            if options.coregister:
                fit = scan_attitude(frames, times, ctx.camera, self.grid, len(survey.bands),
                                    references, self.marker_xy, scan, attitude,
                                    search_m=options.search_m,
                                    n_samples=options.attitude_samples)
                attitude = fit.attitude_rpy_deg
            placed = reposed(frames, attitude)
        self.flush()  # the previous scan's files were written meanwhile: record its unit
        progress = self.progress if refit_from is None and model is None else NULL_PROGRESS
        m = build_scan_mosaic(placed, ctx.camera, self.grid, len(survey.bands),
                              coregister=options.coregister and options.frame_refine,
                              reference=references[0].values if references else None,
                              max_shift_m=options.max_shift_m,
                              max_angle_deg=options.max_angle_deg,
                              seam_balance=options.seam_balance, progress=progress)
        t_start, t_mean = _scan_time(survey, scan)
        rec = {"scan": scan, "time_s": t_mean, "start_s": t_start,
               "attitude": None if fit is None else fit.as_dict(),
               "ties": [] if fit is None else [t.as_list() for t in fit.ties],
               "corrections": {str(k): _correction_dict(v) for k, v in m.corrections.items()},
               "seconds": time.perf_counter() - t_scan, "refit_from": refit_from,
               "seam_gains": {str(k): list(v) for k, v in m.seam_gains.items()}}
        if model is not None and fitted is not None:
            rec.update({k: fitted.get(k) for k in ("attitude", "ties", "refit_from")})
            rec["adjusted"] = adjusted
        self._write(scan, m.values, m.source, t_mean, rec)
        return rec

    def _write(self, scan: int, values: np.ndarray, source: np.ndarray, t_mean: float,
               rec: dict) -> None:
        """Write the scan's COG and source map on the writer thread (while the next scan is
        computed); its run-state unit is recorded once the files are in place
        (:meth:`flush`)."""
        self.flush()
        rel = mosaic_rel(scan)
        survey = self.ctx.survey

        def write() -> None:
            write_cog(self.products / rel, values, self.grid.transform, self.epsg,
                      self.descriptions,
                      tags={"CLEARFAST_SURVEY_ID": survey.manifest["survey_id"],
                            "CLEARFAST_SCAN": scan,
                            "CLEARFAST_SEAM_BALANCE": self.options.seam_balance},
                      scan_time_s=t_mean)
            with atomic_path(_source_path(self.products, scan)) as tmp, \
                    open(tmp, "wb") as fh:
                np.save(fh, source)

        self._writing = (self._writer.submit(write), scan, rec, rel)
        self._last = (scan, values, source)

    def flush(self) -> None:
        """Wait for the scan being written and record its unit in the run state."""
        if self._writing is not None:
            future, scan, rec, rel = self._writing
            self._writing = None
            future.result()
            self.state.finish(f"scan_{scan:03d}", rec, [rel])


def _scan_mosaics(job: _ScanJob, order: list[int], ref: int
                  ) -> tuple[dict[int, dict], dict[int, tuple]]:
    """Every scan's mosaic in time order (each fitted against the previous scan's and the
    reference scan's), then the scans before the first marker-anchored one again, backwards;
    finished scans of an earlier run are kept.

    Returns
    -------
    scan_records : dict scan -> run-state record
    attitudes : dict scan -> (roll, pitch, yaw) degrees of the per-scan fit
    """
    state, progress, options = job.state, job.progress, job.options
    n_pos = len(job.ctx.survey.positions)
    progress.start("mosaics", len(order) * n_pos)
    attitudes: dict[int, tuple] = {}
    scan_records: dict[int, dict] = {}
    previous = reference = None
    model = stored_model(state)
    job.plan([s for s in order if state.done(f"scan_{s:03d}") is None])
    for scan in order:
        rec = state.done(f"scan_{scan:03d}")
        if rec is not None:
            progress.advance(n_pos, scan=scan, resumed=True)
        else:
            refs = [r for r in (previous, reference) if r is not None]
            rec = job.build(scan, refs, _neighbour(scan, attitudes))
        if rec.get("attitude"):
            attitudes[scan] = tuple(rec["attitude"]["attitude_rpy_deg"])
        scan_records[scan] = dict(rec)
        previous = job.reference(scan, rec, model)
        if scan == ref:
            reference = previous
    # the scans before the first one anchored by markers inherit its placement backwards
    anchored = [s for s in order if (scan_records[s].get("attitude") or {})
                .get("n_marker_ties", 0) >= 2]
    if options.coregister and anchored:
        back = list(range(order.index(anchored[0]) - 1, -1, -1))
        job.plan([order[k] for k in back
                  if scan_records[order[k]].get("refit_from") != order[k + 1]])
        for k in back:
            scan, nxt = order[k], order[k + 1]
            if scan_records[scan].get("refit_from") == nxt:
                continue
            refs = [job.reference(nxt, scan_records[nxt], None)]
            if reference is not None and nxt != ref:
                refs.append(reference)
            rec = job.build(scan, refs, attitudes[scan], refit_from=nxt)
            attitudes[scan] = tuple(rec["attitude"]["attitude_rpy_deg"])
            scan_records[scan] = dict(rec)
    progress.close()
    return scan_records, attitudes


def process_survey(survey_path: str | Path, products: str | Path,
                   options: ProcessOptions | None = None, resume: bool = True,
                   progress: Progress = NULL_PROGRESS, until: str = "products",
                   redo_anomalies: bool = False,
                   station_profile: str | Path | None = None) -> dict:
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
    until : {"products", "mosaics"}
        Stop after the scan mosaics (``clearfast mosaic``) or run the whole chain.
    station_profile : path, optional
        Station profile of the weather and soil logs, instead of the one ``survey.json``
        names (``files.station_profile``).
    redo_anomalies : bool
        Detect and characterise again even when the anomalies are up to date
        (``clearfast detect``).

    Returns
    -------
    dict
        The products manifest (``products.json`` content).
    """
    if until not in ("products", "mosaics"):
        raise ValueError(f"unknown stage {until!r}")
    options = ProcessOptions() if options is None else options
    with kernels.use(options.kernels), serial_kernels():
        return _process(survey_path, Path(products), options, resume, progress, until,
                        redo_anomalies, station_profile)


def _process(survey_path: str | Path, products: Path, options: ProcessOptions, resume: bool,
             progress: Progress, until: str, redo_anomalies: bool,
             station_profile: str | Path | None = None) -> dict:
    """:func:`process_survey` once the kernel set is chosen."""
    t_all, cpu_all = time.perf_counter(), cpu_seconds()
    meter = StageMeter()
    with meter.stage("read_and_validate"):
        ctx, epsg, report = open_context(survey_path, progress, station_profile)
    survey = ctx.survey
    key = _input_key(survey, options, station_profile)
    state = RunState(products, key if resume else key + f"-fresh-{time.time_ns()}")
    if not resume:
        state.units = {}
    ref = _reference_scan(survey, options)
    order = sorted(int(x) for x in survey.scans)

    with meter.stage("band_coregistration"):
        ctx.band_offsets = _band_offsets(ctx, state, ref, progress)

    pixel = _pixel_size(survey, options)
    grid = _grid(ctx, epsg, pixel, ref)
    descriptions = [band_description(b.name, b.lambda_min_um, b.lambda_max_um)
                    for b in survey.bands]
    air_at = _air_function(ctx)
    _, marker_xy = _survey_markers(survey, epsg)
    job = _ScanJob(ctx, grid, epsg, descriptions, air_at, marker_xy, options, products, state,
                   progress)
    adjustment = None
    try:
        with meter.stage("mosaics"):
            scan_records, attitudes = _scan_mosaics(job, order, ref)
        if options.coregister and options.adjust_attitude:
            with meter.stage("attitude_adjustment"):
                adjustment = adjust_survey_attitude(job, state, order, scan_records,
                                                    attitudes, progress, reference_scan=ref)
    finally:
        job.close()
    with meter.stage("residuals_and_footprint"):
        valid = _temporal_residuals(products, scan_records, ref, options.coregister)
        write_footprint_geojson(products / "footprint.geojson", valid, grid.transform, epsg,
                                survey.manifest["survey_id"])
    if until == "mosaics":
        manifest = _base_manifest(survey, epsg, options, scan_records,
                                  _fix_quality_summary(ctx))
        manifest["products"] = {"mosaics": "mosaics/", "footprint": "footprint.geojson"}
    else:
        if redo_anomalies:
            state.drop("anomalies")
        manifest = _anomaly_stage(ctx, survey, products, options, state, scan_records, epsg,
                                  grid, report, meter, progress)
    manifest["attitude_adjustment"] = adjustment
    total_wall = time.perf_counter() - t_all
    manifest["timings_s"] = {k: round(v["wall_s"], 3) for k, v in meter.stages.items()} \
        | {"total": round(total_wall, 3)}
    manifest["resources"] = meter.summary(total_wall, cpu_seconds() - cpu_all) \
        | {"kernels": options.kernels}
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
    """The scans' mosaics as one float32 (N, B, H, W) array (filled as they are read, on
    threads that decompress side by side, so that the stack is the only full copy in memory)
    and the first mosaic's record."""
    first = read_mosaic(products / mosaic_rel(scans[0]))
    stack = np.empty((len(scans), *first.bands_c.shape), dtype=np.float32)
    stack[0] = first.bands_c

    def fill(k: int) -> None:
        stack[k] = read_mosaic(products / mosaic_rel(scans[k])).bands_c

    thread_map(fill, range(1, len(scans)))
    return stack, first


def _mosaics_digest(state: RunState, scans: list[int]) -> str:
    """Checksum of the scan mosaics the anomalies come from (their run-state checksums)."""
    import hashlib

    files = [state.units.get(f"scan_{s:03d}", {}).get("files", {}) for s in scans]
    return hashlib.sha256(json.dumps(files, sort_keys=True).encode()).hexdigest()[:20]


def _anomaly_stage(ctx, survey, products: Path, options: ProcessOptions, state: RunState,
                   scan_records: dict[int, dict], epsg: int, grid, report, meter: StageMeter,
                   progress: Progress) -> dict:
    from clearfast_gis.survey import read_soil_log
    from clearfast_gis.thermal import forcing_from_weather

    done = state.done("anomalies")
    mosaics = _mosaics_digest(state, sorted(scan_records))
    if done is not None and done.get("key") == options.detection_key() \
            and done.get("mosaics") == mosaics and (products / "products.json").exists():
        kept = read_products_manifest(products)
        if kept.get("parameters") == options.as_dict():
            progress.message("anomalies: up to date, kept")
            return kept
    scans = sorted(scan_records)
    times = np.array([scan_records[s]["time_s"] for s in scans])
    lon = float(survey.manifest["site"]["longitude_deg"])
    with meter.stage("detection"):
        stack, first = _load_stack(products, scans)
        labels, feats = detect_on_mosaics(stack, times, first.transform, grid.pixel_size, lon,
                                          options.d1_m, options.d2_m, options.epsilon,
                                          options.level, options.gamma, options.max_anomalies,
                                          level_fraction=options.level_fraction,
                                          gamma_fraction=options.gamma_fraction,
                                          progress=progress)
        marker_ids, marker_xy = _survey_markers(survey, epsg)
        feats, _ = split_markers(feats, marker_ids, marker_xy)
        marker_matches = markers_in_mosaics(stack, grid, marker_ids, marker_xy)
    notes: list[str] = []
    inversions = {}
    alpha = sigma = math.nan
    with meter.stage("characterisation"):
        if options.invert and feats:
            forcing = forcing_from_weather(ctx.weather)
            soil_log = read_soil_log(survey.path("soil"), survey.label("soil"),
                                     survey.station_profile)
            outside = labels == 0
            background = np.array([np.nanmedian(img[outside]) for img in stack[:, 0]])
            soil, alpha, sigma = site_soil(soil_log, forcing, times, background)
            inversions = characterise(feats, times, forcing, soil, progress=progress)
        elif not options.invert:
            notes.append("thermal characterisation switched off")
    anomalies = AnomalySet(labels, feats, inversions, alpha, sigma, notes, marker_matches)
    fixq = _fix_quality_summary(ctx)
    code = survey.manifest["survey_id"]
    records = screen_and_rank(suspect_records(anomalies, times, lon, fixq["worst_during_frames"],
                                              code), len(times))
    with meter.stage("products"):
        timings = {k: v["wall_s"] for k, v in meter.stages.items()}
        manifest = write_anomaly_products(products, ctx, survey, anomalies, records, stack,
                                          times, first.transform, epsg, scan_records, report,
                                          options, fixq, timings)
    state.finish("anomalies", {"n": len(records), "key": options.detection_key(),
                               "mosaics": mosaics},
                 ["anomalies.gpkg", "report.html"])
    return manifest


def _survey_markers(survey, epsg: int) -> tuple[list[str], np.ndarray]:
    """Surveyed markers in the survey CRS: ids and (M, 2) positions."""
    from clearfast_gis.geometry.gnss import lonlat_to_crs
    from clearfast_gis.survey import read_markers

    if "markers" not in survey.manifest["files"]:
        return [], np.zeros((0, 2))
    m = read_markers(survey.path("markers"), survey.label("markers"))
    x, y = lonlat_to_crs(np.asarray(m.lon_deg, float), np.asarray(m.lat_deg, float), epsg)
    return [str(i) for i in m.id], np.column_stack([x, y])


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
    keep = {k: old[k] for k in MOSAIC_PARAMETERS if k in old}
    opts = dataclasses.replace(options, **keep)
    return process_survey(survey_path, products, opts, resume=True, progress=progress,
                          redo_anomalies=True)


__all__ = ["format_utc", "process_survey", "redetect"]
