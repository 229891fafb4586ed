"""Multi-scale snapshot detector: the morphological chain at a ladder of object sizes.

One D1 cannot fit objects from 13 to 500 pixels across (snapshots taken from 0.4 to 10 m), so
the chain of :func:`clearfast_gis.detection.detector.detect_anomalies` (top-hat and/or
bottom-hat by reconstruction, stretch and threshold, opening by reconstruction) runs once per
object diameter ``d`` of a ladder (:func:`scale_ladder`, or :func:`altitude_ladder` from the
flight altitude). At scale ``d`` the image is shrunk by ``f = floor(d / work_px)`` (block mean)
so the object spans about ``work_px`` working pixels, smoothed by a Gaussian of standard
deviation ``smooth_ratio * d / f``, and filtered with ``D1 = d1_ratio * d / f`` and
``D2 = d2_ratio * d / f``: every scale costs about the same, the large ones less.

A scale keeps the blobs whose equivalent diameter lies in ``size_band * d`` (its own size
range). Score (:func:`snapshot_score`, dimensionless and comparable across scales):
``|contrast| / sigma x (0.5 + 0.5 circularity) x area_px ** area_power`` with the contrast
centre-minus-ring on the working image (ring of 1.5-2.5 equivalent radii), sigma the standard
deviation of that working image (or its robust 1.4826 MAD) and the area in original pixels. Blobs
seen at several scales are merged by :func:`suppress_overlaps` (best score first; a blob is
dropped when the distance between its centroid and a kept one's is at most ``overlap`` times
half the smaller of the two equivalent diameters), so one blob gives one detection.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from clearfast_gis.detection.detector import detect_anomalies
from clearfast_gis.detection.features import blob_features
from clearfast_gis.detection.selection import median
from clearfast_gis.detection.snapshot import Detection, gaussian_nan, shrink

__all__ = ["MultiScaleParams", "altitude_from_name", "altitude_ladder",
           "detect_snapshot_multiscale", "robust_sigma", "scale_candidates", "scale_ladder",
           "snapshot_score", "suppress_overlaps"]


@dataclass(frozen=True)
class MultiScaleParams:
    """Parameters of the multi-scale detector (ratios are to the scale's object diameter).

    Attributes
    ----------
    work_px : float
        Object diameter in working pixels (sets the shrink factor).
    d1_ratio, d2_ratio : float
        D1 and D2 over the object diameter (D1 > object > D2).
    smooth_ratio : float
        Gaussian pre-filter standard deviation over the object diameter.
    epsilon : float
        Histogram-stretch fraction.
    size_band : (float, float)
        Equivalent diameters kept at a scale, as fractions of the scale's diameter.
    area_power : float
        Exponent of the area term of the score.
    overlap : float
        Non-maximum suppression distance, in half equivalent diameters.
    noise : {'std', 'mad'}
        Score's sigma: standard deviation of the working image, or 1.4826 x its median
        absolute deviation (:func:`robust_sigma`).
    """

    work_px: float = 8.0
    d1_ratio: float = 2.0
    d2_ratio: float = 0.3
    smooth_ratio: float = 0.25
    epsilon: float = 0.01
    size_band: tuple[float, float] = (0.4, 2.0)
    area_power: float = 0.1
    overlap: float = 1.0
    noise: str = "std"


def scale_ladder(min_diameter_px: float = 16.0, max_diameter_px: float = 362.0,
                 per_octave: int = 2) -> np.ndarray:
    """Object diameters (pixels) from ``min`` to ``max`` in steps of ``2 ** (1 / per_octave)``.

    Returns
    -------
    ndarray (K,) of float, increasing; the last value is at most ``max_diameter_px``
    (rounded to 0.1 px).
    """
    if not 1.0 <= min_diameter_px <= max_diameter_px or per_octave < 1:
        raise ValueError(f"need 1 <= min <= max and per_octave >= 1, got {min_diameter_px}, "
                         f"{max_diameter_px}, {per_octave}")
    k = int(np.floor(per_octave * np.log2(max_diameter_px / min_diameter_px) + 1e-9))
    return np.round(min_diameter_px * 2.0 ** (np.arange(k + 1) / per_octave), 1)


def altitude_ladder(altitude_m: float, diameter_px_at_1m: float, spread: float = 8.0,
                    per_octave: int = 2, min_diameter_px: float = 16.0,
                    max_diameter_px: float = 256.0) -> np.ndarray:
    """A window of the ladder placed by the flight altitude.

    The expected object diameter is ``diameter_px_at_1m / altitude_m`` (a nadir camera: object
    size times focal length in pixels, over the range). The ladder spans a factor ``spread``
    (``centre / sqrt(spread)`` to ``centre * sqrt(spread)``), its centre clipped so that the
    window stays inside ``[min_diameter_px, max_diameter_px]`` (the whole range when it is
    narrower than ``spread``).

    Parameters
    ----------
    altitude_m : float
        Camera height above ground, metres (> 0).
    diameter_px_at_1m : float
        Object diameter in pixels at 1 m range.
    spread : float
        Ratio of the largest to the smallest diameter of the ladder (>= 1).
    per_octave : int
        Scales per factor 2.
    min_diameter_px, max_diameter_px : float
        Bounds of the window, pixels.

    Returns
    -------
    ndarray (K,) of float, increasing.
    """
    if not altitude_m > 0 or not diameter_px_at_1m > 0 or spread < 1:
        raise ValueError(f"need altitude > 0, diameter at 1 m > 0 and spread >= 1, got "
                         f"{altitude_m}, {diameter_px_at_1m}, {spread}")
    half = np.sqrt(spread)
    lo_c, hi_c = min_diameter_px * half, max_diameter_px / half
    centre = diameter_px_at_1m / altitude_m
    centre = float(np.clip(centre, lo_c, hi_c)) if lo_c <= hi_c else np.sqrt(
        min_diameter_px * max_diameter_px)
    lo = max(min_diameter_px, centre / half)
    hi = min(max_diameter_px, centre * half)
    return scale_ladder(lo, hi * (1 + 1e-9), per_octave)


_ALTITUDE = re.compile(r"__(\d+)-(\d*)m_")


def altitude_from_name(path: str | Path) -> float | None:
    """Flight altitude (m) written in a file name as ``__<int>-<frac>m_`` (``__0-7m_`` = 0.7 m,
    ``__10-m_`` = 10 m), or None when absent or zero."""
    m = _ALTITUDE.search(Path(path).name)
    if not m:
        return None
    value = float(f"{m.group(1)}.{m.group(2) or '0'}")
    return value if value > 0 else None


def robust_sigma(image: np.ndarray) -> float:
    """Noise of an image: 1.4826 x the median absolute deviation of its valid pixels (the
    objects themselves barely move it, unlike the standard deviation)."""
    v = np.asarray(image, dtype=np.float32)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return 0.0
    return float(1.4826 * median(np.abs(v - median(v))))


def snapshot_score(contrast: float, sigma: float, circularity: float, area_px: float,
                   area_power: float) -> float:
    """``|contrast| / sigma x (0.5 + 0.5 circularity) x area_px ** area_power`` (0 when sigma
    is not positive)."""
    if not sigma > 0 or not np.isfinite(contrast):
        return 0.0
    return float(abs(contrast) / sigma * (0.5 + 0.5 * circularity) * area_px ** area_power)


def scale_candidates(image: np.ndarray, diameter_px: float, polarity: str = "hot",
                     params: MultiScaleParams = MultiScaleParams()) -> list[Detection]:
    """The detector's blobs at one scale, scored, in original pixels (unsorted).

    Parameters
    ----------
    image : ndarray (H, W) float32
        Grey levels or apparent temperature, NaN = no-data.
    diameter_px : float
        Object diameter of this scale, original pixels.
    polarity : {'hot', 'cold', 'both'}
    params : MultiScaleParams

    Returns
    -------
    list of Detection with ``scale_px = diameter_px``.
    """
    f = max(1, int(np.floor(diameter_px / params.work_px)))
    work = shrink(image, f) if f > 1 else np.asarray(image, dtype=np.float32)
    d = diameter_px / f
    if params.smooth_ratio * d > 0.3:
        work = gaussian_nan(work, params.smooth_ratio * d)
    d1 = max(3.0, params.d1_ratio * d)
    d2 = min(max(1.0, params.d2_ratio * d), d1 - 1.0)
    sigma = robust_sigma(work) if params.noise == "mad" else float(np.nanstd(work))
    a_min = np.pi / 4.0 * (params.size_band[0] * d) ** 2
    a_max = np.pi / 4.0 * (params.size_band[1] * d) ** 2
    out = []
    for pol in (("hot", "cold") if polarity == "both" else (polarity,)):
        result = detect_anomalies(work, d1, d2, epsilon=params.epsilon, polarity=pol)
        n = result.n_anomalies
        if n == 0:
            continue
        area = np.bincount(result.labels.ravel(), minlength=n + 1)
        keep = (area >= a_min) & (area <= a_max)
        keep[0] = False
        if not keep.any():
            continue
        lut = np.zeros(n + 1, dtype=np.int32)
        lut[keep] = np.arange(1, int(keep.sum()) + 1)
        for ft in blob_features(lut[result.labels], work, noise="image"):
            area_px = int(ft.area_px * f * f)
            contrast = float(ft.contrast_k[0])
            out.append(Detection(
                x_px=(ft.col + 0.5) * f - 0.5, y_px=(ft.row + 0.5) * f - 0.5,
                area_px=area_px, diameter_px=ft.diameter_px * f, circularity=ft.circularity,
                score=snapshot_score(contrast, sigma, ft.circularity, area_px,
                                     params.area_power),
                polarity="warm" if pol == "hot" else "cool", contrast=contrast,
                bbox=tuple(int(v) * f for v in ft.bbox), scale_px=float(diameter_px)))
    return out


def suppress_overlaps(detections: list[Detection], overlap: float = 1.0) -> list[Detection]:
    """Non-maximum suppression across scales, best score first.

    A detection is dropped when its centroid lies within ``overlap * min(D_a, D_b) / 2`` of an
    already kept one's (D: equivalent diameters), i.e. when the two are the same blob seen at
    two scales.

    Returns
    -------
    list of Detection, highest score first.
    """
    dets = sorted(detections, key=lambda d: -d.score)
    if not dets:
        return []
    xy = np.array([(d.x_px, d.y_px) for d in dets])
    diam = np.array([d.diameter_px for d in dets])
    kept: list[int] = []
    for i in range(len(dets)):
        if kept:
            k = np.asarray(kept)
            dist = np.hypot(xy[k, 0] - xy[i, 0], xy[k, 1] - xy[i, 1])
            if np.any(dist <= overlap * 0.5 * np.minimum(diam[k], diam[i])):
                continue
        kept.append(i)
    return [dets[i] for i in kept]


def detect_snapshot_multiscale(
    image: np.ndarray,
    diameters_px: np.ndarray | list[float] | None = None,
    polarity: str = "hot",
    min_score: float = 0.0,
    params: MultiScaleParams = MultiScaleParams(),
) -> list[Detection]:
    """Detect anomalies of any size in one image (multi-scale snapshot mode).

    Parameters
    ----------
    image : ndarray (H, W)
        Grey levels or apparent temperature (NaN = no-data).
    diameters_px : sequence of float, optional
        Object diameters of the ladder, original pixels; default :func:`scale_ladder` from
        16 px to 0.4 times the image's smaller side (256 px on 640 x 640, as tuned).
    polarity : {'hot', 'cold', 'both'}
        Warm blobs, cool blobs or both (a buried mine is warm by day, cool by night).
    min_score : float
        Drop detections scoring below this.
    params : MultiScaleParams

    Returns
    -------
    list of Detection, one per blob, highest score first (``scale_px`` = the scale that found
    it).
    """
    image = np.asarray(image, dtype=np.float32)
    if image.ndim != 2:
        raise ValueError(f"a snapshot is one (H, W) image, got shape {image.shape}")
    if polarity not in ("hot", "cold", "both"):
        raise ValueError(f"polarity must be 'hot', 'cold' or 'both', got {polarity!r}")
    if diameters_px is None:
        diameters_px = scale_ladder(16.0, max(16.0, 0.4 * min(image.shape)))
    diameters = [float(d) for d in np.atleast_1d(diameters_px)]
    if not diameters or min(diameters) < 2:
        raise ValueError(f"object diameters must be >= 2 px, got {diameters}")
    cands: list[Detection] = []
    for d in diameters:
        if d <= min(image.shape):  # larger objects do not fit in the image
            cands += scale_candidates(image, d, polarity, params)
    return [d for d in suppress_overlaps(cands, params.overlap) if d.score >= min_score]
