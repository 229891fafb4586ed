"""Coverage-relative voting and splitting of merged blobs on a temporal stack of mosaics
(paper §4.4-4.5), and the detector run on mosaics with sizes in metres."""

from __future__ import annotations

import dataclasses
from functools import partial

import numpy as np

from clearfast_gis.detection import blob_features, detect_anomalies
from clearfast_gis.detection.classify import AT_DIAMETER_M
from clearfast_gis.detection.clutter import image_clutter_k
from clearfast_gis.detection.compact import split_oversized
from clearfast_gis.detection.deep import (
    core_contrast,
    core_polarity,
    deep_cores,
    stack_match,
    with_core_support,
)
from clearfast_gis.detection.screening import MIN_DIAMETER_M
from clearfast_gis.detection.stack import as_scan_stack
from clearfast_gis.minetypes import MINE_TYPES
from clearfast_gis.progress import NULL_PROGRESS, Progress


def disk_px(size_m: float, pixel_size_m: float, minimum: int = 3) -> int:
    """A structuring-element diameter in metres as an odd number of pixels (>= minimum).

    Examples
    --------
    >>> disk_px(0.5, 0.02), disk_px(0.06, 0.02), disk_px(0.01, 0.02)
    (25, 3, 3)
    """
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

    Examples
    --------
    >>> import numpy as np
    >>> coverage_level(0.25, np.array([[48, 24, 4]]), n_scans=48, n_bands=1)
    array([[12.,  6.,  3.]])
    """
    floor = max(1, min(MIN_SUPPORT_SCANS * n_bands, round(fraction * n_scans * n_bands)))
    return np.maximum(np.round(fraction * covered), floor).astype(np.float64)


def detect_on_mosaics(stack_c: np.ndarray, times_s: np.ndarray, transform, pixel_size_m: float,
                      longitude_deg: float, d1_m: float, d2_m: float, epsilon: float,
                      level: int | None, gamma: float | None, max_anomalies: int,
                      level_fraction: float = 0.5, gamma_fraction: float | None = None,
                      progress: Progress = NULL_PROGRESS,
                      threshold_snr: float | None = None,
                      deep_templates_k: np.ndarray | None = None,
                      deep_radius_m: float | None = None) -> tuple[np.ndarray, list]:
    """The morphological detector on mosaics, and blob features.

    Parameters
    ----------
    stack_c : ScanStack or float32 (N, B, H, W)
        Co-registered mosaics, degrees C, NaN = no data
        (:mod:`clearfast_gis.detection.stack`: read scan by scan, never held whole).
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
        Keep the highest-scoring blobs of the detector (the deep cores come on top).
    threshold_snr : float or None
        Cap of each image's stretch cut at this many times its clutter
        (:func:`clearfast_gis.detection.clutter.image_clutter_k`); None: the stretch alone.
        The stretch cut is half the top percentile of the hat image: on a day whose mines
        give a few tenths of a kelvin among markers and vegetation of several kelvins it lies
        above a mine that stands 5-8 sigma above the clutter.
    deep_templates_k : float (T, N), optional
        Modelled contrast of a buried object per template and scan, K
        (:func:`clearfast_gis.thermal.daycontrast.reference_curves` at
        :data:`clearfast_gis.detection.deep.DEEP_DEPTHS_M`): the stack's matched filter then
        adds the deep cores (:func:`clearfast_gis.detection.deep.deep_cores`) the per-scan
        detector missed or swallowed into an oversized blob. None: no deep search.
    deep_radius_m : float, optional
        Radius of the templates' object, m (with ``deep_templates_k``).

    Returns
    -------
    labels : int32 (H, W)
        Relabelled 1..K in the order of ``features``.
    features : list of AnomalyFeatures
    """
    source = as_scan_stack(stack_c)
    n_scans, n_bands = source.n_scans, source.n_bands
    if level is None:
        level = partial(coverage_level, level_fraction, n_scans=n_scans, n_bands=n_bands)
    if gamma is None and gamma_fraction is not None:
        gamma = partial(coverage_level, gamma_fraction, n_scans=n_scans, n_bands=n_bands)
    ceiling = None if threshold_snr is None else (
        lambda img: threshold_snr * image_clutter_k(img, pixel_size_m))
    det = detect_anomalies(source, disk_px(d1_m, pixel_size_m), disk_px(d2_m, pixel_size_m),
                           epsilon=epsilon, level=level, gamma=gamma, progress=progress,
                           ceiling=ceiling)
    split = split_by_cores(det.labels, det.votes, det.level)
    split = split_oversized(split, source, disk_px(d1_m, pixel_size_m),
                            disk_px(d2_m, pixel_size_m), d1_m / pixel_size_m)
    if deep_templates_k is not None:
        if deep_radius_m is None:
            raise ValueError("deep_templates_k needs deep_radius_m")
        radius_px = deep_radius_m / pixel_size_m
        match = stack_match(source, deep_templates_k, radius_px)
        split, cores = deep_cores(split, match, radius_px, d1_m / pixel_size_m,
                                  spacing_px=AT_DIAMETER_M[1] / pixel_size_m,
                                  min_area_px=np.pi * (0.5 * MIN_DIAMETER_M / pixel_size_m) ** 2)
        contrast = core_contrast(source, cores, radius_px)
        wide = core_contrast(source, cores, max(t.radius_m for t in MINE_TYPES) / pixel_size_m)
        det = with_core_support(det, split, cores, core_polarity(contrast, match.sigma_k))
    deep = {label: j for j, (label, _, _) in enumerate(cores)} \
        if deep_templates_k is not None else {}
    feats = blob_features(split, source, times_s=times_s, transform=transform,
                          pixel_size_m=pixel_size_m, detection=det, longitude_deg=longitude_deg)
    feats = [dataclasses.replace(f, core_contrast_k=contrast[:, deep[f.id]],
                                 core_wide_contrast_k=wide[:, deep[f.id]],
                                 core_noise_k=match.sigma_k) if f.id in deep else f
             for f in feats]
    # the cap ranks the detector's blobs; the deep cores, few by construction and weak in
    # any one scan, come on top of it
    feats = sorted((f for f in feats if f.id not in deep),
                   key=lambda f: (-f.score, f.id))[:max_anomalies] \
        + [f for f in feats if f.id in deep]
    # one look-up table for the renumbering (not one pass over the image per blob)
    renumber = np.zeros(int(split.max(initial=0)) + 1, dtype=np.int32)
    renumbered = []
    for new_id, f in enumerate(feats, start=1):
        renumber[f.id] = new_id
        renumbered.append(dataclasses.replace(f, id=new_id))
    return renumber[split], renumbered
