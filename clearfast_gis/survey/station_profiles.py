"""Station profiles: a logger's own column names and units mapped to the chain's quantities.

A Campbell Scientific TOA5 table names its columns after the station's program
(``AirT_C_Avg``, ``BP_mbar_Avg``, ``WS_ms_S_WVT``...) and states their units on its third
line (``Deg C``, ``mbar``, ``meters/second``, ``°F``, ``inHg``...). This module finds each
quantity the chain uses by name:

1. the columns of a *station profile* (``clearfast_gis/schemas/station_profile.schema.json``,
   :func:`read_station_profile`), then
2. the names of Campbell's standard sensor programs (:data:`KNOWN_COLUMNS`: ClimaVUE50,
   CS215, HMP155, CNR4, SP-110/SP-Lite, WXT536, TE525 and the toolkit's own names),

and converts every value to the quantity's canonical unit with the small table
:data:`UNITS` (the unit of a profile entry, else the file's units row). Nothing is mapped
by position: a quantity not found by name is missing, and one error lists every missing
quantity with the columns the file has and how to write a profile.
"""

from __future__ import annotations

import os
from dataclasses import dataclass

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey._text import read_text

#: quantity -> (canonical unit, unit dimension, human name)
QUANTITIES: dict[str, tuple[str, str, str]] = {
    "air_temp_c": ("deg C", "temperature", "air temperature"),
    "rh_pct": ("%", "fraction", "relative humidity"),
    "pressure_hpa": ("hPa", "pressure", "barometric pressure"),
    "wind_ms": ("m/s", "speed", "wind speed"),
    "solar_wm2": ("W/m^2", "irradiance", "global solar irradiance (short-wave down)"),
    "sky_lw_wm2": ("W/m^2", "irradiance", "sky long-wave irradiance (pyrgeometer, down)"),
    "rain_mm": ("mm", "length", "precipitation per record"),
}

#: the dimension of every quantity of a station table (weather and soil)
DIMENSIONS = {**{q: v[1] for q, v in QUANTITIES.items()}, "soil_temp_c": "temperature"}

#: quantities a weather table must provide (sky long-wave is estimated when absent, rain is
#: informative)
WEATHER_REQUIRED = ("air_temp_c", "rh_pct", "pressure_hpa", "wind_ms", "solar_wm2")

#: unit spellings (lower case, spaces collapsed) -> (dimension, scale, offset): canonical
#: value = scale * value + offset
UNITS: dict[str, tuple[str, float, float]] = {}


def _units(dimension: str, scale: float, offset: float, *names: str) -> None:
    for n in names:
        UNITS[n] = (dimension, scale, offset)


_units("temperature", 1.0, 0.0, "deg c", "degc", "°c", "c", "degree c", "degrees c",
       "celsius", "deg_c", "degc.")
_units("temperature", 5.0 / 9.0, -32.0 * 5.0 / 9.0, "deg f", "degf", "°f", "f", "degree f",
       "degrees f", "fahrenheit", "deg_f")
_units("temperature", 1.0, -273.15, "k", "kelvin", "deg k", "degk")
_units("fraction", 1.0, 0.0, "%", "percent", "%rh", "% rh", "pct")
_units("pressure", 1.0, 0.0, "hpa", "mbar", "mb", "millibar", "millibars")
_units("pressure", 10.0, 0.0, "kpa")
_units("pressure", 0.01, 0.0, "pa")
_units("pressure", 33.8638866667, 0.0, "inhg", "in hg", "inches hg")
_units("pressure", 1.33322387415, 0.0, "mmhg", "mm hg", "torr")
_units("speed", 1.0, 0.0, "m/s", "meters/second", "metres/second", "m s-1", "ms-1", "m s^-1",
       "meter/second", "mps")
_units("speed", 1.0 / 3.6, 0.0, "km/h", "kph", "km/hr", "kilometers/hour", "km h-1")
_units("speed", 1852.0 / 3600.0, 0.0, "knots", "knot", "kn", "kt", "kts")
_units("speed", 0.44704, 0.0, "mph", "miles/hour", "mi/h")
_units("irradiance", 1.0, 0.0, "w/m^2", "w/m2", "w m-2", "w/m²", "w m^-2", "w/sq m")
_units("irradiance", 1000.0, 0.0, "kw/m^2", "kw/m2", "kw m-2", "kw/m²")
_units("length", 1.0, 0.0, "mm", "millimeters", "millimetres")
_units("length", 25.4, 0.0, "in", "inch", "inches")

