"""Two-blackbody radiometric calibration (paper section 3.3, Eq. 1).

Each pixel's counts are mapped to band radiance by the straight line through the two blackbody
images: ``I_c = I_r1 + (I - I_bb1) (I_r2 - I_r1) / (I_bb2 - I_bb1)``. Written as
``I_c = gain I + offset`` per pixel, this removes the detector's and the filter's
non-uniformity in one step. Pixels whose two blackbody means differ by less than a few counts
cannot be calibrated: they are flagged invalid (NaN), never divided by zero.

Calibration events are repeated during the survey; a scan uses the event nearest in time or
the linear interpolation of gain and offset between the two events bracketing it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry.table import BandTable
from clearfast_gis.radiometry.timeseries import interpolate_log

DEFAULT_MIN_CONTRAST_COUNTS = 4.0
"""Smallest ``|I_bb2 - I_bb1|`` (counts) for a pixel to be calibrated."""


@dataclass(frozen=True)
class GainOffset:
    """Per-pixel linear calibration ``radiance = gain * counts + offset``.

    Attributes
    ----------
    gain : float64 (H, W)
        W m-2 sr-1 per count; NaN where invalid.
    offset : float64 (H, W)
        W m-2 sr-1; NaN where invalid.
    valid : bool (H, W)
        Pixels that could be calibrated.
    """

    gain: np.ndarray
    offset: np.ndarray
    valid: np.ndarray


def gain_offset_two_point(
    bb1_mean: ArrayLike,
    bb2_mean: ArrayLike,
    r1: ArrayLike,
    r2: ArrayLike,
    min_contrast_counts: float = DEFAULT_MIN_CONTRAST_COUNTS,
) -> GainOffset:
    """Gain and offset per pixel from two blackbody images (Eq. 1).

    Parameters
    ----------
    bb1_mean, bb2_mean : array_like (H, W)
        Mean counts of the heated (1) and ambient (2) blackbody images.
    r1, r2 : float or array_like
        Band radiances of the two blackbodies (Eq. 2), W m-2 sr-1.
    min_contrast_counts : float
        Pixels with ``|bb2 - bb1| < min_contrast_counts`` (or non-finite means) are invalid.

    Returns
    -------
    GainOffset
    """
    bb1 = np.asarray(bb1_mean, dtype=np.float64)
    bb2 = np.asarray(bb2_mean, dtype=np.float64)
    if bb1.shape != bb2.shape or bb1.ndim != 2:
        raise InvalidInput(f"blackbody images must both be (H, W), got {bb1.shape} and "
                           f"{bb2.shape}", field="blackbody")
    diff = bb2 - bb1
    valid = np.isfinite(diff) & (np.abs(diff) >= min_contrast_counts)
    safe = np.where(valid, diff, 1.0)
    r1 = np.asarray(r1, dtype=np.float64)
    r2 = np.asarray(r2, dtype=np.float64)
    gain = np.where(valid, (r2 - r1) / safe, np.nan)
    offset = np.where(valid, r1 - np.where(valid, bb1, 0.0) * gain, np.nan)
    return GainOffset(gain, offset, valid)


def apply_gain_offset(raw: ArrayLike, calibration: GainOffset) -> np.ndarray:
    """Counts to band radiance with a per-pixel gain and offset.

    Parameters
    ----------
    raw : array_like (..., H, W)
        Raw counts (any integer or float dtype).
    calibration : GainOffset
        Arrays (H, W), or (P, H, W) matching a (P, H, W) ``raw`` frame by frame.

    Returns
    -------
    ndarray of float32 (..., H, W)
        Band radiance, W m-2 sr-1; NaN at invalid pixels.
    """
    out = np.asarray(raw).astype(np.float32)
    out *= calibration.gain.astype(np.float32)
    out += calibration.offset.astype(np.float32)
    return out


def calibrate_two_point(
    raw: ArrayLike,
    bb1_mean: ArrayLike,
    bb2_mean: ArrayLike,
    r1: ArrayLike,
    r2: ArrayLike,
    min_contrast_counts: float = DEFAULT_MIN_CONTRAST_COUNTS,
) -> tuple[np.ndarray, np.ndarray]:
    """Radiometric calibration of raw frames with two blackbodies (Eq. 1).

    Parameters
    ----------
    raw : array_like (..., H, W)
        Raw counts.
    bb1_mean, bb2_mean : array_like (H, W)
        Mean blackbody images, counts.
    r1, r2 : float
        Blackbody band radiances, W m-2 sr-1.
    min_contrast_counts : float
        Threshold below which a pixel is degenerate (see :func:`gain_offset_two_point`).

    Returns
    -------
    radiance : ndarray of float32 (..., H, W)
        Calibrated radiance ``I_c``, W m-2 sr-1, NaN at invalid pixels.
    valid : ndarray of bool (H, W)
        Calibrated pixels.
    """
    cal = gain_offset_two_point(bb1_mean, bb2_mean, r1, r2, min_contrast_counts)
    return apply_gain_offset(raw, cal), cal.valid


@dataclass(frozen=True)
class CalibrationEvent:
    """One calibration event of one band: both blackbodies imaged, their temperatures read.

    Attributes
    ----------
    time_s : float
        UTC epoch seconds (mean time of the event's blackbody frames).
    band : int
        Band index into ``camera.bands``.
    bb1_mean, bb2_mean : float64 (H, W)
        Mean counts of the heated (1) and ambient (2) blackbody.
    t_bb1_k, t_bb2_k : float
        Blackbody temperatures at ``time_s``, kelvin.
    """

    time_s: float
    band: int
    bb1_mean: np.ndarray
    bb2_mean: np.ndarray
    t_bb1_k: float
    t_bb2_k: float

    def gain_offset(
        self, table: BandTable, min_contrast_counts: float = DEFAULT_MIN_CONTRAST_COUNTS
    ) -> GainOffset:
        """This event's per-pixel calibration in ``table``'s band."""
        r1, r2 = table.radiance(np.array([self.t_bb1_k, self.t_bb2_k]))
        return gain_offset_two_point(self.bb1_mean, self.bb2_mean, r1, r2, min_contrast_counts)


def event_from_frames(
    time_s: float,
    band: int,
    bb1_frames: ArrayLike,
    bb2_frames: ArrayLike,
    t_bb1_k: float,
    t_bb2_k: float,
) -> CalibrationEvent:
    """A calibration event from its blackbody frame stacks.

    Parameters
    ----------
    time_s : float
        Event time, UTC epoch seconds.
    band : int
        Band index.
    bb1_frames, bb2_frames : array_like (N, H, W)
        Frames of the heated and the ambient blackbody (the paper takes 10 or more each).
    t_bb1_k, t_bb2_k : float
        Blackbody temperatures at ``time_s``, kelvin (see :func:`blackbody_temperature_at`).

    Returns
    -------
    CalibrationEvent
        With the frame means in float64.
    """
    f1 = np.asarray(bb1_frames)
    f2 = np.asarray(bb2_frames)
    for name, f in (("bb1_frames", f1), ("bb2_frames", f2)):
        if f.ndim != 3 or f.shape[0] < 1:
            raise InvalidInput(f"expected a (N, H, W) stack with N >= 1, got {f.shape}",
                               field=name)
    return CalibrationEvent(float(time_s), int(band), f1.mean(axis=0, dtype=np.float64),
                            f2.mean(axis=0, dtype=np.float64), float(t_bb1_k), float(t_bb2_k))


def blackbody_temperature_at(
    log_time_s: ArrayLike,
    log_t_k: ArrayLike,
    time_s: ArrayLike,
    max_gap_s: float = 180.0,
    source: str | None = None,
) -> np.ndarray:
    """Blackbody temperature at given times, linearly interpolated in its log.

    Parameters
    ----------
    log_time_s : array_like (T,)
        Log record times, UTC epoch seconds, increasing.
    log_t_k : array_like (T,)
        Logged temperature, kelvin; NaN records are skipped; queries outside the log take
        the nearest record's value (within ``max_gap_s``).
    time_s : array_like
        Query times, UTC epoch seconds.
    max_gap_s : float
        A query farther than this from the nearest valid record is an error.
    source : str, optional
        File name for error messages.

    Returns
    -------
    ndarray of float64
        Temperature, kelvin, shape of ``time_s``.
    """
    return interpolate_log(log_time_s, log_t_k, time_s, max_gap_s, source)


def select_events(
    events: Sequence[CalibrationEvent],
    time_s: float,
    mode: str = "interpolate",
    band: int | None = None,
) -> list[tuple[CalibrationEvent, float]]:
    """The calibration event(s) to apply at ``time_s``, with their weights.

    Parameters
    ----------
    events : sequence of CalibrationEvent
        All events (any bands, any order).
    time_s : float
        Time of the frame or scan, UTC epoch seconds.
    mode : {"nearest", "interpolate"}
        ``nearest``: the event closest in time. ``interpolate``: the two events bracketing
        ``time_s`` with linear weights; before the first or after the last event, the nearest.
    band : int, optional
        Only events of this band.

    Returns
    -------
    list of (CalibrationEvent, weight)
        One or two entries, weights summing to 1.
    """
    return select_events_many(events, [time_s], mode, band)[0]


def select_events_many(
    events: Sequence[CalibrationEvent],
    times_s: ArrayLike,
    mode: str = "interpolate",
    band: int | None = None,
) -> list[list[tuple[CalibrationEvent, float]]]:
    """:func:`select_events` at each of ``times_s`` (UTC epoch seconds, shape (N,)): the
    events are sorted once for all the times. Returns N lists of (event, weight)."""
    if mode not in ("nearest", "interpolate"):
        raise InvalidInput(f"unknown calibration mode {mode!r} (nearest or interpolate)",
                           field="mode", exit_code=2)
    pool = sorted((e for e in events if band is None or e.band == band), key=lambda e: e.time_s)
    if not pool:
        raise InvalidInput("no calibration event" + ("" if band is None else f" for band {band}"),
                           field="blackbody")
    times = np.array([e.time_s for e in pool])
    out = []
    for t in np.asarray(times_s, dtype=np.float64).ravel().tolist():
        if mode == "nearest" or t <= times[0] or t >= times[-1] or len(pool) == 1:
            out.append([(pool[int(np.argmin(np.abs(times - t)))], 1.0)])
            continue
        j = int(np.searchsorted(times, t, side="right"))
        a, b = pool[j - 1], pool[j]
        w = (t - a.time_s) / (b.time_s - a.time_s)
        out.append([(a, 1.0)] if w == 0.0 else [(a, 1.0 - w), (b, w)])
    return out


def gain_offset_at(
    events: Sequence[CalibrationEvent],
    time_s: float,
    table: BandTable,
    mode: str = "interpolate",
    band: int | None = None,
    min_contrast_counts: float = DEFAULT_MIN_CONTRAST_COUNTS,
) -> GainOffset:
    """The per-pixel calibration at ``time_s``: one event's, or two events' blended linearly.

    Parameters
    ----------
    events, time_s, mode, band
        As for :func:`select_events`.
    table : BandTable
        The band (blackbody radiances).
    min_contrast_counts : float
        Degenerate-pixel threshold, counts.

    Returns
    -------
    GainOffset
        Interpolated gain and offset; a pixel is valid only if valid in every event used.
    """
    chosen = select_events(events, time_s, mode, band)
    return blend_gain_offsets([(ev.gain_offset(table, min_contrast_counts), w)
                               for ev, w in chosen])


def blend_gain_offsets(parts: Sequence[tuple[GainOffset, float]]) -> GainOffset:
    """Weighted sum of per-pixel calibrations (linear interpolation in time).

    Parameters
    ----------
    parts : sequence of (GainOffset, weight)
        Weights summing to 1 (as :func:`select_events` returns them).

    Returns
    -------
    GainOffset
        A pixel is valid only if valid in every part.
    """
    if len(parts) == 1:
        return parts[0][0]
    valid = np.logical_and.reduce([c.valid for c, _ in parts])
    gain = sum(w * c.gain for c, w in parts)
    offset = sum(w * c.offset for c, w in parts)
    return GainOffset(np.where(valid, gain, np.nan), np.where(valid, offset, np.nan), valid)
