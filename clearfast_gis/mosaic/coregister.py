"""Spatial co-registration of a projected frame with a reference (paper §5.2).

The geometric pose (RTK-DGPS position, pan/tilt angles) places a frame to within a few
centimetres to decimetres; mutual-information registration of the projected frame against the
mosaic built so far, or against the reference scan's mosaic, removes the rest. The correction
is bounded: a registration that fails or wants more than the bound keeps the geometric pose,
and the decision is recorded.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from clearfast_gis.mosaic.project import ProjectedFrame
from clearfast_gis.registration import (
    ConformalTransform,
    mutual_information,
    register_conformal,
    warp_conformal,
)

MIN_MI_GAIN = 0.03
"""A correction is applied only if it raises the mutual information over the predicted
placement by this fraction: the geometric pose (RTK-DGPS, pan/tilt) is already good to a few
centimetres, and a weak optimum in a low-contrast window must not move a frame."""


@dataclass(frozen=True)
class FrameCorrection:
    """The registration correction applied to one projected frame.

    Attributes
    ----------
    dx_m, dy_m : float
        Shift of the frame on the ground applied by the correction (east, north), metres.
    angle_deg : float
        Rotation applied, degrees.
    applied : bool
        False when the geometric pose was kept.
    reason : str
        ``ok``, ``no_overlap``, ``not_converged``, ``no_gain`` (no clear improvement of the
        mutual information over the predicted placement), ``beyond_bound`` or ``disabled``.
    metric : float
        Mutual information at the solution (nats), NaN if not registered.
    """

    dx_m: float = 0.0
    dy_m: float = 0.0
    angle_deg: float = 0.0
    applied: bool = False
    reason: str = "disabled"
    metric: float = math.nan


def _band0(values: np.ndarray) -> np.ndarray:
    return values[0] if values.ndim == 3 else values


def _mi_after(ref: np.ndarray, mov: np.ndarray, t: ConformalTransform) -> float:
    """Mutual information (nats) of ``ref`` and ``mov`` resampled by ``t`` on their overlap."""
    warped = warp_conformal(mov, t, ref.shape)
    both = np.isfinite(ref) & np.isfinite(warped)
    if both.sum() < 64:
        return 0.0
    return float(mutual_information(ref, warped, mask=both, bins=24))


def measure_correction(projected: ProjectedFrame, reference: np.ndarray, pixel_size_m: float,
                       max_shift_m: float, max_angle_deg: float = 2.0,
                       init: ConformalTransform | None = None,
                       min_overlap_frac: float = 0.15, max_samples: int | None = None,
                       ) -> tuple[FrameCorrection, ConformalTransform | None]:
    """The correction that aligns a projected frame to reference values under its window,
    without applying it (the attitude ties want only the displacement; see
    :func:`coregister_projected` for the parameters).

    Returns
    -------
    correction : FrameCorrection
    transform : ConformalTransform or None
        The transform to apply (maps window cells to the projected frame's cells); None when
        the geometric pose is kept.
    """
    ref = _band0(reference)
    mov = _band0(projected.values)
    valid = projected.valid
    overlap = valid & np.isfinite(ref)
    if overlap.sum() < max(64, min_overlap_frac * valid.sum()):
        return FrameCorrection(reason="no_overlap"), None
    h, w = ref.shape
    centre = ((w - 1) / 2.0, (h - 1) / 2.0)
    start = None if init is None else init.with_center(centre)
    budget = {} if max_samples is None else {"max_samples": max_samples,
                                             "polish_samples": max_samples}
    t = register_conformal(ref, mov, max_shift_px=max_shift_m / pixel_size_m,
                           max_angle_deg=max_angle_deg, init=start, bins=24, **budget)
    if not t.converged:
        return FrameCorrection(reason="not_converged", metric=t.metric), None
    base_t = start if start is not None else ConformalTransform.identity(centre)
    mi_base = _mi_after(ref, mov, base_t)
    mi_new = _mi_after(ref, mov, t)
    if not mi_new > mi_base * (1.0 + MIN_MI_GAIN):
        return FrameCorrection(reason="no_gain", metric=mi_new), None
    # ground displacement of the window centre: content at fixed x comes from moving T(x)
    moved = t.apply(np.array([centre]))[0]
    du, dv = centre[0] - moved[0], centre[1] - moved[1]
    dx, dy = du * pixel_size_m, -dv * pixel_size_m
    base = (0.0, 0.0) if init is None else (-init.tx_px * pixel_size_m,
                                            init.ty_px * pixel_size_m)
    if math.hypot(dx - base[0], dy - base[1]) > max_shift_m * 1.0001:
        return FrameCorrection(reason="beyond_bound", metric=t.metric), None
    return FrameCorrection(dx, dy, -math.degrees(t.angle_rad), True, "ok", t.metric), t


def coregister_projected(projected: ProjectedFrame, reference: np.ndarray, pixel_size_m: float,
                         max_shift_m: float, max_angle_deg: float = 2.0,
                         init: ConformalTransform | None = None,
                         min_overlap_frac: float = 0.15, max_samples: int | None = None,
                         ) -> tuple[ProjectedFrame, FrameCorrection, ConformalTransform | None]:
    """Align a projected frame to reference values under its window.

    Parameters
    ----------
    projected : ProjectedFrame
        The frame on its window of the mosaic grid.
    reference : float32 (B, h, w) or (h, w)
        Reference values (mosaic so far or reference scan) under the same window, NaN where
        empty.
    pixel_size_m : float
        Mosaic cell size, metres.
    max_shift_m, max_angle_deg : float
        Bounds of the correction around ``init`` (identity when None).
    init : ConformalTransform, optional
        Predicted correction (e.g. from the previous scan at the same position).
    min_overlap_frac : float
        Fraction of the frame's cells that must overlap the reference to try.
    max_samples : int, optional
        Samples of the registration at every level, final polish included (default: those
        of :func:`clearfast_gis.registration.register_conformal`).

    Returns
    -------
    corrected : ProjectedFrame
        The frame warped by the correction (the input when not applied).
    correction : FrameCorrection
    transform : ConformalTransform or None
        The transform applied (maps window cells to the projected frame's cells).
    """
    corr, t = measure_correction(projected, reference, pixel_size_m, max_shift_m,
                                 max_angle_deg, init, min_overlap_frac, max_samples)
    if t is None:
        return projected, corr, None
    h, w = _band0(reference).shape
    values = np.stack([warp_conformal(b, t, (h, w)) for b in projected.values])
    incidence = warp_conformal(projected.incidence_deg, t, (h, w))
    values[:, ~np.isfinite(incidence)] = np.nan
    corrected = ProjectedFrame(values.astype(np.float32), incidence.astype(np.float32),
                               projected.window)
    return corrected, corr, t
