"""The survey's mosaic grid and the choices it rests on: the cell size and the reference scan."""

from __future__ import annotations

import numpy as np

from clearfast_gis.geometry.projection import frame_footprints
from clearfast_gis.mosaic.frames import SurveyContext, frame_poses, scan_times
from clearfast_gis.mosaic.grid import mosaic_grid

MIN_DEFAULT_PIXEL_M = 0.02
"""Finest default mosaic cell, metres: five cells across the smallest AP mine (10.4 cm)."""


def pixel_size(survey, chosen_m: float | None = None) -> float:
    """Mosaic cell size, metres: ``chosen_m`` (the option), else the mission's mean
    across-track ground resolution, not finer than :data:`MIN_DEFAULT_PIXEL_M` (finer cells
    cost memory and time without helping the detection of mines; frames are low-pass
    filtered to the cell size)."""
    if chosen_m:
        return float(chosen_m)
    res = survey.mission.get("ground_resolution_m") or {}
    lo, hi = res.get("across_min"), res.get("across_max")
    if lo and hi:
        return max(MIN_DEFAULT_PIXEL_M, round(0.5 * (float(lo) + float(hi)), 3))
    return MIN_DEFAULT_PIXEL_M


def reference_scan(survey, chosen: int | None = None) -> int:
    """The reference scan: ``chosen`` (the option), or the scan nearest local solar noon."""
    if chosen is not None:
        return int(chosen)
    from clearfast_gis.thermal import sun_times

    site = survey.manifest["site"]
    scans = sorted(int(s) for s in survey.scans)
    times = np.array([scan_times(survey, s)[1] for s in scans])
    noon = np.array([sun_times(float(site["latitude_deg"]), float(site["longitude_deg"]),
                               float(t))[1] for t in times])
    return scans[int(np.argmin(np.abs(times - noon)))]


def mosaic_grid_for(ctx: SurveyContext, epsg: int, pixel_size_m: float, reference: int):
    """The survey's mosaic grid (CRS ``epsg``, cells of ``pixel_size_m`` metres): the ground
    footprints of the reference scan's frames, clipped to the mission's area (plus 1 m) when
    they reach it."""
    survey = ctx.survey
    fr = survey.frames
    rows = survey.scan_rows(reference, 0)
    fps = frame_footprints(ctx.camera, frame_poses(ctx, fr.time_s[rows], fr.pan_deg[rows],
                                                   fr.tilt_deg[rows]), max_range_m=60.0)
    area = survey.mission.get("area")
    clip = None
    if area and len(area) == 4:
        xmin, ymin, xmax, ymax = (float(a) for a in area)
        margin = 1.0
        clip = (xmin - margin, ymin - margin, xmax + margin, ymax + margin)
        import shapely

        if not shapely.box(*clip).intersects(shapely.unary_union(fps)):
            clip = None
    return mosaic_grid(fps, pixel_size_m, epsg, clip_to=clip)
