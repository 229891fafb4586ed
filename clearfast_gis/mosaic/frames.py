"""From a survey's raw frames to apparent-temperature frames with their poses.

Glue between the survey reader, the geometry (pose per frame, path length per pixel) and the
radiometry (two-blackbody calibration, atmosphere, apparent temperature).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.geometry.gnss import PlatformTrack
from clearfast_gis.geometry.pose import CameraPose, pose_from_ptu
from clearfast_gis.mosaic.build import FrameInput
from clearfast_gis.parallel import thread_imap
from clearfast_gis.radiometry.calibration import CalibrationEvent
from clearfast_gis.radiometry.camera import CameraRadiometry
from clearfast_gis.radiometry.stage import (
    AirState,
    apparent_temperature_frames,
    band_table,
    has_transmittance_model,
    weather_at,
)
from clearfast_gis.registration import ConformalTransform, warp_conformal
from clearfast_gis.units import ZERO_CELSIUS_K


@dataclass
class SurveyContext:
    """What every scan of one survey needs, read once.

    Attributes
    ----------
    survey : clearfast_gis.survey.Survey
    camera : camera model
    track : PlatformTrack
        Antenna positions in the survey CRS.
    events : list of CalibrationEvent, or CameraRadiometry (a radiometric camera)
    weather : clearfast_gis.survey.WeatherLog
    band_offsets : list of ConformalTransform
        Band b to band 0 alignment (maps band-0 pixels to band-b pixels).
    """

    survey: object
    camera: object
    track: PlatformTrack
    events: list[CalibrationEvent] | CameraRadiometry
    weather: object
    band_offsets: list[ConformalTransform]


def frame_pose(ctx: SurveyContext, time_s: float, pan_deg: float, tilt_deg: float) -> CameraPose:
    """Geometric pose of a frame: RTK position at the frame time, pan/tilt, mount."""
    return frame_poses(ctx, np.array([time_s]), np.array([pan_deg]), np.array([tilt_deg]))[0]


def frame_poses(ctx: SurveyContext, time_s: np.ndarray, pan_deg: np.ndarray,
                tilt_deg: np.ndarray) -> list[CameraPose]:
    """Geometric poses of many frames (one vectorised position interpolation)."""
    antenna = ctx.track.at(np.asarray(time_s, dtype=float))
    platform = ctx.survey.manifest["platform"]
    return [pose_from_ptu(a, p, t, platform) for a, p, t in zip(antenna, pan_deg, tilt_deg,
                                                                 strict=True)]


def path_length_map(camera, pose: CameraPose, lattice: int = 17) -> np.ndarray:
    """Camera-to-ground distance (m) on a lattice of pixels, float32 (n, n),
    ``n = min(lattice, W, H)``.

    The slant range varies smoothly over a frame, so it is computed exactly on a
    ``lattice x lattice`` grid of pixels spanning the frame corner to corner; the radiometry
    interpolates the transmittance bilinearly from it. Pixels that see the sky (or meet the
    ground beyond float32's range) get the largest range of the frame.
    """
    return path_length_maps(camera, [pose], lattice)[0]


def path_length_maps(camera, poses: Sequence[CameraPose], lattice: int = 17) -> np.ndarray:
    """:func:`path_length_map` of many frames, float32 (F, n, n), the lattice's rays in one
    vectorised computation (the same values, bit for bit, as one frame at a time)."""
    w, h = camera.width, camera.height
    lattice = max(2, min(lattice, w, h))
    us = np.linspace(0, w - 1, lattice)
    vs = np.linspace(0, h - 1, lattice)
    uu, vv = np.meshgrid(us, vs)
    g = camera.ground_points_of_poses(uu.ravel(), vv.ravel(), poses)  # (F, n * n, 3)
    origins = np.stack([p.position_m for p in poses])
    d = np.linalg.norm(g - origins[:, None, :], axis=2)
    # a ray that meets the ground beyond float32's range (grazing the horizon) sees sky
    d = np.where(d <= np.finfo(np.float32).max, d, np.nan)
    seen = np.isfinite(d)
    with np.errstate(invalid="ignore"):  # a frame that sees no ground: 20 m
        fill = np.where(seen.any(axis=1), np.nanmax(np.where(seen, d, -np.inf), axis=1), 20.0)
    out = np.where(seen, d, fill[:, None])
    return out.reshape(len(poses), lattice, lattice).astype(np.float32)


def scan_frames(ctx: SurveyContext, scan: int, air_at, atmosphere: bool = True,
                chunk: int = 32, empty: Callable[..., np.ndarray] = np.empty
                ) -> Iterator[FrameInput]:
    """Apparent-temperature frames of one scan, in scan-pattern order.

    Parameters
    ----------
    ctx : SurveyContext
    scan : int
    air_at : callable
        ``air_at(time_s (N,)) -> AirState`` (weather interpolated at frame times).
    atmosphere : bool
        Apply the atmospheric correction.
    chunk : int
        Positions calibrated at a time (bounds memory for large frames).
    empty : callable
        ``empty(shape, dtype)``: the memory of each block of calibrated frames, float32
        (P, B, H, W), every element of which is written here (``np.empty``, or a
        :class:`~clearfast_gis.mosaic.buffers.BufferLease`'s blocks of an earlier scan).

    Yields
    ------
    FrameInput
        values: float32 (B, H, W) degrees C, bands aligned to band 0.
    """
    survey = ctx.survey
    n_bands = len(survey.bands)
    fr = survey.frames
    rows0 = survey.scan_rows(scan, 0)
    positions = fr.position[rows0]
    common = set(positions.tolist())
    rows_by_band = [rows0]
    for b in range(1, n_bands):
        rb = survey.scan_rows(scan, b)
        common &= set(fr.position[rb].tolist())
        rows_by_band.append(rb)
    keep = np.array(sorted(common), dtype=np.int64)
    if keep.size == 0:
        return
    sel = [r[np.isin(fr.position[r], keep)] for r in rows_by_band]
    poses = frame_poses(ctx, fr.time_s[sel[0]], fr.pan_deg[sel[0]], fr.tilt_deg[sel[0]])
    raw_all = [survey.read_scan(scan, b) for b in range(n_bands)]
    pos_all = [fr.position[survey.scan_rows(scan, b)] for b in range(n_bands)]
    gains: list[dict] = [{} for _ in range(n_bands)]  # calibration images, once per scan

    def calibrate(start: int) -> tuple[np.ndarray, list[CameraPose], np.ndarray]:
        """Positions, poses and (P, B, H, W) apparent temperatures of one block of frames."""
        idx = slice(start, min(start + chunk, keep.size))
        block_pos = keep[idx]
        block_poses = poses[idx]
        paths = path_length_maps(ctx.camera, block_poses)
        stack = empty((block_pos.size, n_bands, ctx.camera.height, ctx.camera.width),
                      np.float32)  # (P, B, H, W)
        for b in range(n_bands):
            order = np.searchsorted(pos_all[b], block_pos)
            if np.any(pos_all[b][order] != block_pos):
                raise InvalidInput("positions differ between bands", survey.label("frames"),
                                   f"scan {scan}")
            raw = np.asarray(raw_all[b][order])
            times = fr.time_s[sel[b][idx]]
            band = survey.bands[b]
            table = band_table(band.lambda_min_um, band.lambda_max_um)
            use_atm = atmosphere and has_transmittance_model(band.lambda_min_um,
                                                             band.lambda_max_um)
            air: AirState = air_at(times)
            dst = stack[:, b]
            apparent_temperature_frames(raw, times, b, table, ctx.events, air,
                                        path_length_m=paths, atmosphere=use_atm,
                                        gain_cache=gains[b], out=dst)
            dst -= np.float32(ZERO_CELSIUS_K)  # kelvin to degrees C
            if b > 0 and not _is_identity(ctx.band_offsets[b]):
                for k in range(dst.shape[0]):
                    dst[k] = warp_conformal(dst[k], ctx.band_offsets[b], dst[k].shape)
        return block_pos, block_poses, stack

    # blocks calibrated on threads (the kernels release the GIL), yielded in scan order: each
    # frame's values do not depend on the block or thread that computed it
    for block_pos, block_poses, stack in thread_imap(calibrate, range(0, keep.size, chunk),
                                                     ahead=2):
        for k, (pos, pose) in enumerate(zip(block_pos, block_poses, strict=True)):
            yield FrameInput(int(pos), stack[k], pose)


def _is_identity(t: ConformalTransform) -> bool:
    return abs(t.tx_px) < 1e-6 and abs(t.ty_px) < 1e-6 and abs(t.angle_rad) < 1e-9 \
        and abs(t.scale - 1.0) < 1e-9


def scan_times(survey, scan: int) -> tuple[float, float]:
    """(start, mean) time of a scan's frames, UTC epoch seconds."""
    t = survey.frames.time_s[survey.frames.scan == scan]
    return float(t.min()), float(t.mean())


def first_scan_band_frames(ctx_partial, scan: int, air_at, max_frames: int = 24
                           ) -> Sequence[np.ndarray]:
    """Per-band apparent-temperature stacks of (up to) ``max_frames`` positions of a scan,
    unaligned, for estimating the filter-wheel band offsets."""
    survey = ctx_partial.survey
    fr = survey.frames
    n_bands = len(survey.bands)
    rows = [survey.scan_rows(scan, b) for b in range(n_bands)]
    common = set(fr.position[rows[0]].tolist())
    for r in rows[1:]:
        common &= set(fr.position[r].tolist())
    pick = np.array(sorted(common), dtype=np.int64)
    if pick.size > max_frames:
        pick = pick[np.linspace(0, pick.size - 1, max_frames).round().astype(int)]
    out = []
    for b in range(n_bands):
        rb = rows[b][np.isin(fr.position[rows[b]], pick)]
        raw = survey.read_scan(scan, b)
        order = np.searchsorted(fr.position[survey.scan_rows(scan, b)], pick)
        band = survey.bands[b]
        table = band_table(band.lambda_min_um, band.lambda_max_um)
        times = fr.time_s[rb]
        t_k = apparent_temperature_frames(np.asarray(raw[order]), times, b, table,
                                          ctx_partial.events, air_at(times), atmosphere=False)
        out.append(t_k)
    return out


def air_function(ctx: SurveyContext):
    """``air_at(time_s) -> AirState``: the survey's weather log interpolated at frame times
    (the ``air_at`` of :func:`scan_frames`), errors naming the weather log."""
    label = ctx.survey.label("weather")
    return lambda t: weather_at(ctx.weather, t, source=label)
