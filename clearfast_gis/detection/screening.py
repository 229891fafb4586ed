"""What cannot be a mine: detections set aside from the suspects as ``candidates``.

A detection is set aside, with the first reason that applies (``set_aside_reason``), when

- its detected blob covers less than a disc of the smallest expected mine footprint
  (:data:`MIN_DIAMETER_M`, 6 cm: the lower end of the AP range of the class cue; 28 cm2),
  or its half-maximum thermal footprint is narrower than that (a 10.4 cm M2A4 comes out at
  9.5-12 cm, its blob at 70-180 cm2). The one- to six-cell blobs of texture (4-24 cm2 on a
  2 cm grid) end here;
- it is larger than the largest expected mine footprint (:data:`MAX_DIAMETER_M`, 1.5 times
  the upper end of the AT range): vegetation and disturbed-soil patches;
- fewer than :data:`MIN_SCANS` scans support it (its polarity was seen in one scan only): a
  buried object's contrast returns every day and night, a glint or a passing shadow does not.
  Not three: under the drifting lift (demo, seed 0) two AP mines at 2 and 3 cm are supported
  by 2 of the 6 scans only.

Candidates stay available to analysts in their own layer; they are not ranked.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from clearfast_gis.detection.classify import AP_DIAMETER_M, AT_DIAMETER_M

MIN_DIAMETER_M = AP_DIAMETER_M[0]
"""Smallest thermal footprint diameter of a suspect, m."""

MAX_DIAMETER_M = 1.5 * AT_DIAMETER_M[1]
"""Largest thermal footprint diameter of a suspect, m."""

MIN_SCANS = 2
"""Fewest supporting scans of a suspect (with a single image, N = 1, the rule is off)."""


def _number(value) -> float:
    """A record's numeric field as float (NaN when missing)."""
    return math.nan if value is None else float(value)


def set_aside_reason(record: Mapping, n_images: int) -> str | None:
    """Why a detection cannot be a mine, or None when it stays a suspect.

    Parameters
    ----------
    record : mapping
        Suspect attributes: ``area_m2`` (blob, m2), ``diameter_m`` (half-maximum footprint,
        m) and ``n_scans``.
    n_images : int
        Scans in the survey (the scan rule applies from :data:`MIN_SCANS` scans on).
    """
    area = _number(record.get("area_m2"))
    min_area = math.pi * (0.5 * MIN_DIAMETER_M) ** 2
    if math.isfinite(area) and area < min_area:
        return (f"blob of {1e4 * area:.0f} cm2, smaller than the smallest mine "
                f"({1e4 * min_area:.0f} cm2)")
    d = _number(record.get("diameter_m"))
    if math.isfinite(d) and d < MIN_DIAMETER_M:
        return (f"footprint {100 * d:.1f} cm across, smaller than the smallest mine "
                f"({100 * MIN_DIAMETER_M:.0f} cm)")
    if math.isfinite(d) and d > MAX_DIAMETER_M:
        return (f"footprint {100 * d:.0f} cm across, larger than the largest mine "
                f"({100 * MAX_DIAMETER_M:.0f} cm)")
    n = int(record.get("n_scans") or 0)
    if n_images >= MIN_SCANS and n < MIN_SCANS:
        return f"seen in {n} of {n_images} scans (fewer than {MIN_SCANS})"
    return None


def screen(records: list[dict], n_images: int) -> tuple[list[dict], list[dict]]:
    """Split detection records into suspects and candidates (with ``set_aside_reason``).

    Returns
    -------
    suspects, candidates : list of dict
        In the input order; candidates carry a text ``set_aside_reason``.
    """
    suspects, candidates = [], []
    for rec in records:
        why = set_aside_reason(rec, n_images)
        if why is None:
            suspects.append(rec)
        else:
            candidates.append({**rec, "set_aside_reason": why})
    return suspects, candidates
