"""The anomaly stages of the chain (detection, characterisation, products); the anomaly set
they hand to the products writers is :class:`clearfast_gis.export.records.AnomalySet`."""

from __future__ import annotations

import json

import numpy as np

from clearfast_gis.detection.clutter import background_levels
from clearfast_gis.detection.deep import DEEP_DEPTHS_M
from clearfast_gis.detection.deep_depth import (
    PROFILE_DEPTHS_M,
    characterise_cores,
    with_core_depths,
)
from clearfast_gis.detection.likelihood import screen_and_rank
from clearfast_gis.detection.markers import markers_in_mosaics, split_markers
from clearfast_gis.detection.voting import detect_on_mosaics
from clearfast_gis.export.cog import mosaic_stack
from clearfast_gis.export.manifest import read_products_manifest
from clearfast_gis.export.products import write_anomaly_products
from clearfast_gis.export.records import AnomalySet, suspect_records
from clearfast_gis.mosaic.blur import survey_blur_sigma_m
from clearfast_gis.pipeline import stages
from clearfast_gis.pipeline.scanjob import scan_part
from clearfast_gis.pipeline.stages import Characterisation, Detection, RunContext
from clearfast_gis.pipeline.state import StageState
from clearfast_gis.thermal import forcing_from_weather
from clearfast_gis.thermal.apparent import apparent_gain, sky_band_radiance
from clearfast_gis.thermal.canopy import under_canopy
from clearfast_gis.thermal.daycontrast import (
    PEAK_LIFT_SIGMA,
    REFERENCE_RADIUS_M,
    SHOW_SNR,
    contrast_noise_k,
    day_contrast,
    reference_curves,
)
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.thermal.forward import simulate_background
from clearfast_gis.thermal.materials import Soil
from clearfast_gis.thermal.sitesoil import characterise, site_soil
from clearfast_gis.units import ZERO_CELSIUS_K


def _mosaics_digest(mosaics: StageState, scans: list[int]) -> str:
    """Checksum of the scan mosaics the anomalies come from (their run-state checksums)."""
    import hashlib

    files = [mosaics.files(scan_part(s)) for s in scans]
    return hashlib.sha256(json.dumps(files, sort_keys=True).encode()).hexdigest()[:20]


def _site(c: RunContext, times_s: np.ndarray, background_c: np.ndarray
          ) -> tuple[Forcing, Soil, float, float, float]:
    """The site's weather and soil (:func:`clearfast_gis.thermal.sitesoil.site_soil`) for scans
    at ``times_s`` (UTC epoch s) whose background is ``background_c`` (degrees C, (N,)):
    forcing, soil, soil diffusivity and its sigma (m2/s), grass cover (0-1)."""
    ctx, logs = c[stages.READ].ctx, c[stages.READ].report.logs
    forcing = forcing_from_weather(ctx.weather)
    canopy = float(ctx.survey.manifest["site"].get("vegetation_cover", 0.0))
    soil, alpha, sigma = site_soil(logs.soil, forcing, times_s, background_c, canopy)
    return forcing, soil, alpha, sigma, canopy


def detect(c: RunContext) -> Detection:
    """The ``detection`` stage: the detector on the stacked mosaics, known markers set apart;
    or the products of an earlier run, when they are up to date."""
    read, scan_records = c[stages.READ], c[stages.MOSAICS].scan_records
    scans = sorted(scan_records)
    digest = _mosaics_digest(c.stage_state(stages.MOSAICS), scans)
    done = c.stage_state(stages.PRODUCTS).done()
    if done is not None and done.get("mosaics") == digest \
            and (c.products / "products.json").exists():
        kept = read_products_manifest(c.products)
        if kept.get("parameters") == c.options.as_dict():
            c.progress.message("anomalies: up to date, kept")
            return Detection(kept=kept)
    o = c.options
    times = np.array([scan_records[s]["time_s"] for s in scans])
    lon = float(read.ctx.survey.manifest["site"]["longitude_deg"])
    stack = mosaic_stack(c.products, scans, decode_once=True)  # decoded by the footprint's
    deep_templates = None  # the deep search runs the thermal model: not without it
    if o.invert:
        background, _ = background_levels(stack, np.zeros(stack.shape, dtype=np.int32),
                                          read.grid.pixel_size, clutter=False)
        forcing, soil, _, _, canopy = _site(c, times, background)
        deep_templates = reference_curves(forcing, soil, times, DEEP_DEPTHS_M, canopy)
    else:
        c.progress.message("deep search off: it needs the thermal model (--no-invert)")
    labels, feats = detect_on_mosaics(stack, times, stack.transform, read.grid.pixel_size, lon,
                                      o.d1_m, o.d2_m, o.epsilon, o.level, o.gamma,
                                      o.max_anomalies, level_fraction=o.level_fraction,
                                      gamma_fraction=o.gamma_fraction, progress=c.progress,
                                      threshold_snr=o.threshold_snr,
                                      deep_templates_k=deep_templates,
                                      deep_radius_m=REFERENCE_RADIUS_M)
    ids, xy = list(read.marker_ids), read.marker_xy
    feats, _ = split_markers(feats, ids, xy)
    matches = markers_in_mosaics(stack, read.grid, ids, xy)
    return Detection(None, labels, feats, matches, stack, times, stack.transform, digest)


