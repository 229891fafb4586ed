"""Residual misregistration between a scan's mosaic and the reference scan (paper §3.4)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from clearfast_gis.export.cog import mosaic_stack
from clearfast_gis.parallel import thread_imap
from clearfast_gis.registration import register_conformal


@dataclass(frozen=True)
class TemporalResidual:
    """How far a mosaic still is from the reference after co-registration.

    Attributes
    ----------
    shift_px : float
        RMS displacement over the common footprint implied by the residual transform, mosaic
        pixels.
    angle_deg : float
        Residual rotation, degrees.
    converged : bool
        Whether the residual registration itself converged (if not, the residual is unknown
        and reported as NaN).
    metric : float
        Mutual information at the residual solution, nats.
    """

    shift_px: float
    angle_deg: float
    converged: bool
    metric: float


def temporal_transform(reference: np.ndarray, mosaic: np.ndarray, max_shift_px: float = 20.0):
    """Register a scan's whole mosaic to the reference scan's (rotation and shift, mutual
    information).

    Parameters
    ----------
    reference, mosaic : float32 (H, W)
        One band of the reference scan's mosaic and of the scan's mosaic on the same grid,
        NaN where empty.
    max_shift_px : float
        Search bound, mosaic pixels (rotation within 2 degrees).

    Returns
    -------
    ConformalTransform
        From reference pixel coordinates to the scan's (``converged`` False when the
        registration is not trustworthy).
    """
    return register_conformal(reference, mosaic, max_shift_px=max_shift_px, max_angle_deg=2.0,
                              bins=32)


def temporal_residual(reference: np.ndarray, mosaic: np.ndarray, max_shift_px: float = 20.0
                      ) -> TemporalResidual:
    """Register ``mosaic`` to ``reference`` once more and measure what is left.

    Parameters
    ----------
    reference, mosaic : float32 (H, W)
        One band of the reference scan's mosaic and of the scan's mosaic, NaN where empty.
    max_shift_px : float
        Search bound for the residual.

    Returns
    -------
    TemporalResidual
    """
    t = temporal_transform(reference, mosaic, max_shift_px)
    if not t.converged:
        return TemporalResidual(math.nan, math.nan, False, t.metric)
    both = np.isfinite(reference) & np.isfinite(mosaic)
    rows, cols = np.nonzero(both)
    if rows.size == 0:
        return TemporalResidual(math.nan, math.nan, False, t.metric)
    step = max(1, rows.size // 4000)
    pts = np.column_stack([cols[::step], rows[::step]]).astype(np.float64)
    d = t.apply(pts) - pts
    rms = float(np.sqrt(np.mean(np.sum(d * d, axis=1))))
    return TemporalResidual(rms, math.degrees(t.angle_rad), True, t.metric)


def temporal_residuals(products: Path, scan_records: dict[int, dict], ref: int,
                        measure: bool, decode_once: bool = False) -> np.ndarray:
    """Residual misregistration of every scan's mosaic against the reference scan's (pixels),
    stored in ``scan_records[scan]["residual_px"]`` (None for the reference itself or when it
    cannot be measured). Each mosaic is read once (with ``decode_once``, kept decoded for the
    stages after: :func:`clearfast_gis.export.cog.mosaic_stack`).

    Returns
    -------
    bool (H, W)
        Cells seen by at least one scan (band 0), for the footprint.
    """
    scans = sorted(scan_records)
    stack = mosaic_stack(products, scans, decode_once)
    reference = stack.scan(scans.index(ref))[0] if measure else None

    def residual(scan: int) -> tuple[float | None, np.ndarray]:
        mosaic = stack.scan(scans.index(scan))[0]
        if reference is None or scan == ref:
            return None, np.isfinite(mosaic)
        r = temporal_residual(reference, mosaic)
        return (None if math.isnan(r.shift_px) else r.shift_px), np.isfinite(mosaic)

    seen = None
    for scan, (value, finite) in zip(scans, thread_imap(residual, scans), strict=True):
        scan_records[scan]["residual_px"] = value
        scan_records[scan]["reference_scan"] = ref
        seen = finite if seen is None else seen | finite
    return seen
