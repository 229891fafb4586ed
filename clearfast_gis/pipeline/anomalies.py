"""Anomalies on the temporal stack of mosaics: detect, measure, characterise, classify."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from clearfast_gis.detection import blob_features, classify, detect_anomalies
from clearfast_gis.detection.compact import split_oversized
from clearfast_gis.detection.detector import as_image_stack
from clearfast_gis.detection.features import AnomalyFeatures
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.thermal import (
    Inversion,
    build_site_table,
    invert_anomaly,
)
from clearfast_gis.thermal.error_budget import with_chain_errors
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.timeutil import format_utc
from clearfast_gis.units import ZERO_CELSIUS_K


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


def disk_px(size_m: float, pixel_size_m: float, minimum: int = 3) -> int:
    """A structuring-element diameter in metres as an odd number of pixels (>= minimum)."""
    n = max(minimum, int(round(size_m / pixel_size_m)))
    return n if n % 2 == 1 else n + 1


def split_by_cores(labels: np.ndarray, votes: np.ndarray, level: float) -> np.ndarray:
    """Split detected blobs that hold several voted cores (paper §4.4-4.5).

    The reconstruction of §4.5 grows each voted core M to the whole connected component of
    every thresholded image; on a textured site neighbouring objects then merge into one blob.
    Each connected core becomes its own anomaly: the blob is divided among its cores by a
    watershed on the vote count.

    Parameters
    ----------
    labels : int (H, W)
        Detected blobs (0 = background).
    votes : int (H, W)
        Sum of the opened images, ``sum_i O_i``.
    level : float
        Voting level l.

    Returns
    -------
    int32 (H, W)
        Labels, one per core (blobs without a core keep one label).
    """
    from scipy import ndimage
    from skimage.segmentation import watershed

    mask = labels > 0
    cores, n = ndimage.label((votes >= level) & mask, structure=np.ones((3, 3)))
    if n == 0:
        return labels.astype(np.int32)
    split = watershed(-votes.astype(np.float32), markers=cores, mask=mask)
    orphan = mask & (split == 0)
    if orphan.any():
        extra, _ = ndimage.label(orphan, structure=np.ones((3, 3)))
        split = np.where(orphan, extra + n, split)
    return split.astype(np.int32)


MIN_SUPPORT_SCANS = 3
"""Fewest scans whose images must vote for a pixel (with the default, coverage-relative
voting level and combination threshold)."""


def coverage_level(fraction: float, covered: np.ndarray, n_scans: int, n_bands: int
                   ) -> np.ndarray:
    """Per-pixel vote count required: ``fraction`` of the images covering the pixel.

    Fully covered pixels get ``fraction`` of the N x B images (the stack's level); partly
    covered ones a proportional level, never below what :data:`MIN_SUPPORT_SCANS` scans give
    (nor above the stack's level).

    Parameters
    ----------
    fraction : float
    covered : int (H, W)
        Images with data at each pixel.
    n_scans, n_bands : int

    Returns
    -------
    float (H, W)
    """
    floor = max(1, min(MIN_SUPPORT_SCANS * n_bands, round(fraction * n_scans * n_bands)))
    return np.maximum(np.round(fraction * covered), floor).astype(np.float64)


def detect_on_mosaics(stack_c: np.ndarray, times_s: np.ndarray, transform, pixel_size_m: float,
                      longitude_deg: float, d1_m: float, d2_m: float, epsilon: float,
                      level: int | None, gamma: float | None, max_anomalies: int,
                      level_fraction: float = 0.5, gamma_fraction: float | None = None,
                      progress: Progress = NULL_PROGRESS) -> tuple[np.ndarray, list]:
    """The morphological detector on mosaics, and blob features.

    Parameters
    ----------
    stack_c : float32 (N, B, H, W)
        Co-registered mosaics, degrees C, NaN = no data.
    times_s : float64 (N,)
        Scan times, UTC epoch seconds.
    transform : affine.Affine
        Mosaic grid transform.
    pixel_size_m : float
        Mosaic cell size, metres.
    longitude_deg : float
        Site longitude (local solar time for the polarity).
    d1_m, d2_m, epsilon, level, gamma : detector parameters (paper §4), sizes in metres.
    level_fraction : float
        Voting level, when ``level`` is None, as a fraction of the images that cover each
        pixel (at least :data:`MIN_SUPPORT_SCANS` scans' worth): a drifting platform
        (paper §6) leaves parts of the site out of some scans, and a mine seen in a third of
        the scans is no less a mine.
    gamma_fraction : float or None
        Combination threshold as a fraction of the covering images when ``gamma`` is None
        (None: OR).
    max_anomalies : int
        Keep the highest-scoring ones.

    Returns
    -------
    labels : int32 (H, W)
        Relabelled 1..K in the order of ``features``.
    features : list of AnomalyFeatures
    """
    images, n_scans, n_bands = as_image_stack(stack_c)
    if level is None or (gamma is None and gamma_fraction is not None):
        covered = np.isfinite(images).sum(axis=0)
        if level is None:
            level = coverage_level(level_fraction, covered, n_scans, n_bands)
        if gamma is None and gamma_fraction is not None:
            gamma = coverage_level(gamma_fraction, covered, n_scans, n_bands)
    det = detect_anomalies(stack_c, disk_px(d1_m, pixel_size_m), disk_px(d2_m, pixel_size_m),
                           epsilon=epsilon, level=level, gamma=gamma, progress=progress)
    split = split_by_cores(det.labels, det.votes, level)
    split = split_oversized(split, images, disk_px(d1_m, pixel_size_m),
                            disk_px(d2_m, pixel_size_m), d1_m / pixel_size_m)
    feats = blob_features(split, stack_c, times_s=times_s, transform=transform,
                          pixel_size_m=pixel_size_m, detection=det, longitude_deg=longitude_deg)
    feats = sorted(feats, key=lambda f: (-f.score, f.id))[:max_anomalies]
    labels = np.zeros(split.shape, dtype=np.int32)
    renumbered = []
    for new_id, f in enumerate(feats, start=1):
        labels[split == f.id] = new_id
        renumbered.append(dataclasses.replace(f, id=new_id))
    return labels, renumbered


@dataclass(frozen=True)
class MarkerMatch:
    """A known marker found among the anomalies (a check of the georeferencing).

    Attributes
    ----------
    marker_id : str
    x, y : float
        Surveyed position, survey CRS metres.
    found_x, found_y : float
        Centroid of the matching anomaly, survey CRS metres.
    """

    marker_id: str
    x: float
    y: float
    found_x: float
    found_y: float

    @property
    def offset_m(self) -> float:
        """Distance between the surveyed and the found position, metres."""
        return math.hypot(self.found_x - self.x, self.found_y - self.y)


def split_markers(features: list[AnomalyFeatures], marker_ids: list[str],
                  marker_xy: np.ndarray, radius_m: float = 0.3
                  ) -> tuple[list[AnomalyFeatures], list[MarkerMatch]]:
    """Separate anomalies that are known surveyed markers from the suspects.

    Parameters
    ----------
    features : list of AnomalyFeatures
    marker_ids : list of str
    marker_xy : float (M, 2)
        Surveyed marker positions, survey CRS metres.
    radius_m : float
        An anomaly whose centroid lies this close to a marker is that marker.

    Returns
    -------
    suspects : list of AnomalyFeatures
        The anomalies that are not markers.
    matches : list of MarkerMatch
        The nearest anomaly of each marker found.
    """
    if len(marker_ids) == 0 or not features:
        return features, []
    fx = np.array([f.x for f in features])
    fy = np.array([f.y for f in features])
    d = np.hypot(fx[:, None] - marker_xy[None, :, 0], fy[:, None] - marker_xy[None, :, 1])
    is_marker = d.min(axis=1) <= radius_m
    matches = []
    for j, mid in enumerate(marker_ids):
        i = int(np.argmin(d[:, j]))
        if d[i, j] <= radius_m:
            matches.append(MarkerMatch(str(mid), float(marker_xy[j, 0]), float(marker_xy[j, 1]),
                                       float(fx[i]), float(fy[i])))
    return [f for f, m in zip(features, is_marker, strict=True) if not m], matches


def markers_in_mosaics(stack_c: np.ndarray, grid, marker_ids: list[str],
                       marker_xy: np.ndarray) -> list[MarkerMatch]:
    """Where each surveyed marker appears in the mosaics: the median over the scans of its
    contrast-weighted centroid (:func:`clearfast_gis.mosaic.markers.locate_marker`).

    Parameters
    ----------
    stack_c : float32 (N, B, H, W)
        Mosaics, degrees C.
    grid : GroundGrid
    marker_ids : list of str
    marker_xy : float (M, 2)
        Surveyed positions, survey CRS metres.
    """
    from clearfast_gis.mosaic.markers import locate_marker

    out = []
    for mid, (x, y) in zip(marker_ids, marker_xy, strict=True):
        found = [p for p in (locate_marker(stack_c[i, 0], grid, float(x), float(y))
                             for i in range(stack_c.shape[0])) if p is not None]
        if found:
            fx, fy = np.median(np.array(found), axis=0)
            out.append(MarkerMatch(str(mid), float(x), float(y), float(fx), float(fy)))
    return out


def _band0(series: np.ndarray) -> np.ndarray:
    s = np.asarray(series, dtype=np.float64)
    return s[:, 0] if s.ndim == 2 else s


def radius_nodes(radii_m: np.ndarray, max_nodes: int = 3) -> np.ndarray:
    """A few object radii (m) spanning the anomalies', for the site table."""
    r = np.clip(np.asarray(radii_m, dtype=float), 0.02, 0.25)
    if r.size == 0:
        return np.array([0.05])
    q = np.unique(np.round(np.quantile(r, np.linspace(0, 1, max_nodes)), 2))
    return q


def characterise(features: list[AnomalyFeatures], times_s: np.ndarray, forcing: Forcing,
                 soil, progress: Progress = NULL_PROGRESS) -> dict[int, Inversion]:
    """Depth and diffusivity of each anomaly with the thermal model (one site table).

    Parameters
    ----------
    features : list of AnomalyFeatures
        With ``centre_k`` and ``ring_k`` series in degrees C (mosaic units).
    times_s : float64 (N,)
        Scan times.
    forcing : Forcing
    soil : Soil
        The site's fitted soil.

    Returns
    -------
    dict[int, Inversion]
        With the chain's error terms in the sigmas
        (:func:`clearfast_gis.thermal.error_budget.with_chain_errors`). Anomalies seen in
        fewer than 4 scans (with their background ring) are left out: their status is
        ``not_characterised``.
    """
    if not features:
        return {}
    radii = np.array([0.5 * f.diameter_m for f in features])
    nodes = radius_nodes(radii)
    progress.message(f"thermal model table for radii {', '.join(f'{r:.2f}' for r in nodes)} m")
    table = build_site_table(forcing, soil, nodes if nodes.size > 1 else float(nodes[0]),
                             times_s)
    out: dict[int, Inversion] = {}
    progress.start("characterise", len(features))
    for f, r in zip(features, radii, strict=True):
        centre = _band0(f.centre_k) + ZERO_CELSIUS_K
        ring = _band0(f.ring_k) + ZERO_CELSIUS_K
        r_tab = float(np.clip(r, nodes.min(), nodes.max()))
        if (np.isfinite(centre) & np.isfinite(ring)).sum() >= 4:
            out[f.id] = with_chain_errors(invert_anomaly(times_s, centre, ring, forcing, soil,
                                                         r_tab, table=table))
        progress.advance()
    progress.close()
    return out


def _day_night_contrast(times_s: np.ndarray, contrast: np.ndarray, longitude_deg: float
                        ) -> tuple[float, float]:
    hour = (times_s / 3600.0 + longitude_deg / 15.0) % 24.0
    day = (hour >= 10) & (hour <= 16)
    night = (hour >= 22) | (hour <= 5)
    c = _band0(contrast)

    def pick(sel):
        v = c[sel & np.isfinite(c)]
        return float(v[np.argmax(np.abs(v))]) if v.size else math.nan

    return pick(day), pick(night)


def _daytime_sign(behaviour: str, contrast_day_k: float, contrast_k: np.ndarray) -> str:
    """``hot``/``cold``: the sign of the daytime contrast (schemas/anomaly.schema.json)."""
    if behaviour in ("warm_day_cool_night", "warm"):
        return "hot"
    if behaviour == "cool":
        return "cold"
    if math.isfinite(contrast_day_k):
        return "hot" if contrast_day_k >= 0 else "cold"
    mean = float(np.nanmean(_band0(contrast_k))) if np.isfinite(_band0(contrast_k)).any() else 0
    return "hot" if mean >= 0 else "cold"


def suspect_records(anomalies: AnomalySet, times_s: np.ndarray, longitude_deg: float,
                    fix_quality: int | None, survey_code: str) -> list[dict]:
    """Attribute records of the ``suspects`` layer (schemas/anomaly.schema.json)."""
    from clearfast_gis.report.html import figure_name

    records = []
    for f in anomalies.features:
        inv = anomalies.inversions.get(f.id)
        aid = f"{survey_code}-{f.id:04d}"
        day, night = _day_night_contrast(times_s, f.contrast_k, longitude_deg)
        cue, conf = classify(f, inv, contrast_day_k=day)
        rec = {
            "anomaly_id": aid, "x": float(f.x), "y": float(f.y),
            "area_m2": float(f.area_m2), "diameter_m": float(f.diameter_m),
            "circularity": float(f.circularity),
            "depth_m": inv.depth_m if inv else None,
            "depth_sigma_m": inv.depth_sigma_m if inv else None,
            "diffusivity_m2s": inv.alpha_m2s if inv else None,
            "diffusivity_sigma_m2s": inv.alpha_sigma_m2s if inv else None,
            "status": inv.status if inv else "not_characterised",
            "polarity": _daytime_sign(f.polarity, day, f.contrast_k),
            "diurnal_behaviour": f.polarity, "class_cue": cue, "confidence": float(conf),
            "n_scans": int(f.n_scans), "contrast_day_k": day, "contrast_night_k": night,
            "fix_quality": fix_quality, "figure": figure_name(aid),
            "contrast_series": {"time_utc": [format_utc(t) for t in times_s],
                                "contrast_k": [float(v) for v in _band0(f.contrast_k)]},
            "score": float(f.score),
        }
        records.append(rec)
    return records
