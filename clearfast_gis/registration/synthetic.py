"""Synthetic thermal-like image pairs with a known conformal transform (tests, benchmarks).

The scene is smooth texture (Gaussian blobs, as buried objects and vegetation patches, plus
filtered noise, as soil moisture and roughness) so cubic-spline resampling is exact to well
below 0.01 pixel and the truth is the truth.
"""

from __future__ import annotations

import math

import cv2
import numpy as np
from scipy import ndimage

from clearfast_gis.registration.transform import ConformalTransform


def thermal_scene(shape: tuple[int, int], seed: int = 0, n_blobs: int = 60) -> np.ndarray:
    """A smooth random temperature field, degrees C around 15.

    Parameters
    ----------
    shape : tuple of int
        ``(H, W)`` in pixels.
    seed : int
        Random seed.
    n_blobs : int
        Number of Gaussian blobs (radius 3 to 25 pixels, +-3 K) per 640 x 512 pixels.

    Returns
    -------
    ndarray, float64, shape (H, W)
    """
    rng = np.random.default_rng(seed)
    h, w = shape
    field = ndimage.gaussian_filter(rng.normal(size=shape), 6.0) * 40.0
    field += ndimage.gaussian_filter(rng.normal(size=shape), 2.0) * 6.0
    field += ndimage.gaussian_filter(rng.normal(size=shape), 1.2) * 1.5
    n_blobs = int(round(n_blobs * h * w / (512 * 640))) if n_blobs else 0
    for _ in range(max(n_blobs, 1)):
        r0, c0 = rng.uniform(0, h), rng.uniform(0, w)
        rad = rng.uniform(3.0, 25.0)
        amp = rng.uniform(-3.0, 3.0)
        r_lo, r_hi = max(0, int(r0 - 4 * rad)), min(h, int(r0 + 4 * rad) + 1)
        c_lo, c_hi = max(0, int(c0 - 4 * rad)), min(w, int(c0 + 4 * rad) + 1)
        rows = np.arange(r_lo, r_hi)[:, None]
        cols = np.arange(c_lo, c_hi)[None, :]
        field[r_lo:r_hi, c_lo:c_hi] += amp * np.exp(
            -((rows - r0) ** 2 + (cols - c0) ** 2) / (2.0 * rad * rad))
    return 15.0 + field


def make_pair(
    shape: tuple[int, int],
    truth: ConformalTransform,
    seed: int = 0,
    noise_k: float = 0.05,
    invert: bool = False,
    moving_shape: tuple[int, int] | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """A fixed and a moving image with ``fixed(x) = moving(truth(x))`` (before noise).

    Pairs with the same seed and shapes share the scene (and the fixed image) when the truth
    moves the moving footprint by less than a quarter of the image size.

    Parameters
    ----------
    shape : tuple of int
        ``(H, W)`` of the fixed image.
    truth : ConformalTransform
        Fixed -> moving pixel map.
    seed : int
        Scene and noise seed.
    noise_k : float
        Standard deviation of the independent Gaussian noise added to both images, K.
    invert : bool
        Day/night contrast inversion: the moving image is ``40 - 3 * exp(scene / 12)`` (a
        decreasing non-linear map of the scene temperature) instead of the scene itself.
    moving_shape : tuple of int, optional
        ``(H, W)`` of the moving image (default: ``shape``).

    Returns
    -------
    fixed, moving : float32 arrays
    """
    h, w = shape
    hm, wm = moving_shape or shape
    inv = truth.inverse()
    # canvas large enough to hold both images' footprints
    corners = np.array([[0, 0], [wm - 1, 0], [0, hm - 1], [wm - 1, hm - 1]], dtype=float)
    back = inv.apply(corners)
    # a margin that depends on the shapes only (unless the truth needs more), so pairs of the
    # same seed and shapes show the same scene whatever the truth
    pad = max(h, w, hm, wm) // 4 + 32
    umin = min(-pad, back[:, 0].min() - 8)
    vmin = min(-pad, back[:, 1].min() - 8)
    umax = max(w - 1.0 + pad, back[:, 0].max() + 8)
    vmax = max(h - 1.0 + pad, back[:, 1].max() + 8)
    off = np.array([-math.floor(umin), -math.floor(vmin)])
    canvas_shape = (int(math.ceil(vmax)) + off[1] + 1, int(math.ceil(umax)) + off[0] + 1)
    scene = thermal_scene(canvas_shape, seed)
    coeffs = ndimage.spline_filter(scene, order=3)
    rng = np.random.default_rng(seed + 10_000)
    fixed = scene[off[1]:off[1] + h, off[0]:off[0] + w].copy()
    vv, uu = np.mgrid[0:hm, 0:wm].astype(np.float64)
    src = inv.apply(np.column_stack([uu.ravel(), vv.ravel()]))
    moving = ndimage.map_coordinates(
        coeffs, [src[:, 1] + off[1], src[:, 0] + off[0]], order=3, prefilter=False,
        mode="nearest").reshape(hm, wm)
    if invert:
        moving = 40.0 - 3.0 * np.exp(moving / 12.0)
    fixed = fixed + rng.normal(0.0, noise_k, fixed.shape)
    moving = moving + rng.normal(0.0, noise_k, moving.shape)
    return fixed.astype(np.float32), moving.astype(np.float32)


def rms_displacement(a: ConformalTransform, b: ConformalTransform, shape: tuple[int, int],
                     step_px: int = 8) -> float:
    """RMS distance, pixels, between where ``a`` and ``b`` send a grid of fixed points.

    Parameters
    ----------
    a, b : ConformalTransform
        Two fixed -> moving maps.
    shape : tuple of int
        ``(H, W)`` of the fixed image; the grid covers it every ``step_px`` pixels.
    """
    h, w = shape
    vv, uu = np.mgrid[0:h:step_px, 0:w:step_px].astype(np.float64)
    pts = np.column_stack([uu.ravel(), vv.ravel()])
    d = a.apply(pts) - b.apply(pts)
    return float(np.sqrt(np.mean(np.sum(d * d, axis=1))))


def ragged_mask(shape: tuple[int, int], seed: int = 0, keep: float = 0.7) -> np.ndarray:
    """A ragged footprint (bool, True = data) covering about ``keep`` of the image."""
    rng = np.random.default_rng(seed + 20_000)
    noise = cv2.GaussianBlur(rng.normal(size=shape).astype(np.float32), (0, 0), 25.0)
    h, w = shape
    vv, uu = np.mgrid[0:h, 0:w]
    ramp = (uu / w + 0.6 * vv / h).astype(np.float32)
    field = ramp + 8.0 * noise
    return field <= np.quantile(field, keep)
