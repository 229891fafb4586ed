"""The one check of a survey that needs its blackbody images read: a usable blackbody pair at
every calibration event (run by the chain before any work, after validation,
:func:`clearfast_gis.survey.validate.validate_survey`)."""

from __future__ import annotations

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.timeutil import format_utc

MIN_BLACKBODY_DIFFERENCE_K = 1.0
"""Blackbodies closer than this in temperature give no usable two-point calibration (the
heated one runs ~10 K above the ambient one), kelvin."""


def check_blackbody_pairs(events, survey) -> None:
    """Refuse a degenerate blackbody pair (same temperature, or same counts everywhere).

    Parameters
    ----------
    events : list of CalibrationEvent, or CameraRadiometry (nothing to check)
        The survey's calibration events (:func:`clearfast_gis.radiometry.stage.
        calibration_events`: blackbody temperatures, kelvin, and mean counts per band).
    survey : Survey
        For the file names in the message.

    Raises
    ------
    InvalidInput
        Naming the blackbody log or frames table, the time and the band.
    """
    if not isinstance(events, list):  # a radiometric camera's own calibration
        return
    from clearfast_gis.radiometry.calibration import DEFAULT_MIN_CONTRAST_COUNTS

    for ev in events:
        when = format_utc(ev.time_s, "seconds")
        if not abs(ev.t_bb1_k - ev.t_bb2_k) >= MIN_BLACKBODY_DIFFERENCE_K:
            raise InvalidInput(
                f"degenerate blackbody pair at {when}: blackbodies 1 and 2 at "
                f"{ev.t_bb1_k - 273.15:.2f} and {ev.t_bb2_k - 273.15:.2f} C (they must differ "
                f"by >= {MIN_BLACKBODY_DIFFERENCE_K:g} K)", survey.label("blackbody_log"))
        contrast = float(np.nanmedian(np.abs(np.asarray(ev.bb1_mean, dtype=float)
                                             - np.asarray(ev.bb2_mean, dtype=float))))
        if not contrast >= DEFAULT_MIN_CONTRAST_COUNTS:
            raise InvalidInput(
                f"degenerate blackbody pair at {when} band {ev.band}: the images of "
                f"blackbodies 1 and 2 differ by {contrast:.1f} counts (median), below "
                f"{DEFAULT_MIN_CONTRAST_COUNTS:g}", survey.label("blackbody_frames"))
