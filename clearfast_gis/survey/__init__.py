"""The survey folder: JSON Schemas, readers, writers and the complete validation.

A survey folder holds ``survey.json`` (the manifest), ``mission.json``, the raw frames as
multi-page uint16 TIFFs with ``frames.csv``, blackbody frames and temperatures, the GNSS NMEA
log, the TOA5 weather log, the soil thermocouple log and surveyed markers
(``docs/contracts.md`` §2).
"""

from clearfast_gis.survey.logs import (
    BlackbodyLog,
    Markers,
    SoilLog,
    parse_blackbody_log,
    parse_markers,
    parse_soil_log,
    read_blackbody_log,
    read_markers,
    read_soil_log,
    write_blackbody_log,
    write_markers,
    write_soil_log,
)
from clearfast_gis.survey.manifest import (
    read_mission,
    read_survey_json,
    write_mission,
    write_survey_json,
)
from clearfast_gis.survey.model import (
    Band,
    BlackbodyEvent,
    Survey,
    read_blackbody_frames,
    read_survey,
)
from clearfast_gis.survey.nmea import (
    GnssLog,
    gga_sentence,
    gnss_sentences,
    nmea_checksum,
    parse_nmea,
    read_nmea,
    rmc_sentence,
    write_nmea,
    zda_sentence,
)
from clearfast_gis.survey.schema import load_schema, schema_errors
from clearfast_gis.survey.tables import (
    BlackbodyFramesTable,
    FramesTable,
    parse_blackbody_frames_table,
    parse_frames_table,
    read_blackbody_frames_table,
    read_frames_table,
    write_blackbody_frames_table,
    write_frames_table,
)
from clearfast_gis.survey.tiff import TiffInfo, read_tiff_stack, tiff_info, write_tiff_stack
from clearfast_gis.survey.toa5 import WeatherLog, parse_toa5, read_toa5, write_toa5
from clearfast_gis.survey.validate import Problem, ValidationReport, validate_survey

__all__ = [
    "Band", "BlackbodyEvent", "BlackbodyFramesTable", "BlackbodyLog", "FramesTable", "GnssLog",
    "Markers", "Problem", "SoilLog", "Survey", "TiffInfo", "ValidationReport", "WeatherLog",
    "gga_sentence", "gnss_sentences", "load_schema", "nmea_checksum",
    "parse_blackbody_frames_table", "parse_blackbody_log", "parse_frames_table", "parse_markers",
    "parse_nmea", "parse_soil_log",
    "parse_toa5", "read_blackbody_frames", "read_blackbody_frames_table", "read_blackbody_log",
    "read_frames_table", "read_markers", "read_mission", "read_nmea", "read_soil_log",
    "read_survey", "read_survey_json", "read_tiff_stack", "read_toa5", "rmc_sentence",
    "schema_errors", "tiff_info", "validate_survey", "write_blackbody_frames_table",
    "write_blackbody_log", "write_frames_table", "write_markers", "write_mission", "write_nmea",
    "write_soil_log", "write_survey_json", "write_tiff_stack", "write_toa5",
    "zda_sentence",
]
