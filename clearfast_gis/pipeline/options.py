"""Processing parameters, in one place for the CLI, the QGIS plugin and batch runs."""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, dataclass, fields

from clearfast_gis.attitude.scan import ATTITUDE_SAMPLES
from clearfast_gis.detection.clutter import THRESHOLD_SNR

MOSAIC_PARAMETERS = ("pixel_size_m", "coregister", "search_m", "attitude_samples",
                     "adjust_attitude", "frame_refine", "max_shift_m", "max_angle_deg",
                     "seam_balance", "reference_scan", "atmosphere", "kernels")
"""The parameters that change the mosaics (the others only change the anomalies)."""


@dataclass(frozen=True)
class ProcessOptions:
    """Parameters of ``clearfast process``.

    Attributes
    ----------
    pixel_size_m : float or None
        Mosaic cell size, metres; None: from the mission's ground resolution.
    coregister : bool
        Correct the geometry by image registration (paper §5.2, §3.4): scan after scan in time
        order, the platform attitude (roll, pitch, yaw of the pan/tilt base, which the
        RTK-DGPS does not measure) is fitted to frame displacements measured by mutual
        information against the previous scan's mosaic and to the surveyed markers (absolute
        ground control). A slowly drifting lift (paper §6) is followed step by step.
    search_m : float
        Largest displacement searched when measuring a frame against the reference, metres.
    attitude_samples : int
        Frames per scan measured against each reference for the attitude fit
        (:data:`~clearfast_gis.attitude.scan.ATTITUDE_SAMPLES`).
    adjust_attitude : bool
        After every scan has its own attitude, adjust the attitudes of all scans at once
        (:mod:`clearfast_gis.attitude.adjust`): a smooth attitude over time, pinned by the
        markers of every scan and tied scan to scan by the registrations; the scans whose
        placement changes are projected again.
    frame_refine : bool
        After the attitude fit, also shift each frame individually by mutual information
        against the mosaic so far / the reference (bounded by ``max_shift_m``).
    max_shift_m, max_angle_deg : float
        Bound of the individual frame correction.
    seam_balance : bool
        The paper's histogram-based radiometric seam balancing (§5.3); changes temperatures,
        so off by default and recorded in the products when on.
    reference_scan : int or None
        Scan against which every mosaic's residual misregistration is measured (and whose
        frames give the band offsets); None: the scan nearest local solar noon (strongest
        contrast).
    atmosphere : bool
        Atmospheric correction (Eq. 4).
    kernels : {"fast", "reference"}
        Our kernels, or the reference libraries they are checked against
        (:mod:`clearfast_gis.kernels`); for side-by-side benchmarks.
    d1_m, d2_m : float
        Detector structuring elements: D1 larger than the largest expected mine, D2 < D1
        removes smaller clutter (paper §4), metres.
    epsilon : float
        Histogram stretching percentile fraction (paper §4.2).
    threshold_snr : float or None
        The stretch's cut of each image is capped at this many times the image's clutter
        (1-sigma local contrast at 0.3 m): where markers, vegetation or surface-laid mines of
        several kelvins set the top percentile, the paper's cut (half of it) lies above a
        buried mine's few tenths of a kelvin (clay, loam, after rain, the tropics and the
        southern seasons in ``benchmarks/conditions.py``). None: the stretch alone.
    level : int or None
        Majority-voting level l (paper §4.4); None: ``level_fraction`` of the images.
    level_fraction : float
        Default voting level as a fraction of the N x B images. The paper takes half; on
        diurnal mosaics a buried mine is contrasted for only part of the day (two zero-
        contrast periods, weak night contrast), and a quarter detects far more shallow mines
        at a similar false-alarm rate (``benchmarks/detection_accuracy.py --sweep``).
    gamma : float or None
        Combination threshold (paper §4.6); None: ``gamma_fraction`` of the images.
    gamma_fraction : float or None
        Default combination threshold as a fraction of the N x B images; None combines the
        reconstructed blobs by binary OR. On diurnal mosaics OR lets the low-contrast dawn and
        dusk images join neighbouring texture to a blob, which moves its centroid off the
        mine; a quarter keeps the blob to where it is seen through much of the day
        (``benchmarks/detection_accuracy.py --sweep``).
    invert : bool
        Estimate depth and diffusivity per anomaly with the thermal model.
    max_anomalies : int
        At most this many anomalies (highest scores) are characterised and written.
    """

    pixel_size_m: float | None = None
    coregister: bool = True
    search_m: float = 0.6
    attitude_samples: int = ATTITUDE_SAMPLES
    adjust_attitude: bool = True
    frame_refine: bool = False
    max_shift_m: float = 0.1
    max_angle_deg: float = 0.0
    seam_balance: bool = False
    reference_scan: int | None = None
    atmosphere: bool = True
    kernels: str = "fast"
    d1_m: float = 0.5
    d2_m: float = 0.06
    epsilon: float = 0.01
    threshold_snr: float | None = THRESHOLD_SNR
    level: int | None = None
    level_fraction: float = 0.25
    gamma: float | None = None
    gamma_fraction: float | None = 0.25
    invert: bool = True
    max_anomalies: int = 200

    def mosaic_key(self) -> str:
        """Hash of the parameters that change the mosaics."""
        return _digest({k: getattr(self, k) for k in MOSAIC_PARAMETERS})

    def detection_key(self) -> str:
        """Hash of every parameter (the anomalies depend on all of them)."""
        return _digest(asdict(self))

    def as_dict(self) -> dict:
        """Plain dict for products.json and the report."""
        return {f.name: getattr(self, f.name) for f in fields(self)}


def _digest(obj: dict) -> str:
    return hashlib.sha256(json.dumps(obj, sort_keys=True).encode()).hexdigest()[:16]
