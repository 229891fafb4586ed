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

from clearfast_gis.detection.detector import DetectionResult, count_finite
from clearfast_gis.detection.stack import as_scan_stack, iter_images, map_scans
from clearfast_gis.solar import local_solar_hour

__all__ = ["RING_RADII", "AnomalyFeatures", "blob_features", "features_table", "ring_radii_px",
           "summary_polarity"]

#: Inner and outer radius of the background ring around an object, in its equivalent radii.
RING_RADII = (1.5, 2.5)

# Apparent solar time, day [9, 17) h and night [20, 6) h: the scans whose sign sets the
# diurnal behaviour of a blob (wide windows, so that most scans vote).
DAY_HOURS = (9.0, 17.0)
NIGHT_HOURS = (20.0, 6.0)


@dataclass
class AnomalyFeatures:
    """Features of one anomaly (see the module notes for the definitions).

    Shapes: N scans, B bands; the series are (N,) for a single-band stack, else (N, B).
    A deep core of the stack's matched filter (:mod:`clearfast_gis.detection.deep`) also
    carries ``core_contrast_k``, its disc-ring contrast at the peak per scan (N,), K,
    ``core_wide_contrast_k``, the same at the largest mine type's radius (N,), K, and
    ``core_noise_k``, each scan's spread of the first (N,), K; None for the detector's blobs.
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
    core_contrast_k: np.ndarray | None = None
    core_wide_contrast_k: np.ndarray | None = None
    core_noise_k: np.ndarray | None = None


def ring_radii_px(r_eq_px: float, ring_radii: tuple[float, float] = RING_RADII
                  ) -> tuple[float, float]:
    """Inner and outer radius (pixels) of the background ring around a blob of equivalent
    radius ``r_eq_px`` (pixels): ``ring_radii`` times it, at least 1 and 2 pixels beyond."""
    r_in = max(ring_radii[0] * r_eq_px, r_eq_px + 1.0)
    return r_in, max(ring_radii[1] * r_eq_px, r_in + 2.0)


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


def footprint_window(bbox: tuple[int, int, int, int], grow_px: int,
                     shape: tuple[int, int]) -> tuple[int, int, int, int]:
    """Where :func:`half_max_footprint` searches: the blob's box ``(min_row, min_col,
    max_row, max_col)`` grown by ``grow_px``, clipped to the image; ``(r0, r1, c0, c1)``."""
    h, w = shape
    return (max(0, bbox[0] - grow_px), min(h, bbox[2] + grow_px),
            max(0, bbox[1] - grow_px), min(w, bbox[3] + grow_px))


class _SquareMean:
    """Running ``nanmean`` over images of the squared deviation from each image's ring
    (float32 sums added image by image, the same bits as ``np.nanmean(axis=0)``)."""

    def __init__(self, shape: tuple[int, int]):
        self.total = np.zeros(shape, dtype=np.float32)
        self.count = np.zeros(shape, dtype=np.intp)

    def add(self, deviation: np.ndarray) -> None:
        """``deviation`` float32 (B, h, w): one scan's bands minus their ring means."""
        for d in deviation:
            sq = d * d
            missing = np.isnan(sq)
            self.total += np.where(missing, np.float32(0.0), sq)
            self.count += ~missing

    def rms(self) -> np.ndarray:
        """``sqrt(mean)``, float32 (h, w); NaN where no image had data."""
        with np.errstate(invalid="ignore", divide="ignore"):
            mean = np.divide(self.total, self.count, out=self.total.copy(), casting="unsafe")
        return np.sqrt(mean)


def half_max_footprint(amp: np.ndarray, own: np.ndarray, origin: tuple[int, int]
                       ) -> tuple[np.ndarray, np.ndarray]:
    """Pixels of a blob's half-maximum thermal footprint.

    The amplitude of each pixel is its RMS deviation from the blob's background ring over
    the scans and bands, ``S = sqrt(mean_i (T_i - ring_i)^2)``; the footprint is the
    connected region around the blob's strongest pixel where ``S`` exceeds half the blob's
    peak amplitude (the 95th percentile of ``S`` in the blob, robust to noise), searched within
    the blob's box grown by its equivalent radius (:func:`footprint_window`). For a disc seen
    through a moderate blur its area is the disc's, whereas the detector's thresholded blob
    also takes in part of the blur and of the thermal halo.

    Parameters
    ----------
    amp : float (h, w)
        ``S`` over the search window, K (NaN where no image had data).
    own : bool (h, w)
        The blob's pixels in the window.
    origin : (int, int)
        Row and column of the window's first pixel in the image.

    Returns
    -------
    rows, cols : int arrays
        The footprint's pixels in the image (the blob's own pixels when no footprint is
        found).
    """
    from scipy import ndimage

    r0, c0 = origin
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


