"""The boom lift: true antenna track and attitude (with the trial's drift), and the RTK log.

The lift stands still; its basket sways by millimetres. With ``drift`` the hydraulics slowly
give way as in the 2004 trial (paper §6): the basket loses height and the platform pitches,
rolls and yaws, smoothly over the survey (a saturating curve, fastest at the start). The GNSS
log is the true antenna position plus RTK noise (1-2 cm), with a few RTK-float episodes
(decimetre noise, fix quality 5) and one short loss of fix (quality 0, empty position).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from clearfast_gis.simulate.config import SimConfig

#: RTK fixed noise (1 sigma), metres: horizontal, vertical.
RTK_FIXED_SIGMA_M = (0.012, 0.02)
#: RTK float noise (1 sigma), metres: horizontal, vertical.
RTK_FLOAT_SIGMA_M = (0.15, 0.25)


@dataclass(frozen=True)
class LiftMotion:
    """True motion of the lift's GNSS antenna and platform attitude.

    Attributes
    ----------
    antenna0_m : ndarray (3,)
        Nominal antenna position (E, N, z above ground), metres.
    start_s, duration_s : float
        Survey start (UTC epoch seconds) and length, seconds.
    drift : bool
        Whether the trial's hydraulic drift is on.
    height_loss_m, roll_deg, pitch_deg, yaw_deg : float
        Drift reached at the end of the survey.
    sway_phase : ndarray (3,)
        Phases of the millimetre sway, radians.
    """

    antenna0_m: np.ndarray
    start_s: float
    duration_s: float
    drift: bool
    height_loss_m: float
    roll_deg: float
    pitch_deg: float
    yaw_deg: float
    sway_phase: np.ndarray

    def drift_fraction(self, time_s: np.ndarray) -> np.ndarray:
        """Fraction 0..1 of the final drift reached at ``time_s`` (0 without drift)."""
        s = np.clip((np.asarray(time_s, float) - self.start_s) / self.duration_s, 0.0, 1.0)
        if not self.drift:
            return np.zeros_like(s)
        k = 2.0
        return (1.0 - np.exp(-k * s)) / (1.0 - np.exp(-k))

    def antenna_m(self, time_s: np.ndarray) -> np.ndarray:
        """True antenna positions (N, 3) at ``time_s`` (N,), metres."""
        t = np.atleast_1d(np.asarray(time_s, float))
        f = self.drift_fraction(t)
        w = 2.0 * np.pi / np.array([47.0, 61.0, 83.0])
        sway = 0.003 * np.sin(w[None, :] * (t[:, None] - self.start_s) + self.sway_phase)
        pos = self.antenna0_m[None, :] + sway
        pos[:, 2] -= self.height_loss_m * f
        return pos

    def attitude_rpy_deg(self, time_s: np.ndarray) -> np.ndarray:
        """True platform (roll, pitch, yaw) (N, 3) at ``time_s``, degrees."""
        f = self.drift_fraction(np.atleast_1d(np.asarray(time_s, float)))
        return np.column_stack([self.roll_deg * f, self.pitch_deg * f, self.yaw_deg * f])


def lift_motion(config: SimConfig, antenna0_m: np.ndarray, start_s: float, drift: bool,
                rng: np.random.Generator) -> LiftMotion:
    """The lift's true motion for a survey (drift amounts from ``config``)."""
    return LiftMotion(np.asarray(antenna0_m, float), float(start_s), float(config.duration_s),
                      bool(drift), config.drift_height_loss_m, config.drift_roll_deg,
                      config.drift_pitch_deg, config.drift_yaw_deg,
                      rng.uniform(0.0, 2.0 * np.pi, 3))


@dataclass(frozen=True)
class GnssEpochs:
    """The receiver's epochs: measured antenna positions (world frame) and fix quality.

    time_s (N,), position_m (N, 3) (NaN without a fix), quality (N,) int, n_sats (N,) int,
    hdop (N,).
    """

    time_s: np.ndarray
    position_m: np.ndarray
    quality: np.ndarray
    n_sats: np.ndarray
    hdop: np.ndarray


def gnss_epochs(motion: LiftMotion, start_s: float, end_s: float, interval_s: float,
                rng: np.random.Generator) -> GnssEpochs:
    """Simulate RTK-DGPS epochs of the antenna from ``start_s`` to ``end_s``.

    Three RTK-float episodes of 2-6 min and one 60-90 s loss of fix are placed at random in
    the survey; everything else is RTK fixed with :data:`RTK_FIXED_SIGMA_M` noise.
    """
    t = np.arange(start_s, end_s + 0.5 * interval_s, interval_s)
    n = t.size
    quality = np.full(n, 4, dtype=np.int64)
    span = end_s - start_s
    for _ in range(3):
        t0 = start_s + rng.uniform(0.05, 0.9) * span
        quality[(t >= t0) & (t < t0 + rng.uniform(120.0, 360.0))] = 5
    t0 = start_s + rng.uniform(0.1, 0.9) * span
    quality[(t >= t0) & (t < t0 + rng.uniform(60.0, 90.0))] = 0
    true = motion.antenna_m(t)
    sig = np.where((quality == 5)[:, None], np.array(RTK_FLOAT_SIGMA_M)[[0, 0, 1]],
                   np.array(RTK_FIXED_SIGMA_M)[[0, 0, 1]])
    meas = true + rng.standard_normal((n, 3)) * sig
    meas[quality == 0] = np.nan
    n_sats = np.where(quality == 0, rng.integers(2, 4, n), rng.integers(11, 17, n))
    hdop = np.where(quality == 0, 99.99, np.round(rng.uniform(0.6, 1.1, n), 2))
    return GnssEpochs(t, meas, quality, n_sats, hdop)
