"""The microbolometer detector: per-pixel gain/offset non-uniformity drifting in time, noise.

Raw counts are linear in the band radiance reaching the detector::

    counts_ij(t) = gain_ij(t) * L_ij + offset_ij(t) + n,   n ~ N(0, sigma)

with a nominal gain that maps 240-345 K onto about 8 %-90 % of the bit depth. The fixed
pattern is a smooth vignetting-like gain shading (+-4 %) and offset shading plus pixel-to-pixel
scatter; the drift is a slow diurnal change of the common offset (+-20 counts), a per-pixel
offset pattern (+-5 counts) and a 0.3 % gain change. Over one scan (30 min) it moves the
calibrated temperature by less than 0.03 K, which the two-point calibration between scans
removes (paper §3.3). The temporal noise is white with a standard deviation of NETD times the
band radiance slope at 300 K (noise in radiance is nearly constant over the scene's range).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from clearfast_gis.radiometry import BandTable
from clearfast_gis.simulate.scene import smooth_random_field

DAY_S = 86400.0


@dataclass(frozen=True)
class Detector:
    """Gain/offset model of one band of the camera.

    Attributes
    ----------
    gain0 : float32 (H, W)
        Gain at t0, counts per (W m-2 sr-1).
    offset0 : float32 (H, W)
        Offset at t0, counts.
    offset_pattern : float32 (H, W)
        Per-pixel offset drift pattern, counts at full drift.
    phase_rad : float
        Phase of the diurnal drift.
    t0_s : float
        Reference time, UTC epoch seconds.
    sigma_counts : float
        Temporal noise, counts (1 sigma).
    max_counts : int
        Largest count, ``2**bit_depth - 1``.
    """

    gain0: np.ndarray
    offset0: np.ndarray
    offset_pattern: np.ndarray
    phase_rad: float
    t0_s: float
    sigma_counts: float
    max_counts: int

    def gain_offset(self, time_s: float) -> tuple[np.ndarray, np.ndarray]:
        """Gain (counts per W m-2 sr-1) and offset (counts), each (H, W) float32, at ``time_s``."""
        phase = 2.0 * np.pi * (time_s - self.t0_s) / DAY_S + self.phase_rad
        g = self.gain0 * np.float32(1.0 + 0.003 * np.sin(phase))
        o = self.offset0 + np.float32(20.0 * np.sin(phase)) + self.offset_pattern * np.float32(
            np.cos(phase))
        return g, o

    def counts(self, radiance: np.ndarray, time_s: float, rng: np.random.Generator | None,
               ) -> np.ndarray:
        """Raw uint16 counts (H, W) for the band radiance ``radiance`` (H, W) at the detector.

        ``rng=None`` gives noise-free counts (rounded to integers).
        """
        g, o = self.gain_offset(time_s)
        c = g * radiance.astype(np.float32) + o
        if rng is not None:
            c += rng.standard_normal(c.shape, dtype=np.float32) * np.float32(self.sigma_counts)
        return np.clip(np.rint(c), 0, self.max_counts).astype(np.uint16)


def make_detector(table: BandTable, shape: tuple[int, int], bit_depth: int, netd_k: float,
                  t0_s: float, rng: np.random.Generator) -> Detector:
    """Draw a detector's fixed pattern for one band.

    Parameters
    ----------
    table : BandTable
        The band (for the radiance range and the slope at 300 K).
    shape : (int, int)
        Frame (H, W), pixels.
    bit_depth : int
        Bits per count.
    netd_k : float
        Noise-equivalent temperature difference at 300 K, kelvin.
    t0_s : float
        Reference time of the drift, UTC epoch seconds.
    rng : numpy.random.Generator
    """
    full = 2 ** int(bit_depth) - 1
    l_lo, l_hi = table.radiance(np.array([240.0, 345.0]))
    gain = 0.82 * full / (l_hi - l_lo)
    offset = 0.08 * full - gain * l_lo
    h, w = shape
    yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
    r2 = ((xx - (w - 1) / 2) / (w / 2)) ** 2 + ((yy - (h - 1) / 2) / (h / 2)) ** 2
    shading = 1.0 - 0.04 * r2 / 2.0 + 0.015 * smooth_random_field(shape, 1.0, w / 3.0, rng)
    gain_map = gain * (shading + 0.005 * rng.standard_normal(shape)).astype(np.float32)
    off_map = (offset + 0.01 * full * smooth_random_field(shape, 1.0, w / 4.0, rng)
               + 0.002 * full * rng.standard_normal(shape)).astype(np.float32)
    pattern = (5.0 * smooth_random_field(shape, 1.0, w / 5.0, rng)).astype(np.float32)
    d_l = float(np.diff(table.radiance(np.array([299.95, 300.05])))[0]) / 0.1
    return Detector(gain_map.astype(np.float32), off_map, pattern,
                    float(rng.uniform(0.0, 2.0 * np.pi)), float(t0_s),
                    float(gain * netd_k * d_l), full)
