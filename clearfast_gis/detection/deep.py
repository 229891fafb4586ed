"""Buried objects below the per-scan cut: a matched filter of the whole stack.

A mine 6-8 cm deep gives a few hundredths of a kelvin to a tenth, two to four clutter sigmas
in any one scan: the detector's per-scan cut (paper §4) never fires on it, or it fires inside
a warm patch of ground that is set aside as too large. Its contrast does however follow the
thermal model's curve for a buried object over the whole day (warm by day, cool by night,
late by hours), while soil texture, stones and vegetation follow other curves or none.

For every scan the mean of its bands is filtered into the contrast of a disc of the reference
mine's radius against its ring at :data:`RING_RADII` radii (:func:`disc_ring_contrast`) and
divided by that image's robust spread ``sigma_k``. With ``m_k`` the modelled curve of a
buried object (:func:`clearfast_gis.thermal.daycontrast.reference_curves`, one template per
depth of :data:`DEEP_DEPTHS_M`) and ``z_k = c_k / sigma_k``, the matched filter is

    score = sum_k u_k z_k / sqrt(sum_k u_k**2),   u_k = m_k / sigma_k,

summed over the scans with data at the pixel, the best over the templates: the contrast's
signal-to-noise ratio over the whole stack, in noise sigmas, positive for a mine-like curve.
The share of the stack's energy beyond noise that the template explains,

    explained = score**2 / (sum_k z_k**2 - (n - 1)),

is near 1 for an object whose curve is the template's (its residual is the noise, n - 1
degrees of freedom) and well below for a vegetation patch or a stone, however strong.
A local peak of the score is a deep core (:func:`deep_cores`) when it reaches
:data:`MIN_SCORE` with :data:`MIN_EXPLAINED` explained, away from every blob the detector
kept, or inside one too large to be a mine.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import cv2
import numpy as np
from scipy import ndimage

from clearfast_gis.detection._matchsum import add_scan
from clearfast_gis.detection.detector import DetectionResult, unpack_bits
from clearfast_gis.detection.features import RING_RADII
from clearfast_gis.detection.multiscale import robust_sigma
from clearfast_gis.detection.stack import as_scan_stack, map_scans

__all__ = ["DEEP_DEPTHS_M", "MIN_EXPLAINED", "MIN_SCAN_SHARE", "MIN_SCORE", "StackMatch",
           "core_contrast", "core_polarity",
           "deep_cores", "disc_ring_contrast", "stack_match", "with_core_support"]

#: Depths of the buried-object templates, m: below the shallow mines the per-scan detector
#: finds, to the deepest the thermal model can show on a good day.
DEEP_DEPTHS_M = (0.05, 0.06, 0.07, 0.08, 0.10)

#: Smallest matched-filter score of a deep core, noise sigmas over the stack (sized on the
#: deep scenario's seeds 20-22 and trial seed 5: docs/detection.md).
MIN_SCORE = 6.0

#: Smallest share of the stack's energy beyond noise the template explains at a deep core.
MIN_EXPLAINED = 0.85

#: Fewest scans with data at a deep core ...
MIN_SCANS = 3

#: ... and the least share of the survey's scans: the template tells a buried object from
#: texture by its whole diurnal shape, which a pixel seen over part of the day does not show.
#: Under the drifting lift (trial seed 1) every one of the 115 texture peaks above the cuts
#: lies where 4-23 of the 48 scans have data.
MIN_SCAN_SHARE = 0.75

#: A scan supports a deep core when the core's disc-ring contrast reaches this many of the
#: scan's spreads (either sign).
SUPPORT_SIGMA = 1.0


def _disc_ring_kernels(radius_px: float) -> tuple[np.ndarray, np.ndarray]:
    """Disc (radius ``radius_px``) and ring (``RING_RADII`` radii) footprints, float32."""
    reach = int(np.ceil(RING_RADII[1] * radius_px))
    y, x = np.mgrid[-reach:reach + 1, -reach:reach + 1]
    d = np.hypot(x, y)
    disc = d <= radius_px
    ring = (d >= RING_RADII[0] * radius_px) & (d <= RING_RADII[1] * radius_px)
    return disc.astype(np.float32), ring.astype(np.float32)


def disc_ring_contrast(image: np.ndarray, radius_px: float) -> np.ndarray:
    """Mean over a disc minus the mean over its ring, at every pixel.

    Parameters
    ----------
    image : float (H, W)
        Apparent temperature (K or degrees C), NaN = no data.
    radius_px : float
        Disc radius, pixels; the ring spans :data:`RING_RADII` radii.

    Returns
    -------
    float32 (H, W)
        Contrast in the image's unit (K); NaN where less than half of the disc or of the
        ring has data.
    """
    ok = np.isfinite(image)
    filled = np.where(ok, image, 0.0).astype(np.float32)
    weight = ok.astype(np.float32)
    means = []
    for k in _disc_ring_kernels(radius_px):
        total = cv2.filter2D(filled, -1, k, borderType=cv2.BORDER_CONSTANT)
        count = cv2.filter2D(weight, -1, k, borderType=cv2.BORDER_CONSTANT)
        with np.errstate(invalid="ignore", divide="ignore"):
            means.append(np.where(count >= 0.5 * float(k.sum()), total / count, np.nan))
    return (means[0] - means[1]).astype(np.float32)


def _band_mean(bands: np.ndarray) -> np.ndarray:
    """Mean over the bands with data of one scan, float32 (H, W) (NaN where none has)."""
    ok = np.isfinite(bands)
    with np.errstate(invalid="ignore", divide="ignore"):
        return (np.where(ok, bands, 0.0).sum(axis=0) / ok.sum(axis=0)).astype(np.float32)


@dataclass(frozen=True)
class StackMatch:
    """Output of :func:`stack_match`.

    Attributes
    ----------
    score : float32 (H, W)
        Best matched-filter score over the templates, noise sigmas (NaN without data).
    explained : float32 (H, W)
        Share of the stack's energy beyond noise that the best template explains, 0-1.
    depth_index : int16 (H, W)
        Index of the best template.
    scans : int32 (H, W)
        Scans with data at each pixel.
    sigma_k : float64 (N,)
        Robust spread of each scan's disc-ring contrast, K (NaN for a scan without data).
    """

    score: np.ndarray
    explained: np.ndarray
    depth_index: np.ndarray
    scans: np.ndarray
    sigma_k: np.ndarray


def stack_match(stack, templates_k: np.ndarray, radius_px: float) -> StackMatch:
    """The matched filter of the module over a stack, read scan by scan.

    Parameters
    ----------
    stack : ScanStack, or float32 (N, H, W) or (N, B, H, W)
        Apparent temperature per scan (and band), NaN = no data.
    templates_k : float (T, N)
        Modelled contrast of a buried object per template and scan, K (only their shapes
        and relative size over the scans matter).
    radius_px : float
        Disc radius of :func:`disc_ring_contrast`, pixels.

    Returns
    -------
    StackMatch
    """
    source = as_scan_stack(stack)
    templates = np.asarray(templates_k, dtype=np.float64)
    if templates.ndim != 2 or templates.shape[1] != source.n_scans:
        raise ValueError(f"templates {templates.shape} for {source.n_scans} scans")
    shape, n_t = source.shape, templates.shape[0]
    num = np.zeros((n_t, *shape), dtype=np.float64)
    den = np.zeros((n_t, *shape), dtype=np.float64)
    energy = np.zeros(shape, dtype=np.float64)
    scans = np.zeros(shape, dtype=np.int32)
    sigmas = np.full(source.n_scans, np.nan)

    def one_scan(_scan: int, bands: np.ndarray) -> tuple[np.ndarray, float] | None:
        if not np.isfinite(bands).any():
            return None
        c = disc_ring_contrast(_band_mean(bands), radius_px)
        sigma = robust_sigma(c)
        return (c / sigma, sigma) if sigma > 0 else None

    for k, scan in enumerate(map_scans(one_scan, source)):
        if scan is None:
            continue
        z, sigma = scan
        sigmas[k] = sigma
        add_scan(np.ascontiguousarray(z, dtype=np.float32), templates[:, k] / sigma, num, den,
                 energy, scans)
    with np.errstate(invalid="ignore", divide="ignore"):
        per_template = np.where(den > 0, num / np.sqrt(den), -np.inf)
    best = np.argmax(per_template, axis=0)
    score = np.take_along_axis(per_template, best[None], axis=0)[0]
    score = np.where(scans > 0, score, np.nan)
    excess = energy - np.maximum(scans - 1, 0)
    with np.errstate(invalid="ignore", divide="ignore"):
        explained = np.where(score > 0, np.minimum(
            score**2 / np.maximum(excess, 1e-12), 1.0), 0.0)
    return StackMatch(score.astype(np.float32), explained.astype(np.float32),
                      best.astype(np.int16), scans, sigmas)


def deep_cores(labels: np.ndarray, match: StackMatch, radius_px: float,
               max_diameter_px: float, spacing_px: float, min_area_px: float = 0.0,
               min_score: float = MIN_SCORE,
               min_explained: float = MIN_EXPLAINED, min_scans: int = MIN_SCANS,
               min_scan_share: float = MIN_SCAN_SHARE
               ) -> tuple[np.ndarray, list[tuple[int, int, int]]]:
    """Give every deep core of the matched filter a disc label of its own.

    A core is a local maximum of ``match.score`` (over a square of side ``spacing_px``: one
    core per mine, the largest included) that reaches ``min_score`` with ``min_explained``
    explained and data in ``min_scans`` scans and ``min_scan_share`` of the survey's.
    Cores are taken best first; one with a kept blob (at least ``min_area_px`` in area and
    at most ``max_diameter_px`` in equivalent diameter: smaller blobs, a few cells of texture
    or of the mine itself, are no object) or an earlier core closer to its peak than half
    the spacing plus the radius is left out: the object is found already, or the core is its
    thermal halo (the lateral heat of a strong shallow mine reaches its
    surroundings late, as a deeper object's would; trial seed 5 shows such halos 0.2-0.4 m
    from the centres of shallow AP and surface-laid AT mines). Inside a blob too large to be
    a mine, the disc is cut out of it.

    Parameters
    ----------
    labels : int (H, W)
        Blobs of the detector (0 = background).
    match : StackMatch
        The matched filter on the same grid.
    radius_px : float
        The reference mine's radius, pixels (the core's disc).
    max_diameter_px : float
        Blobs with a larger equivalent diameter are searched.
    spacing_px : float
        Side of the square a core is the largest score of, pixels.
    min_area_px : float
        Blobs smaller than this (pixels) are open ground to a core.
    min_score, min_explained : float
    min_scans : int
    min_scan_share : float

    Returns
    -------
    labels : int32 (H, W)
        The input's labels, and one new label per core (numbered after the largest).
    cores : list of (label, row, col)
        Each new core's label and its peak pixel, in label order.
    """
    out = labels.astype(np.int32).copy()
    size = max(3, int(round(spacing_px)) | 1)
    score = np.where(np.isfinite(match.score), match.score, -np.inf).astype(np.float32)
    peaks = (score >= min_score) & (score == ndimage.maximum_filter(score, size=size)) \
        & (match.explained >= min_explained) \
        & (match.scans >= max(min_scans, np.ceil(min_scan_share * match.sigma_k.size)))
    rows, cols = np.nonzero(peaks)
    cores: list[tuple[int, int, int]] = []
    if rows.size == 0:
        return out, cores
    areas = np.bincount(out.ravel())
    open_ground = (2.0 * np.sqrt(areas / np.pi) > max_diameter_px) | (areas < min_area_px)
    open_ground[0] = True  # the background is open too
    guard = 0.5 * spacing_px + radius_px
    reach = int(np.ceil(guard))
    y, x = np.mgrid[-reach:reach + 1, -reach:reach + 1]
    d = np.hypot(x, y)
    first_new = int(out.max()) + 1
    for i in np.lexsort((cols, rows, -score[rows, cols])):  # best first, ties by position
        r, c = int(rows[i]), int(cols[i])
        r0, r1 = max(0, r - reach), min(out.shape[0], r + reach + 1)
        c0, c1 = max(0, c - reach), min(out.shape[1], c + reach + 1)
        near = d[r0 - r + reach:r1 - r + reach, c0 - c + reach:c1 - c + reach]
        view = out[r0:r1, c0:c1]
        around = view[near <= guard]
        if np.any(around >= first_new) or not np.all(open_ground[around]):
            continue
        label = first_new + len(cores)
        view[near <= radius_px] = label
        cores.append((label, r, c))
    return out, cores


def core_contrast(stack, cores: list[tuple[int, int, int]], radius_px: float) -> np.ndarray:
    """Per scan, each core's disc-ring contrast (:func:`disc_ring_contrast`) at its peak.

    Parameters
    ----------
    stack : ScanStack, or float32 (N, H, W) or (N, B, H, W)
        Apparent temperature, K or degrees C.
    cores : list of (label, row, col)
        From :func:`deep_cores`.
    radius_px : float
        Disc radius, pixels.

    Returns
    -------
    float64 (N, C)
        Contrast, K (NaN where the scan has too little data there).
    """
    source = as_scan_stack(stack)
    reach = int(np.ceil(RING_RADII[1] * radius_px)) + 1
    h, w = source.shape
    windows = [(max(0, r - reach), min(h, r + reach + 1), max(0, c - reach),
                min(w, c + reach + 1), r, c) for _, r, c in cores]

    def one_scan(_scan: int, bands: np.ndarray) -> np.ndarray:
        out = np.full(len(windows), np.nan)
        for j, (r0, r1, c0, c1, r, c) in enumerate(windows):
            out[j] = disc_ring_contrast(_band_mean(bands[:, r0:r1, c0:c1]),
                                        radius_px)[r - r0, c - c0]
        return out

    return np.array(list(map_scans(one_scan, source))).reshape(source.n_scans, len(cores))


def core_polarity(contrast_k: np.ndarray, sigma_k: np.ndarray,
                  min_sigma: float = SUPPORT_SIGMA) -> np.ndarray:
    """Per scan, the sign of each core's disc-ring contrast where it reaches ``min_sigma``
    of that scan's spread (the scans that support it, as the per-scan maps L_i do for the
    detector's blobs).

    Parameters
    ----------
    contrast_k : float (N, C)
        The cores' contrast per scan (:func:`core_contrast`), K.
    sigma_k : float (N,)
        Each scan's spread of the disc-ring contrast (:attr:`StackMatch.sigma_k`), K.
    min_sigma : float

    Returns
    -------
    int8 (N, C)
        +1 warm, -1 cool, 0 not supported, per scan and core.
    """
    with np.errstate(invalid="ignore"):
        z = np.asarray(contrast_k) / np.asarray(sigma_k, dtype=np.float64)[:, None]
    z = np.nan_to_num(z)
    return (np.where(z >= min_sigma, 1, 0) - np.where(z <= -min_sigma, 1, 0)).astype(np.int8)


def with_core_support(detection: DetectionResult, labels: np.ndarray,
                      cores: list[tuple[int, int, int]], polarity: np.ndarray
                      ) -> DetectionResult:
    """The detector's result with each deep core's supporting scans added to the per-scan
    maps L_i (hot where it is warm, cold where cool), so that the blob features count and
    sign them as for the detector's own blobs.

    Parameters
    ----------
    detection : DetectionResult
    labels : int (H, W)
        Labels holding the cores.
    cores : list of (label, row, col)
    polarity : int8 (N, C)
        From :func:`core_polarity`.
    """
    if not cores:
        return detection
    index = {label: j for j, (label, _, _) in enumerate(cores)}
    slices = ndimage.find_objects(labels)
    bits = {1: detection.scan_hot_bits.copy(), -1: detection.scan_cold_bits.copy()}
    for label, j in index.items():
        sl = slices[label - 1]
        own = labels[sl] == label
        cols = slice(sl[1].start // 8, (sl[1].stop + 7) // 8)
        c0 = cols.start * 8
        for sign, packed in bits.items():
            for i in np.flatnonzero(polarity[:, j] == sign):
                block = unpack_bits(packed[i, sl[0], cols], (cols.stop - cols.start) * 8)
                block[:, sl[1].start - c0:sl[1].stop - c0] |= own
                packed[i, sl[0], cols] = np.packbits(block, axis=-1)[:, :cols.stop
                                                                     - cols.start]
    return dataclasses.replace(detection, scan_hot_bits=bits[1], scan_cold_bits=bits[-1])
