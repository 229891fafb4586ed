"""The calibration stage on a survey folder: raw frames of a scan to apparent temperature.

Thin glue between :mod:`clearfast_gis.survey` (blackbody frames and log, weather log, raw
frames) and the pure functions of this package. Calibration is applied frame by frame at each
frame's own time (nearest event, or gain and offset interpolated between the two bracketing
events); air temperature, humidity and pressure are interpolated in the weather log at each
frame's time.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import cv2
import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis import kernels
from clearfast_gis.errors import InvalidInput
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.radiometry.atmosphere import (
    LW_WINDOW_UM,
    atmospheric_transmittance,
    correct_atmosphere,
)
from clearfast_gis.radiometry.calibration import (
    DEFAULT_MIN_CONTRAST_COUNTS,
    CalibrationEvent,
    GainOffset,
    blackbody_temperature_at,
    select_events_many,
)
from clearfast_gis.radiometry.camera import CameraRadiometry
from clearfast_gis.radiometry.table import BandTable
from clearfast_gis.radiometry.timeseries import interpolate_log
from clearfast_gis.units import c_to_k

if TYPE_CHECKING:
    from clearfast_gis.survey import Survey, WeatherLog

DEFAULT_PATH_LENGTH_M = 20.0
"""Camera-to-surface path length used when the geometry supplies none (paper section 3.5:
"around 20 m"), metres."""

DEFAULT_WEATHER_GAP_S = 900.0
"""A frame farther than this from any valid weather record is an error, seconds."""

KERNEL_BLOCK_FRAMES = 8
"""Frames calibrated by one call of the ``apparent_frames`` kernel: it reads each row of the
calibration images once for them all (two events' gain and offset, four float64 maps of 2.6
MB at 320 x 256, more than a core's cache keeps from one frame to the next); the block's
transmittance maps, float32, take 2.6 MB at 320 x 256 and 10.5 MB at 640 x 512."""


@functools.lru_cache(maxsize=16)
def band_table(lambda_min_um: float, lambda_max_um: float) -> BandTable:
    """The :class:`BandTable` of a band, built once per process (200-400 K)."""
    return BandTable(lambda_min_um, lambda_max_um)


def has_transmittance_model(lambda_min_um: float, lambda_max_um: float) -> bool:
    """Whether :func:`atmospheric_transmittance` covers the band (long-wave window)."""
    return LW_WINDOW_UM[0] <= lambda_min_um < lambda_max_um <= LW_WINDOW_UM[1]


def calibration_events(survey: Survey) -> list[CalibrationEvent] | CameraRadiometry:
    """How the survey's counts become radiance: its blackbody calibration events (every band),
    or the camera's own radiometry for a self-calibrated radiometric camera
    (``camera.radiometry``).

    Mean blackbody images come from ``blackbody/frames.csv``; each blackbody's temperature is
    the blackbody log interpolated at the mean time of that blackbody's frames.

    Parameters
    ----------
    survey : clearfast_gis.survey.Survey

    Returns
    -------
    list of CalibrationEvent, or CameraRadiometry
    """
    from clearfast_gis.survey import read_blackbody_frames, read_blackbody_log

    if survey.radiometry is not None:
        return survey.radiometry

    label = survey.label("blackbody_log")
    log = read_blackbody_log(survey.path("blackbody_log"), label)
    events = []
    for e in read_blackbody_frames(survey):
        t1 = blackbody_temperature_at(log.time_s, c_to_k(log.bb1_c), e.bb1_time_s, source=label)
        t2 = blackbody_temperature_at(log.time_s, c_to_k(log.bb2_c), e.bb2_time_s, source=label)
        events.append(CalibrationEvent(e.time_s, e.band, e.bb1_mean, e.bb2_mean, float(t1),
                                       float(t2)))
    return events


@dataclass(frozen=True)
class AirState:
    """Air at the camera at given times: arrays of the query shape.

    Attributes
    ----------
    t_air_k : float64
        Air temperature, kelvin.
    rh_pct : float64
        Relative humidity, percent.
    pressure_hpa : float64
        Pressure, hPa.
    """

    t_air_k: np.ndarray
    rh_pct: np.ndarray
    pressure_hpa: np.ndarray


def weather_at(weather: WeatherLog, time_s: ArrayLike, max_gap_s: float = DEFAULT_WEATHER_GAP_S,
               source: str | None = None) -> AirState:
    """Air temperature, humidity and pressure at given times from a weather log.

    Parameters
    ----------
    weather : clearfast_gis.survey.WeatherLog
        1-minute records; NaN (logger ``NAN``) records are skipped per variable.
    time_s : array_like (N,)
        Query times, UTC epoch seconds.
    max_gap_s : float
        Largest allowed distance from a query to the nearest valid record, seconds.
    source : str, optional
        Log file name for error messages.

    Returns
    -------
    AirState
        Arrays of shape (N,).
    """
    q = np.atleast_1d(np.asarray(time_s, dtype=np.float64))

    def column(values: np.ndarray, name: str) -> np.ndarray:
        return interpolate_log(weather.time_s, values, q, max_gap_s, source, name)

    return AirState(c_to_k(column(weather.air_temp_c, "AirTC_Avg")),
                    np.clip(column(weather.rh_pct, "RH_Avg"), 0.0, 100.0),
                    column(weather.pressure_hpa, "BP_hPa_Avg"))


def apparent_temperature_frames(
    raw: np.ndarray,
    time_s: ArrayLike,
    band: int,
    table: BandTable,
    events: Sequence[CalibrationEvent] | CameraRadiometry,
    air: AirState,
    path_length_m: ArrayLike | None = None,
    mode: str = "interpolate",
    min_contrast_counts: float = DEFAULT_MIN_CONTRAST_COUNTS,
    atmosphere: bool = True,
    progress: Progress = NULL_PROGRESS,
    gain_cache: dict | None = None,
    out: np.ndarray | None = None,
) -> np.ndarray:
    """Apparent temperature of a stack of frames, each calibrated at its own time.

    Parameters
    ----------
    raw : ndarray (P, H, W)
        Raw counts.
    time_s : array_like (P,)
        Frame times, UTC epoch seconds.
    band : int
        Band index (selects the events).
    table : BandTable
        The band.
    events : sequence of CalibrationEvent, or CameraRadiometry
        Calibration events (any bands), or a radiometric camera's own calibration (its
        at-sensor blackbody temperature gives the at-camera band radiance).
    air : AirState
        Air state per frame, arrays (P,).
    path_length_m : float, array_like (P,), (P, H, W) or (P, h, w), optional
        Path length per frame or per pixel, metres; default :data:`DEFAULT_PATH_LENGTH_M`.
        A coarser (P, h, w) lattice spanning the frame corners to corners (the path varies
        smoothly) is turned into transmittance there and interpolated bilinearly.
    mode : {"interpolate", "nearest"}
        Event selection (see :func:`select_events`).
    min_contrast_counts : float
        Degenerate-pixel threshold, counts.
    atmosphere : bool
        Apply the atmospheric correction (Eq. 4); without it ``tau = 1``.
    progress : Progress
        Advanced once per frame.
    gain_cache : dict, optional
        Gain and offset images of the events already computed (for this band, table and
        ``min_contrast_counts``), filled here: pass the same dict to the calls that calibrate
        one scan in blocks of frames.
    out : float32 (P, H, W), optional
        Written with the result (e.g. one band of a (P, B, H, W) stack).

    Returns
    -------
    ndarray of float32 (P, H, W)
        Apparent temperature, kelvin; NaN at uncalibrated pixels (``out`` when given).
    """
    raw = np.asarray(raw)
    if raw.ndim != 3:
        raise InvalidInput(f"expected (P, H, W) frames, got shape {raw.shape}", field="raw")
    n = raw.shape[0]
    times = np.asarray(time_s, dtype=np.float64).reshape(n)
    path = np.asarray(DEFAULT_PATH_LENGTH_M if path_length_m is None else path_length_m,
                      dtype=np.float64)
    if path.ndim == 1:
        path = path.reshape(n, 1, 1)
    if path.ndim == 3 and path.shape[0] != n:
        raise InvalidInput(f"path length shape {path.shape} does not match frames {raw.shape}",
                           field="path_length_m")
    coarse = path.ndim == 3 and path.shape[1:] not in ((1, 1), raw.shape[1:])
    if coarse and not (2 <= path.shape[1] <= raw.shape[1] and 2 <= path.shape[2] <= raw.shape[2]):
        raise InvalidInput(f"path length lattice {path.shape} does not fit frames {raw.shape}",
                           field="path_length_m")
    cache: dict[int, GainOffset] = {} if gain_cache is None else gain_cache
    own = events if isinstance(events, CameraRadiometry) else None
    selected = [] if own is not None else select_events_many(events, times, mode, band)
    tau_all = None
    if atmosphere:  # every frame's transmittance in one call
        frame_axis = (n,) + (1,) * (path.ndim - 1 if path.ndim == 3 else path.ndim)
        tau_all = atmospheric_transmittance(
            path, *(np.asarray(a, dtype=np.float64).reshape(frame_axis)
                    for a in (air.t_air_k, air.rh_pct, air.pressure_hpa)),
            table.lambda_min_um, table.lambda_max_um)
    b_air_all = table.radiance(air.t_air_k)
    if out is None:
        out = np.empty(raw.shape, dtype=np.float32)
    elif out.shape != raw.shape or out.dtype != np.float32:
        raise InvalidInput(f"output {out.dtype} {out.shape} does not match frames {raw.shape}",
                           field="out")
    def frame_tau(k: int):
        """Frame ``k``'s transmittance: 1, a scalar or an (H, W) map."""
        if tau_all is None:
            return 1.0
        if coarse:
            return cv2.resize(np.asarray(tau_all[k], dtype=np.float32),
                              (raw.shape[2], raw.shape[1]), interpolation=cv2.INTER_LINEAR)
        return tau_all[k]

    if own is not None:
        for k in range(n):
            out[k] = camera_apparent(raw[k], own, tau_all[k] if tau_all is not None else 1.0,
                                     air.t_air_k[k], table, raw.shape[1:])
            progress.advance(1)
        return out
    for k0 in range(0, n, KERNEL_BLOCK_FRAMES):
        block = range(k0, min(k0 + KERNEL_BLOCK_FRAMES, n))
        parts = []
        for k in block:
            frame_parts = []
            for ev, w in selected[k]:
                if id(ev) not in cache:
                    cache[id(ev)] = ev.gain_offset(table, min_contrast_counts)
                frame_parts.append((cache[id(ev)], w))
            parts.append(frame_parts)
        kernels.kernel("apparent_frames")(raw[k0:block.stop], parts,
                                          [frame_tau(k) for k in block],
                                          air.t_air_k[k0:block.stop],
                                          b_air_all[k0:block.stop], table,
                                          out[k0:block.stop])
        progress.advance(len(block))
    return out


