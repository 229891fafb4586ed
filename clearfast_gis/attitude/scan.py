"""Per-scan platform attitude from the reference scan and the surveyed markers: the ties of
one scan measured (frame registrations, marker positions) and fitted."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import shapely

from clearfast_gis.attitude.adjust import attitude_at
from clearfast_gis.attitude.fit import fit_attitude
from clearfast_gis.attitude.ties import GroundTie, LinearTie, displacement_jacobian
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.geometry.pose import CameraPose
from clearfast_gis.geometry.projection import frame_footprints
from clearfast_gis.mosaic import FrameInput, build_scan_mosaic, project_frame
from clearfast_gis.mosaic.coregister import measure_correction
from clearfast_gis.mosaic.markers import locate_marker
from clearfast_gis.parallel import thread_map

MARKER_WEIGHT = 5.0
"""Weight of a marker tie relative to an image-registration tie (markers are surveyed)."""


TIE_SAMPLES = 12_000
"""Samples (the steepest-gradient cells) of each frame registration that ties a scan's
attitude. A frame window holds ~30,000 cells; the attitude is fitted to ~50 ties, whose
average does not need each tie's last hundredth of a pixel: on the trial survey 12,000
samples change the fitted roll, pitch and yaw by <= 0.0003 degrees (0.1 mm at 20 m) and
save a fifth of the fit's time."""


ATTITUDE_SAMPLES = 24
"""Frames of a scan, spread over its scan pattern, registered against each reference to tie
its attitude (``ProcessOptions.attitude_samples``; the refined adjustment's neighbour ties
take :data:`~clearfast_gis.attitude.neighbours.NEIGHBOUR_SAMPLES`). Three angles are
fitted to twice as many ties plus the markers. On the trial (251 positions a scan), 24
instead of 40 frames left the misregistration from the true poses as it was, median / max
0.28 / 0.44 px against 0.28 / 0.46 px (seed 0, steady lift; 0.26 / 0.42 and 0.29 / 0.44
px against 0.27 / 0.38 and 0.26 / 0.46 with the drifting lift, seeds 1 and 2). It cut the
mosaics stage from 131 to 103 CPU s (BENCHMARKS.md, "Fewer frames tie a scan's
attitude"). The demo's scans have 24 positions: every frame is a sample either way."""


@dataclass(frozen=True)
class AttitudeFit:
    """The attitude chosen for a scan and the evidence behind it.

    Attributes
    ----------
    attitude_rpy_deg : (roll, pitch, yaw), degrees
    n_marker_ties, n_image_ties, n_used : int
        Ties measured on markers and by registration, and inliers of the fit.
    rms_m : float
        Weighted RMS residual of the ties, metres (NaN without a fit).
    ties : tuple of LinearTie
        The ties, linearised for the survey-wide adjustment
        (:func:`clearfast_gis.attitude.adjust.adjust_attitudes`).
    """

    attitude_rpy_deg: tuple[float, float, float]
    n_marker_ties: int
    n_image_ties: int
    n_used: int
    rms_m: float
    ties: tuple[LinearTie, ...] = field(default=(), repr=False)

    def as_dict(self) -> dict:
        return {"attitude_rpy_deg": list(self.attitude_rpy_deg),
                "n_marker_ties": self.n_marker_ties, "n_image_ties": self.n_image_ties,
                "n_used": self.n_used,
                "rms_m": None if not np.isfinite(self.rms_m) else self.rms_m}


@dataclass(frozen=True)
class ReferenceMosaic:
    """A finished scan mosaic that later scans are registered against.

    Attributes
    ----------
    scan : int
    values : float32 (B, H, W)
        Degrees C.
    source : int (H, W)
        Scan-pattern position of the frame seen in each cell (-1: none).
    frame_at : callable
        ``frame_at(position) -> (time_s, CameraPose)``: the frame's time and the pose (with
        the attitude) it was placed with.
    """

    scan: int
    values: np.ndarray
    source: np.ndarray
    frame_at: Callable[[int], tuple[float, CameraPose]]

    def tie_frame(self, row_slice: slice, col_slice: slice) -> int | None:
        """The position whose frame supplies most of the window (None if empty)."""
        src = self.source[row_slice, col_slice]
        src = src[src >= 0]
        if src.size == 0:
            return None
        vals, counts = np.unique(src, return_counts=True)
        return int(vals[np.argmax(counts)])


def reposed(frames: list[FrameInput], attitude_rpy_deg) -> list[FrameInput]:
    """The frames with every pose given ``attitude_rpy_deg`` (one attitude, or (N, 3))."""
    att = np.asarray(attitude_rpy_deg, dtype=float)
    if att.ndim == 1:
        att = np.broadcast_to(att, (len(frames), 3))
    return [FrameInput(f.index, f.values, f.pose.with_attitude(a))
            for f, a in zip(frames, att, strict=True)]


def reposed_in_time(frames: list[FrameInput], times_s: np.ndarray, node_times_s: np.ndarray,
                    nodes_rpy_deg: np.ndarray) -> list[FrameInput]:
    """The frames posed with the survey-wide attitude model at their times (UTC epoch s)."""
    return reposed(frames, attitude_at(times_s, node_times_s, nodes_rpy_deg))


