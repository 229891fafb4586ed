"""Compact objects inside oversized blobs: a mine on a warm patch of ground.

The detector of paper §4 extracts regional extrema narrower than D1 by top-hat *by
reconstruction*. On a site whose soil temperature varies smoothly over metres, the cap of a
warm (or cool) patch passes as such an extremum, and a mine lying on its flank is swallowed
into one blob much larger than any mine; the blob's centre is then the patch's, not the
mine's. The plain top-hat (by opening, without reconstruction) is blind to the smooth cap and
keeps the full contrast of anything narrower than D1: inside an oversized blob, its
time-averaged normalised response picks out the compact objects, which become anomalies of
their own.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage

from clearfast_gis.detection.morphology import dilate_disk, disk_footprint, erode_disk
from clearfast_gis.detection.multiscale import robust_sigma
from clearfast_gis.detection.selection import median
from clearfast_gis.detection.stack import as_scan_stack, map_scans


def _compact_term(f: np.ndarray, d1_px: float) -> tuple[np.ndarray, np.ndarray] | None:
    """One image's term of :func:`compact_contrast`: ``(where(ok, resp / sigma, 0), ok)``,
    or None when the image does not count (too few cells, no spread).

    The opening and closing by the D1 disk ignore the cells outside the image (for a disk
    the same values as OpenCV's ``morphologyEx`` with a replicated border: tested)."""
    ok = np.isfinite(f)
    if ok.sum() < 9:
        return None
    filled = np.where(ok, f, median(f[ok])).astype(np.float32)
    white = filled - dilate_disk(erode_disk(filled, d1_px), d1_px)
    black = erode_disk(dilate_disk(filled, d1_px), d1_px) - filled
    resp = np.maximum(white, black)
    sigma = robust_sigma(np.where(ok, white - black, np.nan))
    if not sigma > 0:
        return None
    return np.where(ok, resp / sigma, 0.0), ok


class _CompactSum:
    """The running sums of :func:`compact_contrast` over images of one shape, added in
    order."""

    def __init__(self, shape: tuple[int, int]):
        self.total = np.zeros(shape, dtype=np.float64)
        self.count = np.zeros(shape, dtype=np.int32)

    def add(self, term: tuple[np.ndarray, np.ndarray] | None) -> None:
        if term is not None:
            self.total += term[0]
            self.count += term[1]

    def result(self) -> np.ndarray:
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(self.count > 0, self.total / np.maximum(self.count, 1),
                            np.nan).astype(np.float32)


def compact_contrast(images, d1_px: float) -> np.ndarray:
    """Time-averaged contrast of objects narrower than D1, in units of each image's noise.

    Parameters
    ----------
    images : float32 (K, H, W), or an iterable of float32 (H, W)
        Apparent temperature (any unit), NaN = no data.
    d1_px : float
        Disk diameter D1, pixels.

    Returns
    -------
    float32 (H, W)
        Mean over the images of ``max(f - f o D1, f . D1 - f) / sigma``, with ``sigma`` the
        robust standard deviation of the image's top-hat; NaN where no image has data.
    """
    acc = None
    for f in images:
        acc = _CompactSum(f.shape) if acc is None else acc
        acc.add(_compact_term(f, d1_px))
    if acc is None:
        raise ValueError("no images")
    return acc.result()


def split_oversized(labels: np.ndarray, stack, d1_px: float, d2_px: float,
                    max_diameter_px: float, min_contrast: float = 4.0) -> np.ndarray:
    """Give the compact objects inside oversized blobs labels of their own.

    Parameters
    ----------
    labels : int (H, W)
        Blobs (0 = background).
    stack : ScanStack, or float32 (K, H, W) or (N, B, H, W)
        The detector's images (scans x bands), NaN = no data; read scan by scan, only the
        windows around the oversized blobs kept (:mod:`clearfast_gis.detection.stack`).
    d1_px, d2_px : float
        Detector disks D1 and D2, pixels.
    max_diameter_px : float
        Blobs with a larger equivalent diameter are searched.
    min_contrast : float
        Smallest time-averaged compact contrast (:func:`compact_contrast`, noise units) of
        an object.

    Returns
    -------
    int32 (H, W)
        Labels: each compact object found (at least a D2 disk in area) gets a new label; the
        rest of its blob keeps the old one.
    """
    out = labels.astype(np.int32).copy()
    next_label = int(out.max()) + 1
    min_area = float(np.count_nonzero(disk_footprint(d2_px)))
    margin = int(np.ceil(d1_px))
    searched = []  # (label, crop) of the oversized blobs
    for lab, sl in enumerate(ndimage.find_objects(out), start=1):
        if sl is None or 2.0 * np.sqrt(np.count_nonzero(out[sl] == lab) / np.pi) \
                <= max_diameter_px:
            continue
        r0, r1 = max(0, sl[0].start - margin), min(out.shape[0], sl[0].stop + margin)
        c0, c1 = max(0, sl[1].start - margin), min(out.shape[1], sl[1].stop + margin)
        searched.append((lab, (slice(r0, r1), slice(c0, c1))))
    if not searched:
        return out
    sums = [_CompactSum(out[crop].shape) for _, crop in searched]

    # each scan's terms on its reading thread; added in scan and band order
    def terms(_scan: int, bands: np.ndarray) -> list[list]:
        return [[_compact_term(image[crop], d1_px) for _, crop in searched]
                for image in bands]

    for per_band in map_scans(terms, as_scan_stack(stack)):
        for per_blob in per_band:
            for acc, term in zip(sums, per_blob, strict=True):
                acc.add(term)
    for (lab, crop), acc in zip(searched, sums, strict=True):
        contrast = acc.result()
        inside = out[crop] == lab  # new labels never equal an original one
        cores, n = ndimage.label((contrast >= min_contrast) & inside,
                                 structure=np.ones((3, 3)))
        if n == 0:
            continue
        areas = ndimage.sum_labels(np.ones_like(cores), cores, index=np.arange(1, n + 1))
        keep = [k for k, a in enumerate(areas, start=1) if min_area <= a < inside.sum()]
        view = out[crop]
        for k in keep:
            view[cores == k] = next_label
            next_label += 1
    return out
