"""Raw counts to apparent temperature: calibration, atmospheric correction, inverse Planck
(paper sections 3.3, 3.5 and 3.6, Eq. 1, 4 and 5), as one pure function of arrays."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.radiometry.atmosphere import correct_atmosphere
from clearfast_gis.radiometry.calibration import (
    DEFAULT_MIN_CONTRAST_COUNTS,
    CalibrationEvent,
    GainOffset,
    apply_gain_offset,
)
from clearfast_gis.radiometry.table import BandTable


def raw_to_apparent(
    raw: ArrayLike,
    calibration: GainOffset | CalibrationEvent,
    tau: ArrayLike,
    t_air_k: ArrayLike,
    table: BandTable,
    min_contrast_counts: float = DEFAULT_MIN_CONTRAST_COUNTS,
) -> np.ndarray:
    """Apparent temperature of raw frames.

    ``counts --Eq.1--> I_c --Eq.4--> I_surf = (I_c - (1 - tau) B(T_air)) / tau --Eq.5--> T_app``.

    Parameters
    ----------
    raw : array_like (..., H, W)
        Raw counts, e.g. one scan (P, H, W).
    calibration : GainOffset or CalibrationEvent
        Per-pixel calibration ((H, W) or (P, H, W) arrays), or an event to derive it from.
    tau : float or array_like
        Band transmittance of each pixel's path, broadcast against ``raw`` (scalar, (P, 1, 1)
        per frame or (P, H, W) per pixel).
    t_air_k : float or array_like
        Air temperature, kelvin, broadcast like ``tau``.
    table : BandTable
        The band.
    min_contrast_counts : float
        Degenerate-pixel threshold when ``calibration`` is an event.

    Returns
    -------
    ndarray of float32 (..., H, W)
        Apparent temperature, kelvin; NaN at uncalibrated pixels and outside the table's range.
    """
    if isinstance(calibration, CalibrationEvent):
        calibration = calibration.gain_offset(table, min_contrast_counts)
    radiance = apply_gain_offset(raw, calibration)
    surface = correct_atmosphere(radiance, tau, t_air_k, table)
    return table.temperature(surface, dtype=np.float32)
