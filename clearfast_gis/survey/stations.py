"""Real station files in, typed tables in canonical units out: the public entry points.

:func:`read_station_table` reads a weather station's TOA5 table the way the whole chain does
(``validate``, ``process``, ``acquire``): columns by name through a station profile and
Campbell's standard names, values converted to deg C, %, hPa, m/s, W/m^2 and mm.
:func:`survey_station_profile` finds the profile of a survey folder (``survey.json``
``files.station_profile``, or a file given on the command line).
"""

from __future__ import annotations

import os
from pathlib import Path

from clearfast_gis.survey._text import read_text
from clearfast_gis.survey.manifest import resolve_inside
from clearfast_gis.survey.station_profiles import (
    WEATHER_REQUIRED,
    StationProfile,
    read_station_profile,
)
from clearfast_gis.survey.toa5 import StationTable, parse_weather_table

#: ``survey.json`` ``files`` key of a survey's station profile
PROFILE_KEY = "station_profile"

#: file name of the station profile ``acquire`` copies into the survey folder
PROFILE_NAME = "station_profile.json"


def read_station_table(path: str | os.PathLike,
                       profile: StationProfile | str | os.PathLike | None = None,
                       label: str | None = None,
                       required: tuple[str, ...] = WEATHER_REQUIRED) -> StationTable:
    """A weather station's TOA5 table as a :class:`~clearfast_gis.survey.toa5.StationTable`.

    Parameters
    ----------
    path : path
        The TOA5 file.
    profile : StationProfile or path, optional
        The station profile (object or JSON file); None uses Campbell's standard names only.
    label : str, optional
        File name for messages (default ``path``).
    required : tuple of str
        Quantities that must be found (default: air temperature, humidity, pressure, wind,
        short-wave; pass fewer to read a partial table, e.g. to force a simulation).

    Returns
    -------
    StationTable
        ``.weather`` (a ``WeatherLog``: ``time_s`` UTC epoch seconds, ``air_temp_c`` deg C,
        ``rh_pct`` %, ``pressure_hpa`` hPa, ``wind_ms`` m/s, ``solar_wm2`` and ``sky_lw_wm2``
        W/m^2, ``rain_mm`` mm, all (T,), NaN where missing or not logged), ``.columns``
        (where each quantity came from), ``.lines`` (file line of each record) and
        ``.findings(altitude_m)`` (plausibility).

    Raises
    ------
    InvalidInput
        One line naming the file, line and field (see
        :func:`~clearfast_gis.survey.toa5.parse_weather_table`).
    """
    label = str(path) if label is None else label
    if profile is not None and not isinstance(profile, StationProfile):
        profile = read_station_profile(profile)
    return parse_weather_table(read_text(path, label), label, profile, required)


def survey_station_profile(root: str | os.PathLike, manifest: dict,
                           override: str | os.PathLike | None = None
                           ) -> StationProfile | None:
    """The station profile of a survey: ``override`` (a file given on the command line) if
    given, else the file ``survey.json`` names in ``files.station_profile``, else None.

    Raises
    ------
    InvalidInput
        For a profile file that is missing or invalid (naming it and the field).
    """
    if override is not None:
        return read_station_profile(override)
    files = manifest.get("files") if isinstance(manifest, dict) else None
    rel = files.get(PROFILE_KEY) if isinstance(files, dict) else None
    if not isinstance(rel, str):
        return None
    path = resolve_inside(Path(root), rel, "survey.json", f"files.{PROFILE_KEY}")
    return read_station_profile(path, rel)