def camera_apparent(raw: np.ndarray, camera: CameraRadiometry, tau: ArrayLike,
                    t_air_k: float, table: BandTable, shape_hw: tuple[int, int]) -> np.ndarray:
    """Apparent temperature (kelvin, float32 (H, W)) of one radiometric camera frame:
    counts -> at-sensor blackbody temperature (the camera's own calibration) -> band radiance
    -> the toolkit's atmosphere (Eq. 4) -> inverse Planck (Eq. 5).

    ``tau`` is the frame's transmittance: a scalar, (H, W), or a coarser lattice spanning the
    frame corner to corner (interpolated bilinearly).
    """
    tau = np.asarray(tau, dtype=np.float64)
    if tau.ndim == 2 and tau.shape != tuple(shape_hw):
        tau = cv2.resize(tau.astype(np.float32), (shape_hw[1], shape_hw[0]),
                         interpolation=cv2.INTER_LINEAR).astype(np.float64)
    radiance = table.radiance(camera.sensor_temperature_k(raw))
    surface = correct_atmosphere(radiance, tau, t_air_k, table)
    return table.temperature(surface, dtype=np.float32)


def apparent_temperature_scan(
    survey: Survey,
    scan: int,
    band: int | str,
    events: Sequence[CalibrationEvent],
    weather: WeatherLog,
    path_length_m: ArrayLike | None = None,
    mode: str = "interpolate",
    min_contrast_counts: float = DEFAULT_MIN_CONTRAST_COUNTS,
    progress: Progress = NULL_PROGRESS,
) -> np.ndarray:
    """Apparent temperature of every frame of one scan and band (calibration stage).

    Parameters
    ----------
    survey : clearfast_gis.survey.Survey
        The survey folder.
    scan : int
        Scan number.
    band : int or str
        Band index or name.
    events : sequence of CalibrationEvent
        From :func:`calibration_events`.
    weather : clearfast_gis.survey.WeatherLog
        The weather log.
    path_length_m : float, array_like (P,) or (P, H, W), optional
        Camera-to-surface path (e.g. the geometry's per-pixel slant range), metres; default
        :data:`DEFAULT_PATH_LENGTH_M`.
    mode : {"interpolate", "nearest"}
        Calibration event selection.
    min_contrast_counts : float
        Degenerate-pixel threshold, counts.
    progress : Progress
        Advanced once per frame (the caller starts the stage).

    Returns
    -------
    ndarray of float32 (P, H, W)
        Apparent temperature, kelvin, frames in :meth:`Survey.scan_positions` order; NaN at
        uncalibrated pixels. Bands outside the long-wave window (no transmittance model) are
        not corrected for the atmosphere.
    """
    b = survey.band_index(band)
    info = survey.bands[b]
    table = band_table(info.lambda_min_um, info.lambda_max_um)
    rows = survey.scan_rows(scan, b)
    raw = survey.read_scan(scan, b)
    times = survey.frames.time_s[rows]
    air = weather_at(weather, times, source=survey.label("weather"))
    return apparent_temperature_frames(
        raw, times, b, table, events, air, path_length_m, mode, min_contrast_counts,
        atmosphere=has_transmittance_model(info.lambda_min_um, info.lambda_max_um),
        progress=progress)


