"""Field acquisition over serial ports: instrument loggers, pan/tilt driver, mission runner.

- :class:`GnssLogger`: RTK-DGPS NMEA stream to ``gnss.nmea`` (raw, append-only).
- :class:`WeatherStationLogger`: TOA5 records to ``weather.dat``.
- :class:`ThermocoupleLogger`: ``T,<time>,<t1>,...`` lines to ``soil.csv``.
- :class:`PanTiltUnit`: FLIR PTU-style ASCII driver (``PP``/``TP``/``A``).
- :class:`MissionRunner`: stop-and-go execution of ``mission.json`` into a survey folder.
- :class:`SimulatedPtu`, :func:`pty_pair`, :class:`ManualClock`: test and dry-run doubles.

Ports are pyserial ports (``serial.Serial`` or any pyserial URL); see
:func:`open_port` and :func:`parse_port_spec`. Formats are those of ``docs/contracts.md`` §2,
written with :mod:`clearfast_gis.survey`'s formats.
"""

from clearfast_gis.acquire.appendlog import AppendLog, LineSplitter
from clearfast_gis.acquire.gnss import GnssFix, GnssLogger, classify_sentence
from clearfast_gis.acquire.linelogger import LineLogger
from clearfast_gis.acquire.mission import MissionResult, MissionRunner, scan_tiff_name
from clearfast_gis.acquire.ports import (
    DEFAULT_BAUD,
    PortError,
    PortSpec,
    open_port,
    parse_port_spec,
)
from clearfast_gis.acquire.ptu import (
    PanTiltUnit,
    PtuError,
    PtuLimitError,
    PtuProtocolError,
    PtuReply,
    PtuTimeout,
    deg_to_steps,
    format_reply,
    parse_reply,
    steps_to_deg,
)
from clearfast_gis.acquire.simulated import (
    ManualClock,
    SimulatedPtu,
    pty_pair,
    simulated_ptu_device,
)
from clearfast_gis.acquire.soil import (
    DEFAULT_DEPTHS_M,
    ThermocoupleLogger,
    parse_thermocouple_line,
)
from clearfast_gis.acquire.weather import WeatherStationLogger, toa5_header, toa5_record_line

__all__ = [
    "DEFAULT_BAUD", "DEFAULT_DEPTHS_M", "AppendLog", "GnssFix", "GnssLogger", "LineLogger",
    "LineSplitter", "ManualClock", "MissionResult", "MissionRunner", "PanTiltUnit", "PortError",
    "PortSpec", "PtuError", "PtuLimitError", "PtuProtocolError", "PtuReply", "PtuTimeout",
    "SimulatedPtu",
    "ThermocoupleLogger", "WeatherStationLogger", "classify_sentence", "deg_to_steps",
    "format_reply", "open_port", "parse_port_spec", "parse_reply", "parse_thermocouple_line",
    "pty_pair", "scan_tiff_name", "simulated_ptu_device", "steps_to_deg", "toa5_header",
    "toa5_record_line",
]