@dataclass
class _Blob:
    """One labelled blob's geometry and the series measured on it, scan by scan."""

    region: object
    rows: np.ndarray
    cols: np.ndarray
    row: float
    col: float
    r_eq: float
    ring_rows: np.ndarray
    ring_cols: np.ndarray
    window: tuple[int, int, int, int]
    ring: np.ndarray
    noise: np.ndarray
    amp: _SquareMean
    centre: np.ndarray
    fr: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.intp))
    fc: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.intp))


def _nan_stats(values: np.ndarray, n_min: int, stat) -> np.ndarray:
    """``stat(values, axis=1)`` of (B, P) values (NaN ignored), NaN (B,) below ``n_min``
    values."""
    if values.shape[1] < n_min:
        return np.full(values.shape[0], np.nan, dtype=np.float32)
    return stat(values, axis=1)


def blob_features(
    labels: np.ndarray,
    stack,
    times_s: np.ndarray | None = None,
    transform=None,
    pixel_size_m: float | None = None,
    detection: DetectionResult | None = None,
    longitude_deg: float | None = None,
    ring_radii: tuple[float, float] = RING_RADII,
    noise: str = "ring",
) -> list[AnomalyFeatures]:
    """Measure every labelled anomaly.

    The stack is read twice, scan by scan (:mod:`clearfast_gis.detection.stack`): first the
    ring means and spreads and the running RMS amplitude around each blob, then the centre
    means over each blob's half-maximum footprint. Memory holds per blob its series (N, B)
    and two arrays the size of its search window, never the stack.

    Parameters
    ----------
    labels : ndarray of int (H, W)
        Anomaly labels (0 = background), e.g. ``DetectionResult.labels``.
    stack : ScanStack, or ndarray (H, W), (N, H, W) or (N, B, H, W)
        Apparent temperature (K or degrees C), NaN = no-data.
    times_s : ndarray (N,), optional
        Scan times, UTC epoch seconds (for the summary polarity).
    transform : affine.Affine, optional
        Grid transform (pixel corner -> map), for the map centroid.
    pixel_size_m : float, optional
        Ground pixel size in metres; default ``sqrt(|det(transform)|)`` when a transform is
        given. Without either, the metric fields are NaN.
    detection : DetectionResult, optional
        The detector's result on this stack: the per-scan support (hot and cold L_i maps)
        and the coverage count (otherwise counted in a pass of its own).
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
    source = as_scan_stack(stack)
    n, b = source.n_scans, source.n_bands
    if source.shape != labels.shape:
        raise ValueError(f"labels {labels.shape} and stack {source.shape} differ in shape")
    if times_s is not None and len(np.atleast_1d(times_s)) != n:
        raise ValueError(f"{len(np.atleast_1d(times_s))} times for {n} scans")
    if noise not in ("ring", "image"):
        raise ValueError(f"noise must be 'ring' or 'image', got {noise!r}")
    if pixel_size_m is None and transform is not None:
        pixel_size_m = float(np.sqrt(abs(transform.a * transform.e - transform.b * transform.d)))
    ps = float("nan") if pixel_size_m is None else float(pixel_size_m)
    regions = regionprops(labels.astype(np.int32))
    if not regions:
        return []
    # a pixel seen in some scans only (a footprint that moves, paper §6) still serves the
    # ring of those scans: every mean below is over the scans that saw it
    covered = detection.covered if detection is not None else count_finite(
        iter_images(source))
    valid = covered > 0
    blobs = []
    for region in regions:
        row, col = (float(v) for v in region.centroid)
        r_eq = float(np.sqrt(4.0 * int(region.area) / np.pi)) / 2.0
        r_in, r_out = ring_radii_px(r_eq, ring_radii)
        rr, cc = _ring_pixels(labels, valid, row, col, r_in, r_out)
        if rr.size < 2:  # inside another blob (a compact object split from a warm patch):
            # the patch around it is its background
            rr, cc = _ring_pixels(labels, valid, row, col, r_in, r_out, only=int(region.label))
        window = footprint_window(region.bbox, int(np.ceil(r_eq)), labels.shape)
        blobs.append(_Blob(
            region, region.coords[:, 0], region.coords[:, 1], row, col, r_eq, rr, cc, window,
            np.full((n, b), np.nan, dtype=np.float32), np.full((n, b), np.nan, dtype=np.float32),
            _SquareMean((window[1] - window[0], window[3] - window[2])),
            np.full((n, b), np.nan, dtype=np.float32)))

    def rings(_scan: int, bands: np.ndarray) -> tuple[list, np.ndarray | None]:
        out = []
        image_noise = np.array([np.nanstd(x) for x in bands]) if noise == "image" else None
        for blob in blobs:
            around = bands[:, blob.ring_rows, blob.ring_cols]
            ring = _nan_stats(around, 1, np.nanmean)
            r0, r1, c0, c1 = blob.window
            out.append((ring, _nan_stats(around, 2, np.nanstd),
                        bands[:, r0:r1, c0:c1] - ring[:, None, None]))
        return out, image_noise

    def centres(_scan: int, bands: np.ndarray) -> list[np.ndarray]:
        return [np.nanmean(bands[:, blob.fr, blob.fc], axis=1) for blob in blobs]

    image_noise = np.full((n, b), np.nan, dtype=np.float32)
    # a scan that did not see a blob or its ring gives NaN; the filter is the process's, so
    # it holds on the reading threads too (set here, on the calling thread, around each pass)
    with np.errstate(invalid="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore", category=RuntimeWarning)
        for i, (per_blob, scan_noise) in enumerate(map_scans(rings, source)):
            for blob, (ring, spread, deviation) in zip(blobs, per_blob, strict=True):
                blob.ring[i], blob.noise[i] = ring, spread
                blob.amp.add(deviation)
            if scan_noise is not None:
                image_noise[i] = scan_noise
        for blob in blobs:
            r0, r1, c0, c1 = blob.window
            own = labels[r0:r1, c0:c1] == blob.region.label
            blob.fr, blob.fc = half_max_footprint(blob.amp.rms(), own, (r0, c0))
        for i, per_blob in enumerate(map_scans(centres, source)):
            for blob, centre in zip(blobs, per_blob, strict=True):
                blob.centre[i] = centre
    return [_features(blob, n, b, ps, transform, times_s, longitude_deg, detection,
                      image_noise if noise == "image" else None) for blob in blobs]


def _features(blob: _Blob, n: int, b: int, ps: float, transform, times_s, longitude_deg,
              detection: DetectionResult | None, image_noise: np.ndarray | None
              ) -> AnomalyFeatures:
    """One blob's :class:`AnomalyFeatures` from its measured series."""
    region = blob.region
    area = int(region.area)
    diameter = 2.0 * blob.r_eq
    circ, ratio, compact = _circularity(region)
    fwhm_diameter = float(np.sqrt(4.0 * blob.fr.size / np.pi))
    row, col = float(blob.fr.mean()), float(blob.fc.mean())
    centre, ring, noise_k = blob.centre, blob.ring, blob.noise
    contrast = centre - ring
    sigma = noise_k if image_noise is None else image_noise
    cnr = np.abs(contrast) / np.maximum(sigma, 1e-6)
    with warnings.catch_warnings():  # a scan that did not see the blob: an all-NaN row
        warnings.simplefilter("ignore", category=RuntimeWarning)
        c_scan = np.nanmean(contrast, axis=1) if b > 1 else contrast[:, 0]
        cnr_scan = np.nanmax(cnr, axis=1)
    pol = _polarity(detection, blob.rows, blob.cols, c_scan, cnr_scan, n)
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
    return AnomalyFeatures(
        id=int(region.label), row=row, col=col, x=float(x), y=float(y),
        area_px=area, area_m2=area * ps**2, diameter_px=fwhm_diameter,
        diameter_m=fwhm_diameter * ps, blob_diameter_px=diameter,
        circularity=circ, axis_ratio=ratio, compactness=compact,
        polarity_per_scan=pol, polarity=summary_polarity(pol, times_s, longitude_deg),
        n_scans=int(seen.sum()), centre_k=squeeze(centre), ring_k=squeeze(ring),
        contrast_k=squeeze(contrast), noise_k=squeeze(noise_k), score=score,
        bbox=tuple(int(v) for v in region.bbox),
    )


def _polarity(detection: DetectionResult | None, rows: np.ndarray, cols: np.ndarray,
              contrast: np.ndarray, cnr: np.ndarray, n: int) -> np.ndarray:
    sign = np.sign(np.nan_to_num(contrast)).astype(np.int8)
    if detection is None:
        return np.where(np.nan_to_num(cnr) >= 2.0, sign, 0).astype(np.int8)
    hot, cold = detection.support(rows, cols)
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


FOUND_BY_SCANS = "scans"
"""``found_by`` of a blob the detector found in the scans' mosaics (docs/detection.md)."""

FOUND_BY_STACK = "stack"
"""``found_by`` of a deep core: found only by the matched filter over the whole stack of scans
(:mod:`clearfast_gis.detection.deep`), a disc of the reference mine's radius laid at the
score's peak, whose outline and circularity are therefore not measured."""


def found_by(feature: AnomalyFeatures) -> str:
    """How a detection was found: :data:`FOUND_BY_STACK` for a deep core (it carries its
    disc-ring contrast, ``core_contrast_k``), else :data:`FOUND_BY_SCANS`."""
    return FOUND_BY_STACK if feature.core_contrast_k is not None else FOUND_BY_SCANS