#: the names Campbell's standard programs give each quantity (Short Cut and the sensor
#: manuals' example programs), in order of preference; matched without regard to case
KNOWN_COLUMNS: dict[str, tuple[str, ...]] = {
    "air_temp_c": ("AirTC_Avg", "AirT_C_Avg", "AirTC", "AirT_C", "AirTF_Avg", "AirTF",
                   "T107_C_Avg", "Temp_C_Avg", "Ta_Avg", "AirTemp_Avg", "AirT_Avg"),
    "rh_pct": ("RH_Avg", "RH", "RelHumid_Avg", "RelHumid", "RH_percent_Avg", "Ua_Avg"),
    "pressure_hpa": ("BP_hPa_Avg", "BP_mbar_Avg", "BP_mbar", "BP_hPa", "BP_kPa_Avg", "BP_kPa",
                     "BP_inHg_Avg", "BP_inHg", "BP_mmHg_Avg", "Pa_Avg", "BaromPres_Avg"),
    "wind_ms": ("WS_ms_Avg", "WS_ms_S_WVT", "WS_ms", "WS_kph_Avg", "WS_kph_S_WVT",
                "WS_mph_Avg", "WS_mph_S_WVT", "WS_knots_Avg", "WS_knots_S_WVT", "Sm_Avg",
                "WindSpd_Avg", "WindSpd_m_s_Avg"),
    "solar_wm2": ("SlrW_Avg", "SlrFD_W_Avg", "SlrkW_Avg", "SR_Avg", "SW_in_Avg", "SWin_Avg",
                  "short_up_Avg", "SUp_Avg", "IncomingSW_Avg", "Rad_SWin_Avg"),
    "sky_lw_wm2": ("IRSky_Avg", "LW_in_Avg", "LWin_Avg", "long_up_corr_Avg", "LUpCo_Avg",
                   "IncomingLW_Avg", "Rad_LWin_Avg"),
    "rain_mm": ("Rain_mm_Tot", "Rain_in_Tot", "Rain_Tot", "Rain_mm", "Rc_Tot"),
}

PROFILE_FORMAT = "clearfast-station-profile"
PROFILE_HELP = ("map them in a station profile (JSON, schema "
                "clearfast_gis/schemas/station_profile.schema.json, docs/acquire.md): "
                '{"format": "clearfast-station-profile", "format_version": 1, "columns": '
                '{"air_temp_c": {"column": "<name>", "unit": "deg C"}, ...}}, given with '
                "--station-profile FILE or named in survey.json files.station_profile")


@dataclass(frozen=True)
class ColumnMap:
    """Where a quantity comes from in a table.

    Attributes
    ----------
    quantity : str
        Key of :data:`QUANTITIES`.
    column : str
        The file's column name.
    index : int
        Position of that column in the file's field-name line (0-based).
    unit : str
        Unit of the column's values (as written in the profile or the units row).
    scale, offset : float
        canonical = scale * value + offset.
    """

    quantity: str
    column: str
    index: int
    unit: str
    scale: float
    offset: float


@dataclass(frozen=True)
class StationProfile:
    """A station profile (see the schema): columns by quantity, with optional units, the
    field names of a station that sends no header, and soil thermocouple depths.

    Attributes
    ----------
    name : str
    columns : dict
        quantity -> (column name, unit or None: the file's units row).
    header : tuple of str
        Field names, in order, of data lines sent without a TOA5 header (``acquire``).
    soil_columns : dict
        column name -> depth below the surface, metres.
    soil_unit : str or None
        Unit of the soil temperature columns (None: the units row).
    source : str
        File name for messages.
    """

    name: str = ""
    columns: dict[str, tuple[str, str | None]] | None = None
    header: tuple[str, ...] = ()
    soil_columns: dict[str, float] | None = None
    soil_unit: str | None = None
    source: str = ""


def unit_conversion(unit: str, quantity: str, label: str, field: str) -> tuple[float, float]:
    """``(scale, offset)`` turning values in ``unit`` into the canonical unit of ``quantity``.

    Raises
    ------
    InvalidInput
        For a unit that is not in :data:`UNITS` or of another dimension.
    """
    dim = DIMENSIONS[quantity]
    key = " ".join(str(unit).strip().lower().split())
    hit = UNITS.get(key)
    if hit is None or hit[0] != dim:
        known = sorted(k for k, v in UNITS.items() if v[0] == dim)
        raise InvalidInput(f"unit {unit!r} is not a {dim} unit this toolkit converts "
                           f"(known: {', '.join(known)})", label, field)
    return hit[1], hit[2]


