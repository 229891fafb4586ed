"""The twin's thermal camera: frames rendered on request at the twin time and true pose.

:class:`TwinCamera` implements :class:`~clearfast_gis.acquire.camera.Camera`. Each
``capture()`` reads the twin clock and the pan/tilt unit's true angles, and renders every band
as the simulator does (ray trace of the truth grid, atmosphere, detector with its drifting
non-uniformity and noise), band ``b`` exposed ``b * band_interval_s`` after the trigger as a
filter wheel would. Pointed at a blackbody (within ``tolerance_deg`` of its pan/tilt
position) the frame is filled by the blackbody at its true temperature.

The surface temperature comes from the thermal runs on a regular time grid
(``grid_step_s``, 10 min); a frame sees the surface radiance interpolated linearly in time
between the radiance grids of the two grid times around its exposure, so the scene changes
smoothly during a scan (a grid is built once per step, about 0.2 s for the demo).
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from contextlib import AbstractContextManager

import numpy as np

from clearfast_gis.acquire.camera import Exposure
from clearfast_gis.acquire.mission import Blackbodies
from clearfast_gis.simulate.render import RadianceGrid, radiance_grid
from clearfast_gis.simulate.surface import surface_temperature_k, thermal_truth
from clearfast_gis.simulate.twin import Twin, stream


class TwinCamera:
    """The twin's camera (see the module docstring).

    Parameters
    ----------
    twin : Twin
        The digital twin.
    pointing : callable
        ``pointing() -> (pan_deg, tilt_deg)``: the pan/tilt unit's true angles now.
    clock : callable
        The twin clock, UTC epoch seconds.
    blackbodies : Blackbodies
        Where the calibration blackbodies are.
    tolerance_deg : float
        How close to a blackbody's position the frame is filled by it, degrees.
    grid_step_s : float
        Time step of the thermal truth and of the radiance grids, seconds.
    hold : callable, optional
        ``hold()`` -> a context manager during which the twin clock stands still (an exposure
        takes no scene time however long its rendering takes); default: none.

    Attributes
    ----------
    n_frames : int
        Exposures rendered.
    """

    def __init__(self, twin: Twin, pointing: Callable[[], tuple[float, float]],
                 clock: Callable[[], float], blackbodies: Blackbodies,
                 tolerance_deg: float = 2.0, grid_step_s: float = 600.0,
                 hold: Callable[[], AbstractContextManager] = contextlib.nullcontext) -> None:
        self.twin = twin
        self.pointing = pointing
        self.clock = clock
        self.blackbodies = blackbodies
        self.tolerance_deg = float(tolerance_deg)
        self.grid_step_s = float(grid_step_s)
        self.hold = hold
        times = twin.start_s + grid_step_s * np.arange(
            int(np.ceil((twin.end_s - twin.start_s) / grid_step_s)) + 1)
        self.truth = thermal_truth(twin.forcing, times, twin.objects, twin.ground)
        self.rng = stream(twin.seed, "camera")
        self.n_frames = 0
        self._grids: dict[int, list[RadianceGrid]] = {}

    def _grid(self, k: int) -> list[RadianceGrid]:
        """Radiance grids of every band at grid time ``k`` (index into the truth's times)."""
        k = int(np.clip(k, 0, self.truth.time_s.size - 1))
        if k not in self._grids:
            t = float(self.truth.time_s[k])
            temp_k = surface_temperature_k(self.twin.fields, self.truth, k)
            grids = []
            for b in range(self.twin.n_bands):
                l_surf, sky = self.twin.band_surface(temp_k, b, t)
                grids.append(radiance_grid(l_surf, self.twin.grid, sky))
            # scans move forward in time: keep this grid time and the one before
            self._grids = {j: g for j, g in self._grids.items() if j >= k - 1}
            self._grids[k] = grids
        return self._grids[k]

    def radiance_grids(self, band: int, time_s: float) -> list[tuple[RadianceGrid, float]]:
        """The band's radiance grids around ``time_s`` with their interpolation weights."""
        f = (time_s - self.twin.start_s) / self.grid_step_s
        k = int(np.floor(f))
        w = float(np.clip(f - k, 0.0, 1.0))
        if k < 0 or k + 1 >= self.truth.time_s.size or w == 0.0:
            return [(self._grid(k)[band], 1.0)]
        return [(self._grid(k)[band], 1.0 - w), (self._grid(k + 1)[band], w)]

    def blackbody_at(self, pan_deg: float, tilt_deg: float) -> int | None:
        """The blackbody (1 or 2) filling the view at these angles, or None."""
        for bb in (1, 2):
            p, t = self.blackbodies.position(bb)
            if abs(pan_deg - p) <= self.tolerance_deg and abs(tilt_deg - t) <= self.tolerance_deg:
                return bb
        return None

    def capture(self) -> Exposure:
        """Render one exposure of every band (the twin clock held still meanwhile)."""
        with self.hold():
            return self._render()

    def _render(self) -> Exposure:
        t0 = self.clock()
        pan, tilt = self.pointing()
        c = self.twin.config
        times = tuple(t0 + b * c.band_interval_s for b in range(self.twin.n_bands))
        bb = self.blackbody_at(pan, tilt)
        frames = []
        for b, t in enumerate(times):
            if bb is not None:
                frames.append(self.twin.blackbody_counts(b, bb, t, self.rng))
            else:
                frames.append(self.twin.scene_counts(b, pan, tilt, t, self.radiance_grids(b, t),
                                                     self.rng)[0])
        self.n_frames += 1
        return Exposure(np.stack(frames), times)

    def close(self) -> None:
        """Nothing to release."""
