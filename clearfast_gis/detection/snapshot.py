"""Snapshot mode: the detector on one plain image (N = 1, no georeference).

With one image the majority vote keeps every opened blob (level 1/2), so the chain is top-hat
(and/or bottom-hat) by reconstruction, stretch and threshold, opening by reconstruction; each
blob is then measured and scored (:mod:`clearfast_gis.detection.features`) and the detections
are returned best score first.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import cv2
import numpy as np

from clearfast_gis.detection.detector import detect_anomalies
from clearfast_gis.detection.features import RING_RADII, blob_features

__all__ = ["Detection", "detect_snapshot", "gaussian_nan", "shrink"]


@dataclass(frozen=True)
class Detection:
    """One detection in a snapshot.

    Attributes
    ----------
    x_px, y_px : float
        Centroid column and row (pixel centres at integers).
    area_px : int
    diameter_px : float
        Equivalent diameter ``sqrt(4 area / pi)``.
    circularity : float
        Mean of the axis ratio and the compactness, in [0, 1].
    score : float
        Centre-minus-ring contrast over the image's standard deviation, times
        ``0.5 + 0.5 circularity`` and ``log10(1 + area)`` (working pixels).
    polarity : str
        'warm' or 'cool'.
    contrast : float
        Centre mean minus ring mean, in the image's units.
    bbox : (row0, col0, row1, col1)
        Bounding box, end exclusive.
    scale_px : float
        Object diameter of the scale that found it (multi-scale mode), else 0.
    """

    x_px: float
    y_px: float
    area_px: int
    diameter_px: float
    circularity: float
    score: float
    polarity: str
    contrast: float
    bbox: tuple[int, int, int, int]
    scale_px: float = 0.0


def detect_snapshot(
    image: np.ndarray,
    d1_px: float,
    d2_px: float,
    epsilon: float = 0.01,
    polarity: str = "hot",
    min_score: float = 0.0,
    ring_radii: tuple[float, float] = RING_RADII,
    smooth_px: float = 0.0,
    scale: int = 1,
) -> list[Detection]:
    """Detect anomalies in one image.

    Parameters
    ----------
    image : ndarray (H, W)
        Apparent temperature or grey levels (float32; NaN = no-data).
    d1_px, d2_px : float
        Top-hat and opening disk diameters in pixels (D1 > D2 >= 1).
    epsilon : float
        Histogram-stretch fraction.
    polarity : {'hot', 'cold', 'both'}
        Warm blobs, cool blobs or both.
    min_score : float
        Drop detections scoring below this.
    ring_radii : (float, float)
        Background ring radii in equivalent radii of the blob.
    smooth_px : float
        Standard deviation (working pixels) of a Gaussian pre-filter that removes texture
        finer than the objects (grass, gravel); 0 = none.
    scale : int
        Work on the image shrunk by this integer factor (area averaging); D1, D2 and
        ``smooth_px`` are in working pixels, the detections in the original image's pixels.

    Returns
    -------
    list of Detection, highest score first.

    Notes
    -----
    The score's noise is the standard deviation of the whole (filtered) image, which ranks
    blobs on textured ground better than the ring's (see docs/detection.md).
    """
    image = np.asarray(image, dtype=np.float32)
    if image.ndim != 2:
        raise ValueError(f"a snapshot is one (H, W) image, got shape {image.shape}")
    scale = int(scale)
    if scale < 1:
        raise ValueError(f"scale must be an integer >= 1, got {scale}")
    work = image
    if scale > 1:
        work = shrink(image, scale)
    if smooth_px > 0:
        work = gaussian_nan(work, smooth_px)
    result = detect_anomalies(work, d1_px, d2_px, epsilon=epsilon, polarity=polarity)
    feats = blob_features(result.labels, work, detection=result, ring_radii=ring_radii,
                          noise="image")
    s2 = scale * scale
    dets = [
        Detection(
            x_px=(f.col + 0.5) * scale - 0.5, y_px=(f.row + 0.5) * scale - 0.5,
            area_px=int(f.area_px * s2), diameter_px=f.diameter_px * scale,
            circularity=f.circularity, score=f.score,
            polarity="cool" if f.polarity_per_scan[0] < 0 else "warm",
            contrast=float(f.contrast_k[0]), bbox=tuple(int(v) * scale for v in f.bbox),
        )
        for f in feats
        if f.score >= min_score
    ]
    return sorted(dets, key=lambda d: -d.score)


def shrink(image: np.ndarray, factor: int) -> np.ndarray:
    """Shrink (H, W) by an integer factor, averaging blocks (NaN-aware; ragged edges dropped)."""
    h, w = (image.shape[0] // factor) * factor, (image.shape[1] // factor) * factor
    if h == 0 or w == 0:
        raise ValueError(f"image {image.shape} smaller than the scale factor {factor}")
    blocks = image[:h, :w].reshape(h // factor, factor, w // factor, factor)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=RuntimeWarning)
        return np.nanmean(blocks, axis=(1, 3)).astype(np.float32)


def gaussian_nan(image: np.ndarray, sigma_px: float) -> np.ndarray:
    """Gaussian filter (standard deviation ``sigma_px``) that ignores and keeps NaN pixels."""
    nan = np.isnan(image)
    if not nan.any():
        return cv2.GaussianBlur(image, (0, 0), sigma_px, borderType=cv2.BORDER_REFLECT)
    filled = np.where(nan, 0.0, image).astype(np.float32)
    weight = cv2.GaussianBlur((~nan).astype(np.float32), (0, 0), sigma_px,
                              borderType=cv2.BORDER_REFLECT)
    out = cv2.GaussianBlur(filled, (0, 0), sigma_px, borderType=cv2.BORDER_REFLECT)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = out / weight
    out[nan] = np.nan
    return out.astype(np.float32)
