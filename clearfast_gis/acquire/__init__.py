"""Field acquisition over serial ports: instrument drivers, survey clock, mission runner.

- :func:`run_acquisition` (``clearfast acquire``): a mission with every instrument into a
  survey folder, resumable.
- :class:`GnssLogger`: RTK-DGPS NMEA stream to ``gnss.nmea`` (raw, append-only); its RMC/ZDA
  time disciplines the survey clock (:class:`GnssClock`).
- :class:`PanTiltUnit`: FLIR PTU-style ASCII driver (``PP``/``TP``/``A``, resolution and limits
  from the unit, reconnection).
- :class:`WeatherStationLogger`: TOA5 records to ``weather.dat``, polled (``GET <record>``) or
  pushed.
- :class:`ThermocoupleLogger`: ``T`` (soil) and ``B`` (blackbody) lines to ``soil.csv`` and
  ``blackbody/temperatures.csv``.
- :class:`Camera`, :class:`Exposure`, :class:`DropFolderCamera`: the camera interface and its
  drop-folder adapter.
- :class:`MissionRunner`: stop-and-go execution of ``mission.json`` with the blackbody
  calibration each scan, every exposure staged at once (:class:`FrameStore`).
- :class:`SimulatedPtu`, :class:`PtyDevice`, :func:`pty_pair`, :class:`ManualClock`: test and
  dry-run doubles (the twin-driven simulators are in :mod:`clearfast_gis.simulate.devices`).

Ports are pyserial ports (``serial.Serial`` or any pyserial URL); see :func:`open_port`,
:func:`parse_port_spec` and :func:`read_ports_file`. Formats are those of
``docs/contracts.md`` §2, written with :mod:`clearfast_gis.survey`'s formats.
"""

from clearfast_gis.acquire.appendlog import AppendLog, LineSplitter
from clearfast_gis.acquire.camera import (
    Camera,
    CameraError,
    CameraTimeout,
    DropFolderCamera,
    DropFolderServer,
    Exposure,
    parse_camera_spec,
)
from clearfast_gis.acquire.clock import ClockError, GnssClock, HostClock
from clearfast_gis.acquire.framestore import Capture, FrameStore
from clearfast_gis.acquire.gnss import GnssFix, GnssLogger, classify_sentence
from clearfast_gis.acquire.linelogger import LineLogger
from clearfast_gis.acquire.mission import (
    Blackbodies,
    MissionResult,
    MissionRunner,
    event_tiff_name,
    scan_tiff_name,
)
from clearfast_gis.acquire.ports import (
    DEFAULT_BAUD,
    PortError,
    PortSpec,
    open_port,
    parse_port_spec,
    read_ports_file,
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
from clearfast_gis.acquire.ptydevice import PtyDevice, pty_pair
from clearfast_gis.acquire.session import AcquisitionConfig, run_acquisition
from clearfast_gis.acquire.simulated import ManualClock, SimulatedPtu, simulated_ptu_device
from clearfast_gis.acquire.soil import (
    DEFAULT_DEPTHS_M,
    ThermocoupleLogger,
    parse_thermocouple_line,
)
from clearfast_gis.acquire.station import StationSetup, read_setup
from clearfast_gis.acquire.weather import WeatherStationLogger, toa5_header, toa5_record_line

__all__ = [
    "DEFAULT_BAUD", "DEFAULT_DEPTHS_M", "AcquisitionConfig", "AppendLog", "Blackbodies",
    "Camera", "CameraError", "CameraTimeout", "Capture", "ClockError", "DropFolderCamera",
    "DropFolderServer", "Exposure", "FrameStore", "GnssClock", "GnssFix", "GnssLogger",
    "HostClock", "LineLogger", "LineSplitter", "ManualClock", "MissionResult", "MissionRunner",
    "PanTiltUnit", "PortError", "PortSpec", "PtuError", "PtuLimitError", "PtuProtocolError",
    "PtuReply", "PtuTimeout", "PtyDevice", "SimulatedPtu", "StationSetup",
    "ThermocoupleLogger", "WeatherStationLogger", "classify_sentence", "deg_to_steps",
    "event_tiff_name", "format_reply", "open_port", "parse_camera_spec", "parse_port_spec",
    "parse_reply", "parse_thermocouple_line", "pty_pair", "read_ports_file", "read_setup",
    "run_acquisition", "scan_tiff_name", "simulated_ptu_device", "steps_to_deg", "toa5_header",
    "toa5_record_line",
]
