"""The anomaly set of a survey: what the anomaly stage hands to the products."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from clearfast_gis.detection.features import AnomalyFeatures
from clearfast_gis.detection.markers import MarkerMatch
from clearfast_gis.thermal import Inversion


@dataclass
class AnomalySet:
    """Detected anomalies of a survey.

    Attributes
    ----------
    labels : int32 (H, W)
        Anomaly label per mosaic cell (0 = background), ids matching ``features``.
    features : list of AnomalyFeatures
        Highest score first, at most ``max_anomalies``.
    inversions : dict[int, Inversion]
        Thermal characterisation per anomaly id (missing when not attempted).
    soil_alpha_m2s, soil_alpha_sigma_m2s : float
        Soil diffusivity from the thermocouples.
    notes : list of str
        What the characterisation had to skip, and why.
    markers : list of MarkerMatch
        Known markers found among the anomalies (removed from ``features``).
    """

    labels: np.ndarray
    features: list[AnomalyFeatures]
    inversions: dict[int, Inversion]
    soil_alpha_m2s: float = math.nan
    soil_alpha_sigma_m2s: float = math.nan
    notes: list[str] = dataclasses.field(default_factory=list)
    markers: list[MarkerMatch] = dataclasses.field(default_factory=list)
