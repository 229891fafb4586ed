"""Co-registration of the scans through the platform attitude (roll, pitch, yaw of the lift).

RTK-DGPS measures where the camera is, not how the platform is tilted. The attitude is
recovered from ties (measured ground displacements, :mod:`.ties`): per scan by a robust fit
(:mod:`.fit`) to ties measured against the previous and the reference scan and to the surveyed
markers (:mod:`.scan`); then once for the whole survey, a smooth attitude over time adjusted to
all ties at once (:mod:`.adjust`), optionally with ties between neighbouring placed scans
(:mod:`.neighbours`); which attitude each scan was placed with, and which scans an adjustment
moves (:mod:`.placement`); the adjustment as the chain runs it, resumable (:mod:`.survey`).
The chain (:mod:`clearfast_gis.pipeline`) runs them and records them.
"""

from clearfast_gis.attitude.adjust import (
    Adjustment,
    adjust_attitudes,
    attitude_at,
    interpolation_weights,
)
from clearfast_gis.attitude.fit import fit_attitude
from clearfast_gis.attitude.neighbours import (
    frame_windows,
    mosaic_ties,
    neighbour_pairs,
    neighbour_ties,
)
from clearfast_gis.attitude.scan import (
    ATTITUDE_SAMPLES,
    AttitudeFit,
    ReferenceMosaic,
    reposed,
    reposed_in_time,
    scan_attitude,
)
from clearfast_gis.attitude.ties import GroundTie, LinearTie, displacement_jacobian, moved_point

__all__ = [
    "ATTITUDE_SAMPLES", "Adjustment", "AttitudeFit", "GroundTie", "LinearTie", "ReferenceMosaic",
    "adjust_attitudes", "attitude_at", "displacement_jacobian", "fit_attitude",
    "interpolation_weights",
    "frame_windows", "mosaic_ties", "moved_point", "neighbour_pairs", "neighbour_ties",
    "reposed", "reposed_in_time", "scan_attitude",
]
