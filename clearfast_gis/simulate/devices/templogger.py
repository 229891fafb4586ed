"""Simulated thermocouple logger: soil (``T``) and blackbody sensor (``B``) lines."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from clearfast_gis.simulate.devices.scheduled import ScheduledLines
from clearfast_gis.survey.logs import BlackbodyLog, SoilLog
from clearfast_gis.timeutil import format_utc


def _values(temps_c: np.ndarray) -> str:
    return ",".join("NAN" if not math.isfinite(v) else f"{v:.3f}" for v in map(float, temps_c))


class SimulatedTemperatureLogger(ScheduledLines):
    """A logger pushing ``T,<time>,<t1>,...`` for every soil record and
    ``B,<time>,<bb1>,<bb2>`` for every blackbody record, at the records' scene times (degrees
    C, 3 decimals, CR LF). The soil channels are in the soil log's depth order.

    Parameters
    ----------
    soil : SoilLog
        Soil temperatures (every 10 min in the twin).
    blackbody : BlackbodyLog, optional
        Blackbody sensor temperatures (every minute).
    clock : callable
        Scene clock, UTC epoch seconds.
    """

    def __init__(self, soil: SoilLog, blackbody: BlackbodyLog | None,
                 clock: Callable[[], float]) -> None:
        rows = [(float(t), f"T,{format_utc(float(t), 'seconds')},{_values(soil.temp_c[k])}")
                for k, t in enumerate(soil.time_s)]
        if blackbody is not None:
            rows += [(float(t), f"B,{format_utc(float(t), 'seconds')},"
                      f"{_values(np.array([blackbody.bb1_c[k], blackbody.bb2_c[k]]))}")
                     for k, t in enumerate(blackbody.time_s)]
        rows.sort(key=lambda r: r[0])
        self.lines = [(text + "\r\n").encode("ascii") for _, text in rows]
        super().__init__(np.array([r[0] for r in rows]), self.lines.__getitem__, clock)
