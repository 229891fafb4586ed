"""Anomaly detection on thermal stacks and snapshots (paper §4): morphological detector, fast
reconstruction kernels, blob features, scoring and class cues."""

from clearfast_gis.detection.classify import CLASSES, classify, diffusivity_cue
from clearfast_gis.detection.detector import DetectionResult, detect_anomalies
from clearfast_gis.detection.features import (
    AnomalyFeatures,
    blob_features,
    features_table,
    summary_polarity,
)
from clearfast_gis.detection.morphology import (
    binary_opening_by_reconstruction,
    bottom_hat_by_reconstruction,
    dilate_disk,
    disk_footprint,
    erode_disk,
    top_hat_by_reconstruction,
)
from clearfast_gis.detection.multiscale import (
    MultiScaleParams,
    altitude_from_name,
    altitude_ladder,
    detect_snapshot_multiscale,
    scale_ladder,
)
from clearfast_gis.detection.reconstruction import (
    binary_reconstruction,
    reconstruction,
    reconstruction_by_dilation,
    reconstruction_by_erosion,
)
from clearfast_gis.detection.snapshot import Detection, detect_snapshot

__all__ = [
    "CLASSES", "AnomalyFeatures", "Detection", "DetectionResult", "MultiScaleParams",
    "altitude_from_name", "altitude_ladder", "detect_snapshot_multiscale", "scale_ladder",
    "binary_opening_by_reconstruction",
    "binary_reconstruction", "blob_features", "bottom_hat_by_reconstruction", "classify",
    "detect_anomalies", "detect_snapshot", "dilate_disk", "diffusivity_cue", "disk_footprint",
    "erode_disk", "features_table", "reconstruction",
    "reconstruction_by_dilation", "reconstruction_by_erosion",
    "summary_polarity", "top_hat_by_reconstruction",
]
