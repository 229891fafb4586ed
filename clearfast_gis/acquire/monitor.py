"""Pan/tilt unit monitor for ``clearfast log``: initialise the unit, then poll its position."""

from __future__ import annotations

import threading

from clearfast_gis.acquire.ptu import PanTiltUnit
from clearfast_gis.errors import ClearfastError


class PtuMonitor:
    """Polls a :class:`PanTiltUnit`'s read-back angles every ``interval_s`` seconds.

    Attributes
    ----------
    pan_deg, tilt_deg : float or None
        Latest read-back, degrees.
    n_polls : int
        Successful position queries.
    error : str or None
        One-line description of the error that ended :meth:`run`, if any.
    """

    kind = "ptu"

    def __init__(self, ptu: PanTiltUnit, interval_s: float = 1.0) -> None:
        self.ptu = ptu
        self.interval_s = float(interval_s)
        self.pan_deg: float | None = None
        self.tilt_deg: float | None = None
        self.n_polls = 0
        self.error: str | None = None
        self._thread: threading.Thread | None = None

    def run(self, stop: threading.Event) -> None:
        """Initialise the unit, then poll until ``stop`` is set or the unit fails."""
        try:
            self.ptu.initialize()
            while not stop.is_set():
                self.pan_deg, self.tilt_deg = self.ptu.position()
                self.n_polls += 1
                stop.wait(self.interval_s)
        except ClearfastError as exc:
            self.error = exc.one_line()

    def start(self, stop: threading.Event) -> threading.Thread:
        """Run :meth:`run` in a daemon thread and return it."""
        self._thread = threading.Thread(target=self.run, args=(stop,), daemon=True,
                                        name="clearfast-ptu")
        self._thread.start()
        return self._thread

    def status(self) -> dict:
        """A JSON-ready snapshot."""
        return {"port": self.ptu.name, "polls": self.n_polls, "pan_deg": self.pan_deg,
                "tilt_deg": self.tilt_deg, "error": self.error}

    def status_text(self) -> str:
        """Short status for a one-line display."""
        if self.pan_deg is None or self.tilt_deg is None:
            return "ptu no data"
        return f"ptu pan {self.pan_deg:.2f} tilt {self.tilt_deg:.2f}"
