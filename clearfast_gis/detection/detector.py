"""The morphological anomaly detector on a temporal stack (paper §4, Fig. 4).

For every image f_i of the stack (scan i, band b):

1. top-hat  ``t_i = f_i - r_B(f_i o D1 | f_i)`` (hot) and bottom-hat (cold, the dual);
2. ``G_i = T(F_m(t_i, I1, I2), 0.5)`` with I1, I2 at the epsilon percentiles (optionally
   with the cut capped at a multiple of the image's noise, ``ceiling``);
3. ``O_i = R_B(G_i o D2 | G_i)``;
4. majority vote ``M = T(sum_i O_i, l)``, i.e. pixels where ``sum_i O_i >= l``;
5. ``L_i = R_B(M | G_i)``;
6. ``R = OR_i L_i`` or ``R = T(sum_i L_i, gamma)`` (``sum >= gamma``).

Hot and cold anomalies are filtered separately (steps 1-3 and 5-6 per polarity). With
``polarity='both'`` the vote of step 4 counts, per image, a pixel that is in a hot *or* a cold
opened blob: a buried mine is warm by day and cool by night, and the vote asks for blobs with a
consistent presence over the day, whichever sign it has. Each blob keeps its polarity per scan
through the separate ``L_i`` maps. A multi-band stack (N, B, H, W) is treated as N * B images
(default level N * B / 2); the per-scan maps are the OR over the bands.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from clearfast_gis.detection.morphology import (
    binary_opening_by_reconstruction,
    bottom_hat_by_reconstruction,
    top_hat_by_reconstruction,
)
from clearfast_gis.detection.reconstruction import binary_reconstruction
from clearfast_gis.detection.stack import as_scan_stack, map_scans
from clearfast_gis.detection.stretch import stretch_threshold
from clearfast_gis.parallel import thread_imap
from clearfast_gis.progress import NULL_PROGRESS, Progress

__all__ = ["DetectionResult", "count_finite", "detect_anomalies",
           "unpack_bits"]

_EIGHT = np.ones((3, 3), dtype=bool)


@dataclass(frozen=True)
class DetectionResult:
    """Output of :func:`detect_anomalies`.

    Attributes
    ----------
    mask_hot, mask_cold : ndarray of bool (H, W)
        Combined hot (top-hat) and cold (bottom-hat) detections R.
    mask : ndarray of bool (H, W)
        ``mask_hot | mask_cold``.
    labels : ndarray of int32 (H, W)
        8-connected labels of ``mask`` (0 = background), ids 1..n_anomalies.
    votes : ndarray of int32 (H, W)
        ``sum_i O_i`` (hot or cold, per image), the majority-vote count.
    scan_hot_bits, scan_cold_bits : ndarray of uint8 (N, H, ceil(W / 8))
        The per-scan reconstructed maps L_i (OR over bands), rows packed by
        ``np.packbits(axis=-1)`` (:attr:`scan_hot`, :meth:`support` unpack them).
    level, gamma : float or float (H, W)
        The vote level used and the combination threshold (None = OR).
    covered : ndarray of int32 (H, W)
        Images with data at each pixel.
    """

    mask_hot: np.ndarray
    mask_cold: np.ndarray
    mask: np.ndarray
    labels: np.ndarray
    votes: np.ndarray
    scan_hot_bits: np.ndarray
    scan_cold_bits: np.ndarray
    level: float | np.ndarray
    gamma: float | np.ndarray | None
    covered: np.ndarray

    @property
    def n_anomalies(self) -> int:
        """Number of labelled anomalies."""
        return int(self.labels.max(initial=0))

    @property
    def scan_hot(self) -> np.ndarray:
        """The hot L_i maps, bool (N, H, W)."""
        return unpack_bits(self.scan_hot_bits, self.labels.shape[1])

    @property
    def scan_cold(self) -> np.ndarray:
        """The cold L_i maps, bool (N, H, W)."""
        return unpack_bits(self.scan_cold_bits, self.labels.shape[1])

    def support(self, rows: np.ndarray, cols: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Whether each scan's hot and cold L_i touch the pixels ``(rows, cols)``: two bool
        (N,)."""
        shift = (7 - cols % 8).astype(np.uint8)

        def touched(bits: np.ndarray) -> np.ndarray:
            return ((bits[:, rows, cols // 8] >> shift) & 1).astype(bool).any(axis=1)

        return touched(self.scan_hot_bits), touched(self.scan_cold_bits)


def unpack_bits(packed: np.ndarray, width: int) -> np.ndarray:
    """A boolean image from its rows packed by ``np.packbits(mask, axis=-1)``: bool (H, width)."""
    return np.unpackbits(packed, axis=-1, count=width).view(bool)


def count_finite(images) -> np.ndarray:
    """Images with data at each pixel, int32 (H, W), counted one image at a time (no
    (K, H, W) temporary).

    Parameters
    ----------
    images : float (K, H, W), or an iterable of float (H, W)
    """
    count = None
    for img in images:
        ok = np.isfinite(img)
        count = ok.astype(np.int32) if count is None else count + ok
    if count is None:
        raise ValueError("no images")
    return count


def detect_anomalies(
    stack,
    d1_px: float,
    d2_px: float,
    epsilon: float = 0.01,
    level: float | np.ndarray | Callable[[np.ndarray], np.ndarray] | None = None,
    gamma: float | np.ndarray | Callable[[np.ndarray], np.ndarray] | None = None,
    polarity: str = "both",
    progress: Progress = NULL_PROGRESS,
    ceiling: float | np.ndarray | Callable[[np.ndarray], float] | None = None,
) -> DetectionResult:
    """Detect hot and cold anomalies on a temporal (multi-band) stack.

    The images are read once, scan by scan (:func:`clearfast_gis.detection.stack.map_scans`):
    memory holds the scans being filtered, the thresholded hats G_i one bit a pixel and the
    per-scan maps L_i one bit a pixel, never the stack.

    Parameters
    ----------
    stack : ScanStack, or ndarray (N, H, W) or (N, B, H, W) (or (H, W) for one image)
        Apparent temperature per scan (and band), float32, NaN = no-data.
    d1_px : float
        Top-hat disk diameter D1 in pixels (larger than the largest expected object). The
        caller converts metres on a mosaic: ``d1_px = d1_m / pixel_size_m``.
    d2_px : float
        Opening disk diameter D2 in pixels, ``1 <= D2 < D1``; blobs that a D2 disk does not fit
        into are removed.
    epsilon : float
        Histogram-stretch fraction (paper §4.2).
    level : float, float (H, W) or callable, optional
        Majority-vote level l; a pixel is kept where ``sum_i O_i >= l``. Default ``N*B / 2``.
        A map gives each pixel its own level; a function of the coverage count (int32 (H, W),
        images with data at each pixel) gives the map once the images are read (e.g. relative
        to the images that cover each pixel when the footprint changes from scan to scan).
    gamma : float, float (H, W) or callable, optional
        Combination threshold: ``R = sum_i L_i >= gamma`` (a function of the coverage count
        as for ``level``); None combines with OR.
    polarity : {'both', 'hot', 'cold'}
        Which anomalies to look for.
    progress : Progress
        Reports one step per image.
    ceiling : float, ndarray (N*B,) or callable, optional
        Highest cut of step 2 per image, in the stack's units (K), or a function of the image
        (float32 (H, W)) giving it: a pixel of the hat image is set above
        ``min(stretch cut, ceiling)`` (:func:`clearfast_gis.detection.stretch.stretch_threshold`);
        None: the paper's stretch alone.

    Returns
    -------
    DetectionResult
    """
    if polarity not in ("both", "hot", "cold"):
        raise ValueError(f"polarity must be 'both', 'hot' or 'cold', got {polarity!r}")
    if not d1_px > d2_px >= 1:
        raise ValueError(f"need D1 > D2 >= 1 pixel, got D1={d1_px}, D2={d2_px}")
    source = as_scan_stack(stack)
    n, b, shape = source.n_scans, source.n_bands, source.shape
    k = n * b
    if callable(ceiling):
        def cut_of(_i: int, image: np.ndarray) -> float:
            return float(ceiling(image))
    else:
        ceilings = np.broadcast_to(np.full(1, np.nan) if ceiling is None
                                   else np.asarray(ceiling, dtype=np.float64), (k,))

        def cut_of(i: int, _image: np.ndarray) -> float:
            return float(ceilings[i])
    want = {"hot": polarity in ("both", "hot"), "cold": polarity in ("both", "cold")}
    # thresholded hats G_i are kept (the reconstruction of the final mask needs them), one bit
    # a pixel; the openings O_i and the reconstructions L_i are folded into counts as they
    # come, so that memory holds two (K, H, W / 8) packed stacks
    packed_w = (shape[1] + 7) // 8
    g = {p: np.zeros((k, shape[0], packed_w), dtype=np.uint8) for p in ("hot", "cold")}
    votes = np.zeros(shape, dtype=np.int32)
    covered = np.zeros(shape, dtype=np.int32)
    progress.start("detect", k)

    def one_scan(scan: int, bands: np.ndarray) -> tuple[list[np.ndarray], np.ndarray]:
        seen_per_band, finite = [], np.zeros(shape, dtype=np.int32)
        for j, image in enumerate(bands):
            i = scan * b + j
            cut = cut_of(i, image)
            seen = np.zeros(shape, dtype=bool)
            for p, hat in (("hot", top_hat_by_reconstruction),
                           ("cold", bottom_hat_by_reconstruction)):
                if want[p]:
                    gi = stretch_threshold(hat(image, d1_px), epsilon, ceiling=cut)
                    g[p][i] = np.packbits(gi, axis=-1)
                    seen |= binary_opening_by_reconstruction(gi, d2_px)
            finite += np.isfinite(image)
            seen_per_band.append(seen)
            progress.advance()
        return seen_per_band, finite

    for seen_per_band, finite in map_scans(one_scan, source):
        for seen in seen_per_band:
            votes += seen
        covered += finite
    progress.close()
    level = k / 2.0 if level is None else level(covered) if callable(level) else (
        np.asarray(level, dtype=np.float64) if np.ndim(level) else float(level))
    if callable(gamma):
        gamma = gamma(covered)
    m = votes >= level
    out, scans = {}, {}
    for p in ("hot", "cold"):
        count = np.zeros(shape, dtype=np.int32)
        scans[p] = np.zeros((n, shape[0], packed_w), dtype=np.uint8)
        if want[p] and m.any():
            lis = thread_imap(lambda i, p=p: binary_reconstruction(m, unpack_bits(
                g[p][i], shape[1])), range(k))
            scan_map = np.zeros(shape, dtype=bool)
            for i, li in enumerate(lis):
                count += li
                scan_map |= li
                if i % b == b - 1:  # the scan's last band: its map is complete
                    scans[p][i // b] = np.packbits(scan_map, axis=-1)
                    scan_map[:] = False
        out[p] = count > 0 if gamma is None else count >= gamma
    mask = out["hot"] | out["cold"]
    labels, _ = ndimage.label(mask, structure=_EIGHT)
    return DetectionResult(
        mask_hot=out["hot"], mask_cold=out["cold"], mask=mask,
        labels=labels.astype(np.int32), votes=votes,
        scan_hot_bits=scans["hot"], scan_cold_bits=scans["cold"],
        level=level, gamma=gamma, covered=covered,
    )
