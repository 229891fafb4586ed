"""A smooth random test image with no-data, shared by the kernel tests."""

from __future__ import annotations

import cv2
import numpy as np


def scene(seed: int = 0, shape=(240, 300)) -> np.ndarray:
    """float32 (H, W) Gaussian-blurred noise with a NaN hole and two NaN columns."""
    rng = np.random.default_rng(seed)
    f = cv2.GaussianBlur(rng.normal(size=shape).astype(np.float32), (0, 0), 3)
    f[40:70, 100:220] = np.nan  # a no-data hole
    f[:, :2] = np.nan
    return f
