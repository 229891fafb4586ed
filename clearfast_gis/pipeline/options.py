"""Processing parameters, in one place for the CLI, the QGIS plugin and batch runs."""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, dataclass, fields


@dataclass(frozen=True)
class ProcessOptions:
    """Parameters of ``clearfast process``.

    Attributes
    ----------
    pixel_size_m : float or None
        Mosaic cell size, metres; None: from the mission's ground resolution.
    coregister : bool
        Mutual-information correction of every frame's placement (paper §5.2, §3.4).
    max_shift_m, max_angle_deg : float
        Bound of a frame's correction around its prediction.
    seam_balance : bool
        The paper's histogram-based radiometric seam balancing (§5.3); changes temperatures,
        so off by default and recorded in the products when on.
    reference_scan : int
        Scan whose mosaic the others are co-registered to.
    atmosphere : bool
        Atmospheric correction (Eq. 4).
    d1_m, d2_m : float
        Detector structuring elements: D1 larger than the largest expected mine, D2 < D1
        removes smaller clutter (paper §4), metres.
    epsilon : float
        Histogram stretching percentile fraction (paper §4.2).
    level : int or None
        Majority-voting level l; None: half the number of scans.
    gamma : float or None
        Combination threshold; None: binary OR (paper §4.6).
    invert : bool
        Estimate depth and diffusivity per anomaly with the thermal model.
    max_anomalies : int
        At most this many anomalies (highest scores) are characterised and written.
    """

    pixel_size_m: float | None = None
    coregister: bool = True
    max_shift_m: float = 0.3
    max_angle_deg: float = 0.0
    seam_balance: bool = False
    reference_scan: int = 0
    atmosphere: bool = True
    d1_m: float = 0.5
    d2_m: float = 0.06
    epsilon: float = 0.01
    level: int | None = None
    gamma: float | None = None
    invert: bool = True
    max_anomalies: int = 200

    def mosaic_key(self) -> str:
        """Hash of the parameters that change the mosaics."""
        keys = ("pixel_size_m", "coregister", "max_shift_m", "max_angle_deg", "seam_balance",
                "reference_scan", "atmosphere")
        return _digest({k: getattr(self, k) for k in keys})

    def detection_key(self) -> str:
        """Hash of every parameter (the anomalies depend on all of them)."""
        return _digest(asdict(self))

    def as_dict(self) -> dict:
        """Plain dict for products.json and the report."""
        return {f.name: getattr(self, f.name) for f in fields(self)}


def _digest(obj: dict) -> str:
    return hashlib.sha256(json.dumps(obj, sort_keys=True).encode()).hexdigest()[:16]
