"""The mosaic stages' glue to the run state: the band co-registration stage's unit, and the
mosaic worker (:class:`clearfast_gis.mosaic.scanjob.ScanJob`) of a run, whose finished scans
are the mosaic stage's units ``mosaics/scan_NNN``."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from clearfast_gis.export.cog import band_description
from clearfast_gis.mosaic.frames import SurveyContext, air_function, first_scan_band_frames
from clearfast_gis.mosaic.scanjob import ScanJob
from clearfast_gis.pipeline.state import StageState
from clearfast_gis.progress import Progress
from clearfast_gis.registration import ConformalTransform, estimate_band_offsets


def scan_part(scan: int) -> str:
    """The mosaic stage's run-state unit of a scan (``mosaics/scan_NNN``)."""
    return f"scan_{scan:03d}"


@dataclass(frozen=True)
class _ScanUnits:
    """The mosaic stage's run state seen as the worker's :class:`~clearfast_gis.mosaic.
    scanjob.ScanUnits` (a unit per scan)."""

    state: StageState

    def done(self, scan: int) -> dict | None:
        return self.state.done(scan_part(scan))

    def finish(self, scan: int, record: dict, files: list[str]) -> None:
        self.state.finish(scan_part(scan), record, files)


def band_offsets(ctx: SurveyContext, state: StageState, reference: int,
                 progress: Progress) -> list[ConformalTransform]:
    """Offsets of the bands from band 0 (filter wheel), measured on the reference scan's
    frames; the stage's run-state unit keeps them."""
    rec = state.done()
    n = len(ctx.survey.bands)
    if rec is not None:
        return [ConformalTransform(**t) for t in rec["offsets"]]
    if n == 1:
        offsets = [ConformalTransform.identity()]
    else:
        progress.start("band co-registration", 1)
        stacks = first_scan_band_frames(ctx, reference, air_function(ctx))
        offsets = estimate_band_offsets(stacks)
        progress.advance()
        progress.close()
    state.finish("", {"offsets": [
        {k: (v if not (isinstance(v, float) and math.isnan(v)) else 0.0)
         for k, v in dataclasses.asdict(t).items()} for t in offsets]})
    return offsets


def scan_job(c, read, state: StageState) -> ScanJob:
    """The mosaic worker of a run (``c``: the RunContext; ``read``: its SurveyRead)."""
    survey = read.ctx.survey
    descriptions = [band_description(b.name, b.lambda_min_um, b.lambda_max_um)
                    for b in survey.bands]
    return ScanJob(read.ctx, read.grid, read.epsg, descriptions, air_function(read.ctx),
                   read.marker_xy, c.options, c.products, _ScanUnits(state), c.progress)
