"""Simulated RTK-DGPS receiver: GGA, RMC and ZDA sentences every epoch of a track."""

from __future__ import annotations

import math
import threading
from collections.abc import Callable

import numpy as np

from clearfast_gis.simulate.devices.scheduled import ScheduledLines
from clearfast_gis.survey.nmea import GnssLog, gga_sentence, rmc_sentence, zda_sentence


class SimulatedGnss(ScheduledLines):
    """A receiver streaming a :class:`~clearfast_gis.survey.nmea.GnssLog` as NMEA 0183.

    Each epoch gives ``$GPGGA``, ``$GPRMC`` and ``$GPZDA`` (CR LF ended), sent when the scene
    clock reaches the epoch. :meth:`lose_fix` degrades the fix from a scene time on (quality
    0: no position, RMC void; or 1: autonomous GPS, metre noise), as when the RTK base link
    drops or the antenna is shaded; the receiver's time keeps coming.

    Parameters
    ----------
    track : GnssLog
        Epochs (time, position, fix quality, satellites, HDOP).
    clock : callable
        Scene clock, UTC epoch seconds.
    """

    def __init__(self, track: GnssLog, clock: Callable[[], float]) -> None:
        self.track = track
        self._lost: list[tuple[float, float, int]] = []
        self._lock = threading.Lock()
        self._rng = np.random.default_rng(0)
        super().__init__(track.time_s, self._epoch, clock)

    def lose_fix(self, start_s: float, end_s: float, quality: int = 0) -> None:
        """Degrade epochs from ``start_s`` to ``end_s`` (scene UTC seconds) to ``quality``."""
        with self._lock:
            self._lost.append((float(start_s), float(end_s), int(quality)))

    def _quality(self, k: int, t: float) -> int:
        q = int(self.track.fix_quality[k])
        with self._lock:
            for a, b, lost in self._lost:
                if a <= t < b:
                    q = min(q, lost) if q > 0 else q
        return q

    def _epoch(self, k: int) -> bytes:
        tr = self.track
        t = float(tr.time_s[k])
        q = self._quality(k, t)
        lat, lon, alt = float(tr.lat_deg[k]), float(tr.lon_deg[k]), float(tr.alt_m[k])
        n_sats, hdop = int(tr.n_sats[k]), float(tr.hdop[k])
        if q == 0:
            lat = lon = alt = math.nan
            n_sats, hdop = min(n_sats, 3), 99.99
        elif q != int(tr.fix_quality[k]):  # autonomous: metre-level scatter
            d = self._rng.standard_normal(3) * np.array([1.5e-5, 1.5e-5, 3.0])
            lat, lon, alt = lat + d[0], lon + d[1], alt + d[2]
        hdop = hdop if math.isfinite(hdop) else 99.99
        lines = (gga_sentence(t, lat, lon, alt, q, n_sats, hdop),
                 rmc_sentence(t, lat, lon, valid=q > 0), zda_sentence(t))
        return "".join(s + "\r\n" for s in lines).encode("ascii")
