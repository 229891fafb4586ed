"""Multi-scale snapshot detector (draft)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from clearfast_gis.detection.detector import detect_anomalies
from clearfast_gis.detection.features import blob_features
from clearfast_gis.detection.snapshot import gaussian_nan, shrink


@dataclass(frozen=True)
class Candidate:
    x_px: float
    y_px: float
    area_px: float
    diameter_px: float
    circularity: float
    contrast: float
    noise_ring: float
    noise_image: float
    scale_px: float
    polarity: int
    bbox: tuple[int, int, int, int]


def scale_candidates(image, diameter_px, work_px=10.0, d1_ratio=2.0, d2_ratio=0.3,
                     smooth_ratio=0.15, epsilon=0.01, polarity="both", size_band=(0.4, 2.0)):
    f = max(1, int(np.floor(diameter_px / work_px)))
    work = shrink(image, f) if f > 1 else np.asarray(image, np.float32)
    d = diameter_px / f
    if smooth_ratio * d > 0.3:
        work = gaussian_nan(work, smooth_ratio * d)
    d1 = max(3.0, d1_ratio * d)
    d2 = max(1.0, d2_ratio * d)
    sig_img = float(np.nanstd(work))
    out = []
    pols = ("hot", "cold") if polarity == "both" else (polarity,)
    amin = np.pi / 4 * (size_band[0] * d) ** 2
    amax = np.pi / 4 * (size_band[1] * d) ** 2
    for pol in pols:
        res = detect_anomalies(work, d1, d2, epsilon=epsilon, polarity=pol)
        n = res.n_anomalies
        if n == 0:
            continue
        area = np.bincount(res.labels.ravel(), minlength=n + 1)
        keep = (area >= amin) & (area <= amax)
        keep[0] = False
        if not keep.any():
            continue
        lut = np.zeros(n + 1, np.int32)
        lut[keep] = np.arange(1, keep.sum() + 1)
        labels = lut[res.labels]
        ring_labels = res.labels
        for ft in blob_features(labels, work, noise="ring"):
            out.append(Candidate(
                x_px=(ft.col + 0.5) * f - 0.5, y_px=(ft.row + 0.5) * f - 0.5,
                area_px=ft.area_px * f * f, diameter_px=ft.diameter_px * f,
                circularity=ft.circularity, contrast=float(ft.contrast_k[0]),
                noise_ring=float(ft.noise_k[0]), noise_image=sig_img, scale_px=diameter_px,
                polarity=1 if pol == "hot" else -1,
                bbox=tuple(int(v) * f for v in ft.bbox)))
    return out