def _marker_tie(placed: list[FrameInput], footprints, camera, grid: GroundGrid, n_bands: int,
                x: float, y: float, search_m: float) -> GroundTie | None:
    """Find one surveyed marker in a small mosaic of the frames that see it."""
    box = shapely.box(x - search_m, y - search_m, x + search_m, y + search_m)
    sel = [i for i, fp in enumerate(footprints) if fp.intersects(box)]
    if not sel:
        return None
    ps = grid.pixel_size
    x0 = grid.x0 + np.floor((x - search_m - grid.x0) / ps) * ps
    y0 = grid.y0 - np.floor((grid.y0 - (y + search_m)) / ps) * ps
    n = int(np.ceil(2 * search_m / ps)) + 2
    local = GroundGrid(x0, y0, ps, n, n, grid.epsg)
    m = build_scan_mosaic([placed[i] for i in sel], camera, local, n_bands, coregister=False)
    found = locate_marker(m.values[0], local, x, y, search_m=search_m)
    if found is None:
        return None
    r, c = local.rowcol(np.array([found[0]]), np.array([found[1]]))
    rr, cc = int(round(float(r[0]))), int(round(float(c[0])))
    if not (0 <= rr < local.height and 0 <= cc < local.width) or m.source[rr, cc] < 0:
        return None
    index_of = {f.index: i for i, f in enumerate(placed)}
    return GroundTie(index_of[int(m.source[rr, cc])], found[0], found[1], x - found[0],
                     y - found[1], MARKER_WEIGHT)


def scan_attitude(frames: list[FrameInput], times_s: np.ndarray, camera, grid: GroundGrid,
                  n_bands: int, references: list[ReferenceMosaic], marker_xy: np.ndarray,
                  scan: int, init_rpy_deg=(0.0, 0.0, 0.0), search_m: float = 0.6,
                  n_samples: int = ATTITUDE_SAMPLES) -> AttitudeFit:
    """Fit the platform attitude of one scan.

    Parameters
    ----------
    frames : list of FrameInput
        The scan's calibrated frames with their geometric poses.
    times_s : float (N,)
        Time of each frame, UTC epoch seconds.
    camera : camera model
    grid : GroundGrid
        The mosaic grid.
    n_bands : int
    references : list of ReferenceMosaic
        Mosaics to measure the frames against (the previous scan's, and the reference
        scan's so that errors do not accumulate along the chain); empty for the first scan.
    marker_xy : float (M, 2)
        Surveyed markers, survey CRS metres.
    scan : int
        The scan's number (recorded in its ties).
    init_rpy_deg : (roll, pitch, yaw)
        Starting attitude (the previous scan's), degrees.
    search_m : float
        Largest displacement searched per frame registration, metres.
    n_samples : int
        Frames registered against the reference (spread over the scan pattern).

    Returns
    -------
    AttitudeFit
        With every tie linearised for the survey-wide adjustment.
    """
    init = tuple(float(a) for a in init_rpy_deg)
    placed = reposed(frames, init)
    ties: list[GroundTie] = []
    linear: list[LinearTie] = []
    n_marker = n_image = 0
    base = np.array(init)

    def jac_at(i: int, x: float, y: float) -> np.ndarray:
        return displacement_jacobian(camera, placed[i].pose, x, y)

    footprints = None
    if len(marker_xy):
        footprints = frame_footprints(camera, [f.pose for f in placed])
        for x, y in marker_xy:
            tie = _marker_tie(placed, footprints, camera, grid, n_bands, float(x), float(y),
                              search_m)
            if tie is not None:
                ties.append(tie)
                linear.append(LinearTie(scan, float(times_s[tie.frame]), base,
                                        jac_at(tie.frame, tie.x, tie.y),
                                        np.array([tie.dx, tie.dy]), tie.weight))
                n_marker += 1
    if references:
        pick = np.unique(np.linspace(0, len(placed) - 1, min(n_samples, len(placed)))
                         .round().astype(int))

        def measure(i: int):
            """Frame ``i`` projected, and its displacement against each reference."""
            pf = project_frame(placed[i].values, camera, placed[i].pose, grid,
                               footprint=None if footprints is None else footprints[i])
            if pf is None:
                return None
            rs, cs = pf.window.slices
            return pf, [measure_correction(pf, ref.values[:, rs, cs], grid.pixel_size,
                                           max_shift_m=search_m, max_angle_deg=0.0,
                                           max_samples=TIE_SAMPLES)[0]
                        for ref in references]

        for i, measured in zip(pick, thread_map(measure, pick), strict=True):
            if measured is None:
                continue
            pf, corrs = measured
            rs, cs = pf.window.slices
            xc = grid.x0 + (pf.window.col0 + pf.window.width / 2) * grid.pixel_size
            yc = grid.y0 - (pf.window.row0 + pf.window.height / 2) * grid.pixel_size
            for ref, corr in zip(references, corrs, strict=True):
                if not corr.applied:
                    continue
                ties.append(GroundTie(int(i), xc, yc, corr.dx_m, corr.dy_m, 1.0))
                n_image += 1
                j = ref.tie_frame(rs, cs)
                if j is None:
                    continue
                t_ref, pose_ref = ref.frame_at(j)
                xr, yr = xc + corr.dx_m, yc + corr.dy_m
                linear.append(LinearTie(
                    scan, float(times_s[i]), base, jac_at(int(i), xc, yc),
                    np.array([corr.dx_m, corr.dy_m]), 1.0, ref.scan, float(t_ref),
                    np.asarray(pose_ref.attitude_rpy_deg, dtype=float),
                    displacement_jacobian(camera, pose_ref, xr, yr)))
    if len(ties) < 2:
        return AttitudeFit(init, n_marker, n_image, 0, float("nan"), tuple(linear))
    poses = [f.pose for f in frames]
    att, rms, used = fit_attitude(camera, poses, ties, base_rpy_deg=init)
    return AttitudeFit(att, n_marker, n_image, used, rms, tuple(linear))
