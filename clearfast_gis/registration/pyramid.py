"""Masked image pyramids: no-data (NaN) never leaks into valid pixels.

Level ``l`` pixel ``x`` sits at level-0 pixel ``2**l * x`` (the sampling of :func:`cv2.pyrDown`),
so a transform moves between levels with :meth:`ConformalTransform.scaled`.
"""

from __future__ import annotations

import cv2
import numpy as np


def apply_mask(image: np.ndarray, mask: np.ndarray | None = None) -> np.ndarray:
    """``image`` as float32 with NaN wherever it is not finite or ``mask`` is False.

    Parameters
    ----------
    image : ndarray, shape (H, W)
        Any real dtype.
    mask : ndarray of bool, shape (H, W), optional
        ``True`` where the pixel is usable.

    Returns
    -------
    ndarray, float32, shape (H, W)
        A new array.
    """
    img = np.array(image, dtype=np.float32, copy=True)
    if img.ndim != 2:
        raise ValueError(f"expected a 2-D image, got shape {img.shape}")
    if mask is not None:
        m = np.asarray(mask, dtype=bool)
        if m.shape != img.shape:
            raise ValueError(f"mask shape {m.shape} differs from image shape {img.shape}")
        img[~m] = np.nan
    return img


def masked_gaussian(image: np.ndarray, sigma_px: float) -> np.ndarray:
    """Gaussian smoothing by normalised convolution; NaN pixels stay NaN and do not spread.

    Parameters
    ----------
    image : ndarray, float32, shape (H, W)
        NaN marks no-data.
    sigma_px : float
        Standard deviation of the Gaussian, pixels (0 returns a copy).
    """
    if sigma_px <= 0:
        return image.copy()
    valid = np.isfinite(image)
    filled = np.where(valid, image, 0.0).astype(np.float32)
    num = cv2.GaussianBlur(filled, (0, 0), sigma_px, borderType=cv2.BORDER_REFLECT)
    den = cv2.GaussianBlur(valid.astype(np.float32), (0, 0), sigma_px,
                           borderType=cv2.BORDER_REFLECT)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = num / den
    out[~valid] = np.nan
    return out


def masked_pyr_down(image: np.ndarray) -> np.ndarray:
    """One pyramid level down (half size) of an image with NaN no-data.

    A coarse pixel is valid when more than half of its filter weight lies on valid pixels.
    """
    valid = np.isfinite(image)
    filled = np.where(valid, image, 0.0).astype(np.float32)
    num = cv2.pyrDown(filled, borderType=cv2.BORDER_REFLECT)
    den = cv2.pyrDown(valid.astype(np.float32), borderType=cv2.BORDER_REFLECT)
    out = np.full(num.shape, np.nan, dtype=np.float32)
    ok = den > 0.5
    out[ok] = num[ok] / den[ok]
    return out


def masked_pyramid(image: np.ndarray, levels: int) -> list[np.ndarray]:
    """``[level 0, level 1, ..., level levels-1]``, each half the size of the previous."""
    out = [image]
    for _ in range(levels - 1):
        out.append(masked_pyr_down(out[-1]))
    return out


def n_levels_for(shape: tuple[int, int], coarsest_px: int = 96, min_px: int = 24) -> int:
    """Pyramid depth so that the coarsest level's larger side is at most ``coarsest_px``.

    The smaller side never drops below ``min_px``.
    """
    h, w = shape
    levels = 1
    while max(h, w) > coarsest_px and min(h, w) // 2 >= min_px:
        h, w = (h + 1) // 2, (w + 1) // 2
        levels += 1
    return levels