def parse_station_profile(text: str, label: str = "station_profile.json") -> StationProfile:
    """Parse and check a station profile (JSON against ``station_profile.schema.json``).

    Raises
    ------
    InvalidInput
        Naming the field, for invalid JSON, a schema violation or an unknown unit.
    """
    from clearfast_gis.survey.manifest import manifest_problems, parse_json

    doc = parse_json(text, label)
    probs = manifest_problems(doc, "station_profile")
    if probs:
        fld, msg = probs[0]
        raise InvalidInput(msg, label, fld)
    cols: dict[str, tuple[str, str | None]] = {}
    for q, spec in (doc.get("columns") or {}).items():
        unit = spec.get("unit")
        if unit is not None:
            unit_conversion(unit, q, label, f"columns.{q}.unit")
        cols[q] = (spec["column"], unit)
    soil = doc.get("soil") or {}
    soil_unit = soil.get("unit")
    if soil_unit is not None:
        unit_conversion(soil_unit, "soil_temp_c", label, "soil.unit")
    depths = {d["column"]: float(d["depth_m"]) for d in soil.get("depths", [])}
    if len(set(depths.values())) != len(depths):
        raise InvalidInput("two thermocouples have the same depth", label, "soil.depths")
    return StationProfile(name=str(doc.get("name", "")), columns=cols,
                          header=tuple(doc.get("header", ())), soil_columns=depths or None,
                          soil_unit=soil_unit, source=label)


def read_station_profile(path: str | os.PathLike, label: str | None = None) -> StationProfile:
    """Read a station profile file (see :func:`parse_station_profile`)."""
    label = str(path) if label is None else label
    return parse_station_profile(read_text(path, label), label)


def map_columns(names: list[str], units: list[str], label: str,
                profile: StationProfile | None = None,
                required: tuple[str, ...] = WEATHER_REQUIRED) -> dict[str, ColumnMap]:
    """Find every quantity of :data:`QUANTITIES` among a table's column names.

    Parameters
    ----------
    names, units : list of str
        The field-name and units lines of the table (units may be shorter or empty).
    label : str
        File name for messages.
    profile : StationProfile, optional
        Its columns take precedence over the built-in names.
    required : tuple of str
        Quantities that must be found.

    Returns
    -------
    dict
        quantity -> :class:`ColumnMap`, for every quantity found.

    Raises
    ------
    InvalidInput
        One error listing every missing required quantity (and every column whose unit is
        unknown), the file's columns and how to write a profile.
    """
    lower = {n.strip().lower(): i for i, n in reversed(list(enumerate(names)))}
    found: dict[str, ColumnMap] = {}
    missing: list[str] = []
    bad_units: list[str] = []
    for q in QUANTITIES:
        spec = (profile.columns or {}).get(q) if profile is not None else None
        if spec is not None:
            i = lower.get(spec[0].strip().lower())
            if i is None:
                missing.append(f"{QUANTITIES[q][2]} ({q}: profile column {spec[0]!r} not in "
                               "the file)")
                continue
            unit = spec[1]
        else:
            i = next((lower[c.lower()] for c in KNOWN_COLUMNS[q] if c.lower() in lower), None)
            if i is None:
                if q in required:
                    missing.append(f"{QUANTITIES[q][2]} ({q}, e.g. {KNOWN_COLUMNS[q][0]})")
                continue
            unit = None
        if unit is None:
            unit = units[i].strip() if i < len(units) else ""
        try:
            scale, offset = unit_conversion(unit, q, label, "line 3")
        except InvalidInput as exc:
            bad_units.append(f"{names[i].strip()}: {exc.message}")
            continue
        found[q] = ColumnMap(q, names[i].strip(), i, unit, scale, offset)
    if missing:
        units_too = f"; {'; '.join(bad_units)}" if bad_units else ""
        raise InvalidInput(f"missing {', '.join(missing)}{units_too}; the file has columns "
                           f"{', '.join(n.strip() for n in names)}; {PROFILE_HELP}",
                           label, "line 2")
    if bad_units:
        raise InvalidInput(f"{'; '.join(bad_units)}; give the unit in a station profile "
                           '("columns": {"<quantity>": {"column": ..., "unit": ...}})',
                           label, "line 3")
    return found
