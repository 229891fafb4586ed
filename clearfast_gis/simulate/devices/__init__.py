"""Device simulators: the field instruments' serial protocols, driven by the digital twin.

Each simulator is a protocol engine (bytes in, bytes due out) served on a pseudo-terminal by
:class:`~clearfast_gis.acquire.ptydevice.PtyDevice`, so that ``clearfast acquire`` and the
tests run the real drivers through real terminals:

- :class:`SimulatedGnss`: RTK-DGPS receiver, GGA + RMC + ZDA every epoch of the twin's track;
- :class:`SimulatedWeatherStation`: datalogger answering ``GET <record>`` polls (TOA5 lines);
- :class:`SimulatedTemperatureLogger`: thermocouple logger pushing ``T`` (soil) and ``B``
  (blackbody sensors) lines;
- the pan/tilt unit is :class:`~clearfast_gis.acquire.simulated.SimulatedPtu` on the twin clock;
- :class:`TwinCamera`: renders frames of the twin's scene (or blackbodies) at the twin time and
  the pan/tilt unit's true pose, behind the camera interface
  (:class:`~clearfast_gis.acquire.camera.Camera`), shared through a drop folder;
- :class:`DeviceRig`: all of them from one twin, with a ports file and scheduled faults
  (``clearfast simulate-devices``).

All run on a :class:`TwinClock`: scene UTC advancing ``time_scale`` times faster than real time.
"""

from clearfast_gis.simulate.devices.camera import TwinCamera
from clearfast_gis.simulate.devices.clock import TwinClock
from clearfast_gis.simulate.devices.gnss import SimulatedGnss
from clearfast_gis.simulate.devices.rig import DeviceRig, Fault, parse_fault
from clearfast_gis.simulate.devices.scheduled import ScheduledLines
from clearfast_gis.simulate.devices.templogger import SimulatedTemperatureLogger
from clearfast_gis.simulate.devices.weather import SimulatedWeatherStation

__all__ = ["DeviceRig", "Fault", "ScheduledLines", "SimulatedGnss",
           "SimulatedTemperatureLogger", "SimulatedWeatherStation", "TwinCamera", "TwinClock",
           "parse_fault"]