def characterise_suspects(c: RunContext) -> Characterisation:
    """The ``characterisation`` stage: the site's soil, then depth and diffusivity of every
    suspect with the thermal model; the deep cores' depth from their curve's shape
    (:mod:`clearfast_gis.detection.deep_depth`; the day's contrast noise is the general
    inversion's)."""
    det = c[stages.DETECTION]
    if det.kept is not None:
        return Characterisation()
    if not c.options.invert:
        return Characterisation(notes=("thermal characterisation switched off",))
    if not det.features:
        return Characterisation()
    ctx = c[stages.READ].ctx
    background, clutter_k = background_levels(det.stack, det.labels,
                                              c[stages.READ].grid.pixel_size)
    site = ctx.survey.manifest["site"]
    forcing, soil, alpha, sigma, canopy = _site(c, det.times_s, background)
    band = ctx.survey.bands[0]
    gain = apparent_gain(background + ZERO_CELSIUS_K,
                         simulate_background(soil, under_canopy(forcing, canopy),
                                             det.times_s).surface_k,
                         band.lambda_min_um, band.lambda_max_um,
                         sky_band_radiance(forcing, det.times_s, band.lambda_min_um,
                                           band.lambda_max_um))
    blur = survey_blur_sigma_m(ctx, [f.x for f in det.features], [f.y for f in det.features],
                               c[stages.READ].grid.pixel_size)
    inversions = characterise(det.features, det.times_s, forcing, soil, progress=c.progress,
                              canopy=canopy, gain=gain, blur_m=blur)
    noise = contrast_noise_k(inversions, ctx.survey, clutter_k)
    if any(f.core_contrast_k is not None for f in det.features):
        inversions = with_core_depths(inversions, characterise_cores(
            det.features, reference_curves(forcing, soil, det.times_s, PROFILE_DEPTHS_M,
                                           canopy)))
    o = c.options
    day = day_contrast(forcing, soil, det.times_s, noise, float(site["latitude_deg"]),
                       float(site["longitude_deg"]),
                       show_snr=(o.threshold_snr - PEAK_LIFT_SIGMA) if o.threshold_snr
                       else SHOW_SNR, show_share=o.level_fraction, canopy=canopy)
    return Characterisation(inversions, alpha, sigma, day=day)


def write_products(c: RunContext) -> dict:
    """The ``products`` stage: suspect records, anomalies.gpkg, report.html; returns the
    products manifest."""
    from clearfast_gis.geometry.gnss import fix_quality_summary

    det, char = c[stages.DETECTION], c[stages.CHARACTERISATION]
    if det.kept is not None:
        return det.kept
    read = c[stages.READ]
    survey = read.ctx.survey
    anomalies = AnomalySet(det.labels, det.features, char.inversions, char.soil_alpha_m2s,
                           char.soil_alpha_sigma_m2s, list(char.notes), det.markers, char.day)
    fixq = fix_quality_summary(read.ctx.track, read.ctx.survey.frames.time_s)
    lon = float(survey.manifest["site"]["longitude_deg"])
    records = screen_and_rank(suspect_records(anomalies, det.times_s, lon,
                                              fixq["worst_during_frames"],
                                              survey.manifest["survey_id"]),
                              len(det.times_s))
    timings = {k: v["wall_s"] for k, v in c.meter.stages.items()}
    manifest = write_anomaly_products(c.products, read.ctx, survey, anomalies, records,
                                      det.stack, c[stages.FOOTPRINT].valid, det.times_s,
                                      det.transform, read.epsg,
                                      c[stages.MOSAICS].scan_records, read.report, c.options,
                                      fixq, timings)
    c.stage_state(stages.PRODUCTS).finish("", {"n": len(records), "mosaics": det.mosaics_digest},
                                          ["anomalies.gpkg", "report.html"])
    return manifest
