"""The mosaic stage's worker: one scan's mosaic at a time (attitude fit, projection, COG,
record of the finished scan), with the next scan's frames calibrated ahead on a helper thread
and the previous scan's files written on another; and the order the scans are built in (time
order, then the scans before the first marker-anchored one again, backwards).

The module is one concept (building the scans' mosaics) around one stateful object, which
owns the two helper threads and hands finished mosaics to the next scan as references. Which
scans are finished is kept by the caller (:class:`ScanUnits`, the run state of
:mod:`clearfast_gis.pipeline`), so this package does not depend on the pipeline."""

from __future__ import annotations

import dataclasses
import math
import time
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path
from typing import Protocol

import numpy as np

from clearfast_gis.atomic import atomic_path
from clearfast_gis.attitude import ReferenceMosaic, reposed, reposed_in_time, scan_attitude
from clearfast_gis.attitude.placement import nearest_attitude, placement_attitude
from clearfast_gis.export.cog import keep_decoded, read_mosaic, write_cog
from clearfast_gis.export.layout import mosaic_rel, source_rel
from clearfast_gis.mosaic.buffers import BufferLease, BufferPool
from clearfast_gis.mosaic.build import FrameCorrection, build_scan_mosaic
from clearfast_gis.mosaic.frames import frame_pose, scan_frames, scan_times
from clearfast_gis.progress import NULL_PROGRESS


class ScanUnits(Protocol):
    """The record of finished scans that a :class:`ScanJob` reads and writes (the run state,
    so that a run resumes)."""

    def done(self, scan: int) -> dict | None:
        """The record of ``scan`` if it is finished and its files unchanged, else None."""

    def finish(self, scan: int, record: dict, files: list[str]) -> None:
        """Record ``scan`` as finished with its product ``files`` (products-relative)."""


def _correction_dict(c: FrameCorrection) -> dict:
    return dataclasses.asdict(c) | {"metric": None if math.isnan(c.metric) else c.metric}


def source_path(products: Path, scan: int) -> Path:
    """Where a scan's source map is kept (folder created)."""
    p = products / source_rel(scan)
    p.parent.mkdir(parents=True, exist_ok=True)
    return p


class ScanJob:
    """Builds one scan's mosaic (attitude fit, projection, COG, run-state record)."""

    def __init__(self, ctx, grid, epsg, descriptions, air_at, marker_xy, options, products,
                 state: ScanUnits, progress) -> None:
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
        # the calibrated frames' memory, reused from scan to scan (mosaic.buffers)
        self._buffers = BufferPool()
        self._leases: dict[int, BufferLease] = {}

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
            self._leases.clear()
            self._buffers.clear()

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
        """All apparent-temperature frames of ``scan`` (:func:`scan_frames`), in blocks
        leased from the pool until the scan's mosaic is built (:meth:`build`)."""
        lease = self._buffers.lease()
        frames = list(scan_frames(self.ctx, scan, self.air_at,
                                  atmosphere=self.options.atmosphere, empty=lease.empty))
        self._leases[scan] = lease
        return frames

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
            source = np.load(source_path(self.products, scan))
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
        # the mosaic holds copies: the frames' blocks go to the next scans' calibration
        del frames, placed
        lease = self._leases.pop(scan, None)
        if lease is not None:
            lease.release()
        t_start, t_mean = scan_times(survey, scan)
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
            keep_decoded(self.products, rel, values)  # the stages after read it, undecoded
            with atomic_path(source_path(self.products, scan)) as tmp, \
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
            self.state.finish(scan, rec, [rel])


def scan_mosaics(job: ScanJob, order: list[int], ref: int, model=None
                 ) -> tuple[dict[int, dict], dict[int, tuple]]:
    """Every scan's mosaic in time order (each fitted against the previous scan's and the
    reference scan's), then the scans before the first marker-anchored one again, backwards;
    finished scans of an earlier run are kept.

    ``model`` is the survey-wide attitude (node times, nodes) that scans of an earlier run
    were placed with, when the adjustment ran (:func:`~clearfast_gis.attitude.survey.
    stored_model`).

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
    job.plan([s for s in order if state.done(s) is None])
    for scan in order:
        rec = state.done(scan)
        if rec is not None:
            progress.advance(n_pos, scan=scan, resumed=True)
        else:
            refs = [r for r in (previous, reference) if r is not None]
            rec = job.build(scan, refs, nearest_attitude(scan, attitudes))
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
