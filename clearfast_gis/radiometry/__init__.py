"""Radiometry: band Planck integral and tables, two-blackbody calibration, atmospheric
correction and apparent temperature (paper sections 3.3, 3.5, 3.6; Eq. 1, 2, 4, 5).

Everything here is a pure function of numpy arrays; the survey-reading glue of the calibration
stage is :mod:`clearfast_gis.radiometry.stage`.
"""

from clearfast_gis.radiometry.apparent import raw_to_apparent
from clearfast_gis.radiometry.atmosphere import (
    atmospheric_transmittance,
    correct_atmosphere,
    observed_radiance,
    path_radiance,
    water_vapour_content,
)
from clearfast_gis.radiometry.calibration import (
    DEFAULT_MIN_CONTRAST_COUNTS,
    CalibrationEvent,
    GainOffset,
    apply_gain_offset,
    blackbody_temperature_at,
    blend_gain_offsets,
    calibrate_two_point,
    event_from_frames,
    gain_offset_at,
    gain_offset_two_point,
    select_events,
)
from clearfast_gis.radiometry.planck import (
    adaptive_simpson,
    band_radiance,
    band_radiance_derivative,
    band_radiance_quad,
    band_temperature,
    spectral_radiance,
)
from clearfast_gis.radiometry.surface import surface_leaving_radiance
from clearfast_gis.radiometry.table import BandTable, apparent_temperature_paper, paper_table

__all__ = [
    "DEFAULT_MIN_CONTRAST_COUNTS",
    "BandTable",
    "CalibrationEvent",
    "GainOffset",
    "adaptive_simpson",
    "apparent_temperature_paper",
    "apply_gain_offset",
    "atmospheric_transmittance",
    "band_radiance",
    "band_radiance_derivative",
    "band_radiance_quad",
    "band_temperature",
    "blackbody_temperature_at",
    "blend_gain_offsets",
    "calibrate_two_point",
    "correct_atmosphere",
    "event_from_frames",
    "gain_offset_at",
    "gain_offset_two_point",
    "observed_radiance",
    "paper_table",
    "path_radiance",
    "raw_to_apparent",
    "select_events",
    "spectral_radiance",
    "surface_leaving_radiance",
    "water_vapour_content",
]
