"""What the chain reads from a survey folder: the validated survey and its logs, the
platform track, the calibration events, the survey's CRS, the identity of the inputs (the
mosaic grid, its cell size and the reference scan are chosen in
:mod:`clearfast_gis.mosaic.survey_grid`; the CRS, the markers and the fix summary in
:mod:`clearfast_gis.geometry.gnss`)."""

from __future__ import annotations

import json
from pathlib import Path

from clearfast_gis import __version__
from clearfast_gis.errors import InvalidInput, more_problems
from clearfast_gis.geometry.gnss import platform_track, smooth_static_track, survey_epsg
from clearfast_gis.mosaic.frames import SurveyContext
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.radiometry.stage import calibration_events
from clearfast_gis.registration import ConformalTransform


def input_key(survey, station_profile: str | Path | None = None) -> str:
    """Identity of the inputs (manifest, frame table, logs, station profile) and of the
    toolkit's version (the parameters key each stage's units,
    :mod:`clearfast_gis.pipeline.stages`)."""
    import hashlib

    h = hashlib.sha256()
    h.update(json.dumps(survey.manifest, sort_keys=True).encode())
    for key in ("frames", "blackbody_frames", "blackbody_log", "gnss", "weather", "soil"):
        if key not in survey.manifest["files"]:  # blackbodies of a radiometric camera
            continue
        p = survey.path(key)
        st = p.stat()
        h.update(f"{key}:{st.st_size}:{st.st_mtime_ns}".encode())
    if station_profile is not None:
        h.update(Path(station_profile).read_bytes())
    elif "station_profile" in survey.manifest["files"]:
        h.update(survey.path("station_profile").read_bytes())
    h.update(__version__.encode())
    return h.hexdigest()[:20]


def open_context(survey_path: str | Path, progress: Progress = NULL_PROGRESS,
                 station_profile: str | Path | None = None):
    """Read everything the chain needs from a survey folder, after validating it (the logs
    validation parsed are used, not parsed again); ``station_profile`` overrides the one
    ``survey.json`` names.

    Returns
    -------
    ctx : SurveyContext
    epsg : int
        The survey's UTM CRS.
    report : ValidationReport
        With the parsed logs (``report.logs``: GNSS, weather, soil, markers).
    """
    from clearfast_gis.survey import read_survey, validate_survey
    from clearfast_gis.survey.blackbody_check import check_blackbody_pairs
    from clearfast_gis.survey.station_profiles import read_station_profile

    report = validate_survey(survey_path, station_profile=station_profile)
    if not report.valid:
        first = report.problems[0].line()
        more = more_problems(len(report.problems), "run clearfast validate")
        raise InvalidInput(first + more)
    for w in report.warnings:
        progress.message(f"warning: {w.line()}")
    survey = read_survey(survey_path)
    survey.use_tables(report.logs.frames, report.logs.blackbody_frames)
    gnss = report.logs.gnss
    epsg = survey_epsg(survey, gnss)
    track = smooth_static_track(platform_track(
        gnss, epsg, float(survey.manifest["site"]["ground_altitude_m"]),
        source=survey.label("gnss")))
    if station_profile is not None:
        survey.use_station_profile(read_station_profile(station_profile))
    weather = report.logs.weather
    events = calibration_events(survey)
    check_blackbody_pairs(events, survey)
    ctx = SurveyContext(survey, survey.camera, track, events, weather,
                        [ConformalTransform.identity()] * len(survey.bands))
    return ctx, epsg, report
