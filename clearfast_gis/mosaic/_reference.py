"""The mosaic's reference kernel (``--kernels reference``): the registry's ``resample`` with
scipy (:mod:`clearfast_gis.kernels`)."""

from __future__ import annotations

import numpy as np
from scipy import ndimage


def resample(band: np.ndarray, map_x: np.ndarray, map_y: np.ndarray, sigma_px: float
                    ) -> np.ndarray:
    """:func:`clearfast_gis.mosaic.project.resample` on the reference kernels (scipy)."""
    if sigma_px > 0:
        band = ndimage.gaussian_filter(band, sigma_px, mode="nearest", truncate=3.0)
    return ndimage.map_coordinates(band, [map_y, map_x], order=1, mode="constant",
                                   cval=np.nan, prefilter=False).astype(np.float32)
