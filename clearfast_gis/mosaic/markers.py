"""Finding the surveyed markers in a mosaic: absolute ground control for the geometry.

Markers are plates laid at surveyed positions and chosen to stand out thermally (heated or
cooled, or of low emissivity). Around each surveyed position the mosaic is searched for the
blob of most extreme apparent temperature; its centroid is where the geometry put the marker.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage

from clearfast_gis.geometry.grid import GroundGrid


def locate_marker(values: np.ndarray, grid: GroundGrid, x: float, y: float,
                  search_m: float = 0.6, size_m: float = 0.3, min_contrast_k: float = 2.0
                  ) -> tuple[float, float] | None:
    """Where a marker appears in a mosaic near its surveyed position.

    A candidate is a blob that stands out from the window's median by more than
    ``min_contrast_k`` (warmer or cooler), lies within ``search_m`` of the surveyed position
    and has an area within about a factor 3 of the plate's. The one chosen maximises its peak
    contrast times a size term (log-normal in area, factor-2 spread) times a proximity term
    (Gaussian, sigma = half the search radius).

    Parameters
    ----------
    values : float32 (H, W)
        One band of the mosaic, degrees C (NaN = empty).
    grid : GroundGrid
    x, y : float
        Surveyed position, survey CRS metres.
    search_m : float
        Half-size of the search window, metres.
    size_m : float
        Side of the marker plate, metres.
    min_contrast_k : float
        Smallest contrast of a marker against the window's median, K.

    Returns
    -------
    (x, y) of the chosen blob's contrast-weighted centroid, or None when no candidate.
    """
    ps = grid.pixel_size
    c = int(round((x - grid.x0) / ps - 0.5))
    r = int(round((grid.y0 - y) / ps - 0.5))
    n = int(np.ceil(search_m / ps))
    r0, r1 = max(0, r - n), min(grid.height, r + n + 1)
    c0, c1 = max(0, c - n), min(grid.width, c + n + 1)
    if r1 - r0 < 3 or c1 - c0 < 3:
        return None
    win = values[r0:r1, c0:c1]
    ok = np.isfinite(win)
    if ok.mean() < 0.3:
        return None
    dev = np.where(ok, win - np.median(win[ok]), 0.0)
    expected_px = (size_m / ps) ** 2
    rows, cols = np.mgrid[r0:r1, c0:c1]
    best, best_score = None, 0.0
    for sign in (1.0, -1.0):
        mask = sign * dev > min_contrast_k
        lab, n_lab = ndimage.label(mask)
        for k in range(1, n_lab + 1):
            sel = lab == k
            area = int(sel.sum())
            w = np.abs(dev) * sel
            cy = float((rows * w).sum() / w.sum())
            cx = float((cols * w).sum() / w.sum())
            bx = grid.x0 + (cx + 0.5) * ps
            by = grid.y0 - (cy + 0.5) * ps
            d2 = (bx - x) ** 2 + (by - y) ** 2
            size_term = np.exp(-np.log(area / expected_px) ** 2 / (2 * np.log(2.0) ** 2))
            if d2 > search_m**2 or size_term < 0.25:
                continue
            score = float(np.abs(dev[sel]).max() * size_term
                          * np.exp(-d2 / (2 * (0.5 * search_m) ** 2)))
            if score > best_score:
                best, best_score = (bx, by), score
    return best
