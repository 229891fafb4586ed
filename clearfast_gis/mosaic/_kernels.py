"""The mosaic's fast kernel (``--kernels fast``, :mod:`clearfast_gis.kernels`): the registry's
``resample`` with OpenCV (reference: :mod:`clearfast_gis.mosaic._reference`)."""

from __future__ import annotations

import cv2
import numpy as np


def resample(band: np.ndarray, map_x: np.ndarray, map_y: np.ndarray, sigma_px: float
                  ) -> np.ndarray:
    """:func:`clearfast_gis.mosaic.project.resample` on the fast kernels (OpenCV)."""
    if sigma_px > 0:
        band = cv2.GaussianBlur(band, (0, 0), sigma_px, borderType=cv2.BORDER_REPLICATE)
    return cv2.remap(band, map_x, map_y, interpolation=cv2.INTER_LINEAR,
                     borderMode=cv2.BORDER_CONSTANT, borderValue=float("nan"))
