"""Features of each detected anomaly: position, size, shape, polarity, contrast series, score.

Definitions (also in docs/detection.md):

- centroid: mean (row, col) of the half-maximum footprint's pixels (below; pixel centres at
  integers): the object, even when the blob took in neighbouring texture; map centroid
  ``transform * (col + 0.5, row + 0.5)`` (the rasterio affine of the grid maps pixel corners).
- area: pixel count of the detected blob (and ``count * pixel_size_m**2``).
- diameter: equivalent diameter ``sqrt(4 A / pi)`` of the half-maximum thermal footprint
  (:func:`half_max_footprint`: the connected region around the centroid where the pixel's RMS
  deviation from the background ring over the scans exceeds half the blob's peak). The
  thresholded blob also takes in blur and thermal halo and overstates the size;
  ``blob_diameter_px`` keeps the blob's own equivalent diameter.
- circularity (paper §6): mean of the minor/major axis ratio of the blob's inertia ellipse and
  the compactness ``4 pi A / P**2``. P is scikit-image's ``regionprops`` perimeter (boundary
  pixels of the 4-connected contour weighted 1, sqrt(2) or (1+sqrt(2))/2 by configuration); on
  small digital disks that estimator gives compactness slightly above 1, so it is clipped to 1.
- contrast series: per scan (and band), ``centre = mean over the half-maximum footprint`` and
  ``ring = mean over an annulus around the centroid`` with radii ``ring_radii`` times the
  equivalent radius (at least 1 and 2 pixels beyond the blob), excluding every detected blob and
  no-data; ``contrast = centre - ring`` (K when the stack is in K or degrees C).
- polarity per scan: +1 warm, -1 cool, 0 not seen. With a :class:`DetectionResult`, a scan
  supports the blob when its hot (cold) reconstruction L_i touches it; when both do, the sign of
  the contrast decides. Without one, the sign of the contrast where ``|contrast| >= 2 sigma_ring``.
- summary polarity: 'warm_day_cool_night' when at least 2/3 of the supporting day scans (local
  solar hour in [9, 17)) are warm and at least 2/3 of the supporting night scans (solar hour in
  [20, 24) or [0, 6)) are cool, both present; otherwise 'warm' (>= 80 % of the supporting scans
  warm), 'cool' (>= 80 % cool), 'mixed', or 'none' without support. Dawn and dusk scans
  (zero-contrast periods) count for 'warm'/'cool'/'mixed' only.
- score: contrast-to-noise ratio ``|contrast| / sigma`` (median over the supporting scans,
  over all scans if none) times the shape term ``0.5 + 0.5 * circularity`` times the size term
  ``log10(1 + area_px)``. sigma is the standard deviation of the ring (``noise='ring'``) or of
  the whole valid image of that scan (``noise='image'``, steadier on textured snapshots).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np
from skimage.measure import regionprops

from clearfast_gis.detection.detector import DetectionResult, as_image_stack, count_finite
from clearfast_gis.solar import local_solar_hour

__all__ = ["AnomalyFeatures", "blob_features", "features_table", "summary_polarity"]

# Apparent solar time, day [9, 17) h and night [20, 6) h: the scans whose sign sets the
# diurnal behaviour of a blob (wide windows, so that most scans vote).
DAY_HOURS = (9.0, 17.0)
NIGHT_HOURS = (20.0, 6.0)


@dataclass
class AnomalyFeatures:
    """Features of one anomaly (see the module notes for the definitions).

    Shapes: N scans, B bands; the series are (N,) for a single-band stack, else (N, B).
    """

    id: int
    row: float
    col: float
    x: float
    y: float
    area_px: int
    area_m2: float
    diameter_px: float
    diameter_m: float
    circularity: float
    axis_ratio: float
    compactness: float
    polarity_per_scan: np.ndarray
    polarity: str
    n_scans: int
    centre_k: np.ndarray
    ring_k: np.ndarray
    contrast_k: np.ndarray
    noise_k: np.ndarray
    score: float
    bbox: tuple[int, int, int, int] = field(default=(0, 0, 0, 0))
    blob_diameter_px: float = float("nan")


def summary_polarity(polarity_per_scan: np.ndarray, times_s: np.ndarray | None = None,
                     longitude_deg: float | None = None) -> str:
    """Summarise per-scan polarities (+1 warm, -1 cool, 0 none) over the day.

    Parameters
    ----------
    polarity_per_scan : ndarray (N,) of int
    times_s : ndarray (N,), optional
        Scan times, UTC epoch seconds.
    longitude_deg : float, optional
        Site longitude (east positive), for the local solar hour.

    Returns
    -------
    str
        'warm_day_cool_night', 'warm', 'cool', 'mixed' or 'none'.
    """
    pol = np.asarray(polarity_per_scan).astype(int)
    seen = pol != 0
    if not seen.any():
        return "none"
    if times_s is not None and longitude_deg is not None:
        hour = local_solar_hour(np.asarray(times_s, dtype=np.float64), longitude_deg)
        day = (hour >= DAY_HOURS[0]) & (hour < DAY_HOURS[1]) & seen
        night = ((hour >= NIGHT_HOURS[0]) | (hour < NIGHT_HOURS[1])) & seen
        if (day.any() and night.any() and np.mean(pol[day] > 0) >= 2 / 3
                and np.mean(pol[night] < 0) >= 2 / 3):
            return "warm_day_cool_night"
    warm = float(np.mean(pol[seen] > 0))
    if warm >= 0.8:
        return "warm"
    if warm <= 0.2:
        return "cool"
    return "mixed"


def _circularity(region) -> tuple[float, float, float]:
    major = float(region.axis_major_length)
    minor = float(region.axis_minor_length)
    ratio = minor / major if major > 0 else 1.0
    perim = float(region.perimeter)
    compact = min(1.0, 4.0 * np.pi * region.area / perim**2) if perim > 0 else 1.0
    return 0.5 * (ratio + compact), ratio, compact


def _ring_pixels(labels: np.ndarray, valid: np.ndarray, row: float, col: float,
                 r_in: float, r_out: float, only: int | None = None
                 ) -> tuple[np.ndarray, np.ndarray]:
    """Ring pixels outside every blob, or outside blob ``only`` alone when given."""
    h, w = labels.shape
    r0, r1 = max(0, int(np.floor(row - r_out))), min(h, int(np.ceil(row + r_out)) + 1)
    c0, c1 = max(0, int(np.floor(col - r_out))), min(w, int(np.ceil(col + r_out)) + 1)
    rr, cc = np.mgrid[r0:r1, c0:c1]
    d2 = (rr - row) ** 2 + (cc - col) ** 2
    box = labels[r0:r1, c0:c1]
    free = box == 0 if only is None else box != only
    sel = (d2 >= r_in**2) & (d2 <= r_out**2) & free & valid[r0:r1, c0:c1]
    return rr[sel], cc[sel]


def half_max_footprint(cube: np.ndarray, labels: np.ndarray, label: int, row: float,
                       col: float, ring: np.ndarray, bbox: tuple[int, int, int, int],
                       grow_px: int) -> tuple[np.ndarray, np.ndarray]:
    """Pixels of a blob's half-maximum thermal footprint.

    The amplitude of each pixel is its RMS deviation from the blob's background ring over
    the scans and bands, ``S = sqrt(mean_i (T_i - ring_i)^2)``; the footprint is the
    connected region around the blob's strongest pixel where ``S`` exceeds half the blob's
    peak amplitude (the 95th percentile of ``S`` in the blob, robust to noise), searched within
    the blob's box grown by ``grow_px``. For a disc seen through a moderate blur its area is
    the disc's, whereas the detector's thresholded blob also takes in part of the blur and of the
    thermal halo.

    Parameters
    ----------
    cube : float (N, B, H, W)
    labels : int (H, W)
    label : int
    row, col : float
        Blob centroid, pixels (kept for the interface; the seed is the amplitude peak).
    ring : float (N, B)
        Background ring mean per scan and band (NaN: that scan and band are left out).
    bbox : (min_row, min_col, max_row, max_col)
    grow_px : int

    Returns
    -------
    rows, cols : int arrays
        The footprint's pixels (the blob's own pixels when no footprint is found).
    """
    from scipy import ndimage

    h, w = labels.shape
    r0, c0 = max(0, bbox[0] - grow_px), max(0, bbox[1] - grow_px)
    r1, c1 = min(h, bbox[2] + grow_px), min(w, bbox[3] + grow_px)
    sub = cube[:, :, r0:r1, c0:c1] - ring[:, :, None, None]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=RuntimeWarning)
        amp = np.sqrt(np.nanmean(sub.reshape(-1, r1 - r0, c1 - c0) ** 2, axis=0))
    own = labels[r0:r1, c0:c1] == label
    vals = amp[own & np.isfinite(amp)]
    if vals.size == 0:
        rr, cc = np.nonzero(own)
        return rr + r0, cc + c0
    peak = np.percentile(vals, 95)
    above = np.nan_to_num(amp, nan=0.0) >= 0.5 * peak
    lab, _ = ndimage.label(above)
    # seed at the blob's strongest pixel: a blob that took in neighbouring texture keeps the
    # object where its diurnal amplitude peaks
    own_amp = np.where(own, np.nan_to_num(amp, nan=-np.inf), -np.inf)
    rc, cc_ = np.unravel_index(int(np.argmax(own_amp)), own_amp.shape)
    core = lab[rc, cc_]
    if core == 0:
        ids, counts = np.unique(lab[own & (lab > 0)], return_counts=True)
        if ids.size == 0:
            rr, cc = np.nonzero(own)
            return rr + r0, cc + c0
        core = ids[np.argmax(counts)]
    rr, cc = np.nonzero(lab == core)
    return rr + r0, cc + c0


def blob_features(
    labels: np.ndarray,
    stack: np.ndarray,
    times_s: np.ndarray | None = None,
    transform=None,
    pixel_size_m: float | None = None,
    detection: DetectionResult | None = None,
    longitude_deg: float | None = None,
    ring_radii: tuple[float, float] = (1.5, 2.5),
    noise: str = "ring",
) -> list[AnomalyFeatures]:
    """Measure every labelled anomaly.

    Parameters
    ----------
    labels : ndarray of int (H, W)
        Anomaly labels (0 = background), e.g. ``DetectionResult.labels``.
    stack : ndarray (H, W), (N, H, W) or (N, B, H, W)
        Apparent temperature (K or degrees C), NaN = no-data.
    times_s : ndarray (N,), optional
        Scan times, UTC epoch seconds (for the summary polarity).
    transform : affine.Affine, optional
        Grid transform (pixel corner -> map), for the map centroid.
    pixel_size_m : float, optional
        Ground pixel size in metres; default ``sqrt(|det(transform)|)`` when a transform is
        given. Without either, the metric fields are NaN.
    detection : DetectionResult, optional
        Gives the per-scan support (hot and cold L_i maps).
    longitude_deg : float, optional
        Site longitude for the local solar hour.
    ring_radii : (float, float)
        Inner and outer radius of the background ring, in equivalent radii of the blob.
    noise : {'ring', 'image'}
        Noise estimate of the score: the ring's standard deviation or the image's.

    Returns
    -------
    list of AnomalyFeatures, in label order.
    """
    labels = np.asarray(labels)
    images, n, b = as_image_stack(stack)
    if images.shape[1:] != labels.shape:
        raise ValueError(f"labels {labels.shape} and stack {images.shape[1:]} differ in shape")
    if times_s is not None and len(np.atleast_1d(times_s)) != n:
        raise ValueError(f"{len(np.atleast_1d(times_s))} times for {n} scans")
    if noise not in ("ring", "image"):
        raise ValueError(f"noise must be 'ring' or 'image', got {noise!r}")
    cube = images.reshape(n, b, *labels.shape)
    # a pixel seen in some scans only (a footprint that moves, paper §6) still serves the
    # ring of those scans: every mean below is over the scans that saw it
    valid = count_finite(images) > 0
    image_noise = None
    if noise == "image":  # per image, so that no copy of the whole stack is made
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", category=RuntimeWarning)
            image_noise = np.array([[np.nanstd(cube[i, j]) for j in range(b)]
                                    for i in range(n)])
    if pixel_size_m is None and transform is not None:
        pixel_size_m = float(np.sqrt(abs(transform.a * transform.e - transform.b * transform.d)))
    ps = float("nan") if pixel_size_m is None else float(pixel_size_m)
    out = []
    for region in regionprops(labels.astype(np.int32)):
        rows, cols = region.coords[:, 0], region.coords[:, 1]
        row, col = (float(v) for v in region.centroid)
        area = int(region.area)
        diameter = float(np.sqrt(4.0 * area / np.pi))
        circ, ratio, compact = _circularity(region)
        r_eq = diameter / 2.0
        r_in = max(ring_radii[0] * r_eq, r_eq + 1.0)
        r_out = max(ring_radii[1] * r_eq, r_in + 2.0)
        rr, cc = _ring_pixels(labels, valid, row, col, r_in, r_out)
        if rr.size < 2:  # inside another blob (a compact object split from a warm patch):
            # the patch around it is its background
            rr, cc = _ring_pixels(labels, valid, row, col, r_in, r_out, only=int(region.label))
        with np.errstate(invalid="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", category=RuntimeWarning)
            centre = np.nanmean(cube[:, :, rows, cols], axis=2)
            ring = np.nanmean(cube[:, :, rr, cc], axis=2) if rr.size else np.full((n, b), np.nan)
            noise_k = (np.nanstd(cube[:, :, rr, cc], axis=2) if rr.size > 1
                       else np.full((n, b), np.nan))
        fr, fc = half_max_footprint(cube, labels, int(region.label), row, col,
                                    ring, region.bbox,
                                    grow_px=int(np.ceil(r_eq)))
        fwhm_diameter = float(np.sqrt(4.0 * fr.size / np.pi))
        row, col = float(fr.mean()), float(fc.mean())
        with np.errstate(invalid="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", category=RuntimeWarning)
            centre = np.nanmean(cube[:, :, fr, fc], axis=2)
        contrast = centre - ring
        sigma = noise_k if noise == "ring" else image_noise
        cnr = np.abs(contrast) / np.maximum(sigma, 1e-6)
        with warnings.catch_warnings():  # a scan that did not see the blob: an all-NaN row
            warnings.simplefilter("ignore", category=RuntimeWarning)
            c_scan = np.nanmean(contrast, axis=1) if b > 1 else contrast[:, 0]
            cnr_scan = np.nanmax(cnr, axis=1)
        pol = _polarity(detection, rows, cols, c_scan, cnr_scan, n)
        seen = pol != 0
        support = cnr_scan[seen] if seen.any() else cnr_scan
        support = support[np.isfinite(support)]
        shape_size = (0.5 + 0.5 * circ) * np.log10(1.0 + area)
        score = float(np.median(support)) * shape_size if support.size else 0.0
        x = y = float("nan")
        if transform is not None:
            u, v = col + 0.5, row + 0.5
            x = transform.a * u + transform.b * v + transform.c
            y = transform.d * u + transform.e * v + transform.f
        squeeze = (lambda a: a[:, 0]) if b == 1 else (lambda a: a)
        out.append(AnomalyFeatures(
            id=int(region.label), row=row, col=col, x=float(x), y=float(y),
            area_px=area, area_m2=area * ps**2, diameter_px=fwhm_diameter,
            diameter_m=fwhm_diameter * ps, blob_diameter_px=diameter,
            circularity=circ, axis_ratio=ratio, compactness=compact,
            polarity_per_scan=pol, polarity=summary_polarity(pol, times_s, longitude_deg),
            n_scans=int(seen.sum()), centre_k=squeeze(centre), ring_k=squeeze(ring),
            contrast_k=squeeze(contrast), noise_k=squeeze(noise_k), score=score,
            bbox=tuple(int(v) for v in region.bbox),
        ))
    return out


def _polarity(detection: DetectionResult | None, rows: np.ndarray, cols: np.ndarray,
              contrast: np.ndarray, cnr: np.ndarray, n: int) -> np.ndarray:
    sign = np.sign(np.nan_to_num(contrast)).astype(np.int8)
    if detection is None:
        return np.where(np.nan_to_num(cnr) >= 2.0, sign, 0).astype(np.int8)
    hot = detection.scan_hot[:, rows, cols].any(axis=1)
    cold = detection.scan_cold[:, rows, cols].any(axis=1)
    pol = np.zeros(n, dtype=np.int8)
    pol[hot & ~cold] = 1
    pol[cold & ~hot] = -1
    both = hot & cold
    pol[both] = sign[both]
    return pol


def features_table(features: list[AnomalyFeatures]) -> dict[str, np.ndarray]:
    """The scalar fields of a feature list as a table (dict of 1-D arrays, one row per
    anomaly); the series stay in the :class:`AnomalyFeatures` objects."""
    names = ["id", "row", "col", "x", "y", "area_px", "area_m2", "diameter_px", "diameter_m",
             "circularity", "axis_ratio", "compactness", "polarity", "n_scans", "score"]
    return {k: np.array([getattr(f, k) for f in features]) for k in names}
