"""The chain as one declared list of stages.

Each :class:`Stage` names itself, the :class:`~clearfast_gis.pipeline.options.ProcessOptions`
fields it depends on and the products it writes, and runs as ``run(context) -> record``, a
frozen dataclass kept in the :class:`RunContext` for the stages after it. One name per stage
serves the resource meter (``products.json`` ``timings_s`` and ``resources``), the run state
(its units are ``STAGE`` or ``STAGE/PART``), the progress (bar and JSON lines, with the
stage's human label beside it) and ``clearfast process --from/--until``.

A stage's key chains the key of the stage before it with its own options, so changing a
detector parameter keeps the mosaics, while changing a mosaic parameter redoes everything
after the mosaics (:meth:`RunContext.stage_state`).
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from clearfast_gis.pipeline.options import ProcessOptions
from clearfast_gis.pipeline.state import RunState, StageState
from clearfast_gis.progress import Progress
from clearfast_gis.resources import StageMeter


@dataclass
class RunContext:
    """What a run's stages share: the request, the records of the stages run so far, the run
    state (opened by the first stage) and the mosaic worker (closed by the chain's loop).

    Attributes
    ----------
    survey_path, products : Path
    options : ProcessOptions
    progress : Progress
    meter : StageMeter
    fresh : bool
        Ignore the records of an earlier run (``--no-resume``).
    station_profile : path or None
        Station profile of the weather and soil logs instead of the survey's own.
    records : dict
        Stage name -> the record its ``run`` returned.
    state : RunState or None
    job : ScanJob or None
    """

    survey_path: Path
    products: Path
    options: ProcessOptions
    progress: Progress
    meter: StageMeter
    fresh: bool = False
    station_profile: Path | None = None
    records: dict[str, object] = field(default_factory=dict)
    state: RunState | None = None
    job: object = None

    def __getitem__(self, name: str):
        """The record of stage ``name`` (it must have run)."""
        return self.records[name]

    def stage_key(self, name: str) -> str:
        """Key of stage ``name``: its options chained with the stages before it."""
        key = ""
        for stage in STAGES:
            key = _digest([key, {k: getattr(self.options, k) for k in stage.options}])
            if stage.name == name:
                return key
        raise KeyError(name)

    def stage_state(self, name: str) -> StageState:
        """The run-state units of stage ``name`` under its current key."""
        return self.state.stage(name, self.stage_key(name))


@dataclass(frozen=True)
class Stage:
    """One step of the chain.

    Attributes
    ----------
    name : str
        Used by the meter, the run state, the progress lines, ``--from`` and ``--until``.
    label : str
        What the stage does, for people (shown beside the name by the progress).
    options : tuple of str
        ProcessOptions fields the stage's result depends on.
    outputs : tuple of str
        Files or folders it writes into the products folder (relative).
    run : callable
        ``run(context) -> record`` (a frozen dataclass).
    """

    name: str
    label: str
    options: tuple[str, ...]
    outputs: tuple[str, ...]
    run: Callable[[RunContext], object]


def _digest(obj) -> str:
    return hashlib.sha256(json.dumps(obj, sort_keys=True).encode()).hexdigest()[:16]


# -- records -------------------------------------------------------------------------------

@dataclass(frozen=True)
class SurveyRead:
    """``read_and_validate``: the survey, its CRS and the policies derived from it.

    Attributes
    ----------
    ctx : SurveyContext
    epsg : int
    report : ValidationReport
        With the parsed logs.
    reference_scan : int
    order : tuple of int
        Scans in time order.
    grid : GroundGrid
        The mosaic grid (survey CRS, metres).
    marker_ids : tuple of str
    marker_xy : float (M, 2)
        Surveyed markers, survey CRS metres.
    """

    ctx: object
    epsg: int
    report: object
    reference_scan: int
    order: tuple[int, ...]
    grid: object
    marker_ids: tuple[str, ...]
    marker_xy: np.ndarray


@dataclass(frozen=True)
class BandOffsets:
    """``band_coregistration``: the offset of each band from band 0 (ConformalTransform)."""

    offsets: tuple


@dataclass(frozen=True)
class ScanMosaics:
    """``mosaics`` (updated by ``attitude_adjustment``): per scan its run-state record and the
    attitude (roll, pitch, yaw, degrees) of its own fit."""

    scan_records: dict[int, dict]
    attitudes: dict[int, tuple]


@dataclass(frozen=True)
class AttitudeAdjustment:
    """``attitude_adjustment``: its summary for products.json (None when switched off)."""

    summary: dict | None


@dataclass(frozen=True)
class Footprint:
    """``residuals_and_footprint``: cells seen by at least one scan, bool (H, W)."""

    valid: np.ndarray


@dataclass(frozen=True)
class Detection:
    """``detection``: the suspects on the stacked mosaics, or the products kept.

    Attributes
    ----------
    kept : dict or None
        The products manifest of an earlier run that is up to date (nothing else is set).
    labels : int32 (H, W)
    features : list of AnomalyFeatures
    markers : list of MarkerMatch
    stack : ScanStack
        The mosaics detected on, degrees C, read scan by scan from their COGs
        (:class:`clearfast_gis.export.cog.CogStack`).
    times_s : float (N,)
        Scan times, UTC epoch seconds.
    transform : affine.Affine
    mosaics_digest : str
        Checksum of the mosaics detected on.
    """

    kept: dict | None = None
    labels: np.ndarray | None = None
    features: list = field(default_factory=list)
    markers: list = field(default_factory=list)
    stack: object = None
    times_s: np.ndarray | None = None
    transform: object = None
    mosaics_digest: str = ""


@dataclass(frozen=True)
class Characterisation:
    """``characterisation``: depth and diffusivity per anomaly id, the site's soil
    diffusivity (m2/s) and its 1-sigma, what was skipped, and how much contrast the day
    gave (a :class:`~clearfast_gis.thermal.daycontrast.DayContrast`, or None)."""

    inversions: dict = field(default_factory=dict)
    soil_alpha_m2s: float = math.nan
    soil_alpha_sigma_m2s: float = math.nan
    notes: tuple[str, ...] = ()
    day: object = None


@dataclass(frozen=True)
class Products:
    """``products``: the products manifest (``products.json`` content, before timings)."""

    manifest: dict


# -- stages --------------------------------------------------------------------------------

def _read(c: RunContext) -> SurveyRead:
    from clearfast_gis.geometry.gnss import survey_markers
    from clearfast_gis.mosaic.survey_grid import mosaic_grid_for, pixel_size, reference_scan
    from clearfast_gis.pipeline import inputs

    ctx, epsg, report = inputs.open_context(c.survey_path, c.progress, c.station_profile)
    survey = ctx.survey
    key = inputs.input_key(survey, c.station_profile)
    c.state = RunState(c.products, key)
    if c.fresh:
        c.state.units = {}
    ref = reference_scan(survey, c.options.reference_scan)
    ids, xy = survey_markers(report.logs.markers, epsg)
    return SurveyRead(ctx, epsg, report, ref, tuple(sorted(int(x) for x in survey.scans)),
                      mosaic_grid_for(ctx, epsg, pixel_size(survey, c.options.pixel_size_m), ref),
                      tuple(ids), xy)


def _bands(c: RunContext) -> BandOffsets:
    from clearfast_gis.pipeline.scanjob import band_offsets

    read = c[READ]
    offsets = band_offsets(read.ctx, c.stage_state(BANDS), read.reference_scan, c.progress)
    read.ctx.band_offsets = offsets
    return BandOffsets(tuple(offsets))


def _mosaics(c: RunContext) -> ScanMosaics:
    from clearfast_gis.attitude.survey import stored_model
    from clearfast_gis.mosaic.scanjob import scan_mosaics
    from clearfast_gis.pipeline.scanjob import scan_job

    read = c[READ]
    c.job = scan_job(c, read, c.stage_state(MOSAICS))
    model = stored_model(c.stage_state(ADJUSTMENT))
    records, attitudes = scan_mosaics(c.job, list(read.order), read.reference_scan, model)
    return ScanMosaics(records, attitudes)


def _adjustment(c: RunContext) -> AttitudeAdjustment:
    from clearfast_gis.attitude.survey import adjust_survey_attitude

    if not (c.options.coregister and c.options.adjust_attitude):
        return AttitudeAdjustment(None)
    read, mosaics = c[READ], c[MOSAICS]
    return AttitudeAdjustment(adjust_survey_attitude(
        c.job, c.stage_state(ADJUSTMENT), list(read.order), mosaics.scan_records,
        mosaics.attitudes, c.progress, reference_scan=read.reference_scan))


def _footprint(c: RunContext) -> Footprint:
    from clearfast_gis.export.products import write_footprint_geojson
    from clearfast_gis.mosaic.temporal import temporal_residuals

    c.job.close()
    read = c[READ]
    valid = temporal_residuals(c.products, c[MOSAICS].scan_records, read.reference_scan,
                               c.options.coregister, decode_once=True)
    write_footprint_geojson(c.products / "footprint.geojson", valid, read.grid.transform,
                            read.epsg, read.ctx.survey.manifest["survey_id"])
    return Footprint(valid)


def _detection(c: RunContext) -> Detection:
    from clearfast_gis.pipeline.anomalies import detect

    return detect(c)


def _characterisation(c: RunContext) -> Characterisation:
    from clearfast_gis.pipeline.anomalies import characterise_suspects

    return characterise_suspects(c)


def _products(c: RunContext) -> Products:
    from clearfast_gis.pipeline.anomalies import write_products

    return Products(write_products(c))


READ, BANDS, MOSAICS, ADJUSTMENT, FOOTPRINT, DETECTION, CHARACTERISATION, PRODUCTS = (
    "read_and_validate", "band_coregistration", "mosaics", "attitude_adjustment",
    "residuals_and_footprint", "detection", "characterisation", "products")

_MOSAIC_OPTIONS = ("pixel_size_m", "coregister", "search_m", "attitude_samples",
                   "adjust_attitude", "frame_refine", "max_shift_m", "max_angle_deg",
                   "seam_balance", "atmosphere")

STAGES: tuple[Stage, ...] = (
    Stage(READ, "read and validate the survey folder", (), (), _read),
    Stage(BANDS, "filter-wheel band offsets", ("reference_scan", "kernels"), (), _bands),
    # the scans re-projected by the adjustment are mosaic units: both depend on all the
    # mosaic parameters (turning the adjustment off must redo the mosaics it moved)
    Stage(MOSAICS, "one mosaic per scan, attitude fitted", _MOSAIC_OPTIONS, ("mosaics/",),
          _mosaics),
    Stage(ADJUSTMENT, "survey-wide attitude adjustment", (), ("mosaics/",), _adjustment),
    Stage(FOOTPRINT, "temporal residuals and footprint", (), ("footprint.geojson",),
          _footprint),
    Stage(DETECTION, "anomaly detection on the mosaics",
          ("d1_m", "d2_m", "epsilon", "threshold_snr", "level", "level_fraction", "gamma",
           "gamma_fraction", "max_anomalies"), (), _detection),
    Stage(CHARACTERISATION, "depth and diffusivity of the suspects", ("invert",), (),
          _characterisation),
    Stage(PRODUCTS, "GeoPackage, figures, report", (),
          ("anomalies.gpkg", "report.html", "figures/"), _products),
)
"""The chain, in order."""

STAGE_NAMES: tuple[str, ...] = tuple(s.name for s in STAGES)


def stage_index(name: str) -> int:
    """Position of stage ``name`` in :data:`STAGES` (ValueError naming the stages)."""
    if name not in STAGE_NAMES:
        raise ValueError(f"unknown stage {name!r} (stages: {', '.join(STAGE_NAMES)})")
    return STAGE_NAMES.index(name)


__all__ = ["STAGES", "STAGE_NAMES", "RunContext", "Stage", "stage_index"]
