"""Mutual information of two images from their joint histogram (hard binning).

These are the reference definitions, used to report and compare alignments. The registration
itself maximises a smooth (Parzen-windowed) estimate of the same quantity, see ``_kernels``.
"""

from __future__ import annotations

import numpy as np


def joint_histogram(
    a: np.ndarray, b: np.ndarray, mask: np.ndarray | None = None, bins: int = 32
) -> np.ndarray:
    """Joint histogram of two images over their common valid pixels.

    Parameters
    ----------
    a, b : ndarray, shape (H, W)
        Images of the same shape (any unit); NaN marks no-data.
    mask : ndarray of bool, shape (H, W), optional
        Pixels to use (``True``); combined with the finite pixels of both images.
    bins : int
        Number of bins per image; each image's bins span its own [min, max] over the used
        pixels, as :func:`numpy.histogram2d` does.

    Returns
    -------
    ndarray, float64, shape (bins, bins)
        Counts; rows index ``a``'s bins, columns ``b``'s.
    """
    a = np.asarray(a)
    b = np.asarray(b)
    if a.shape != b.shape:
        raise ValueError(f"images differ in shape: {a.shape} vs {b.shape}")
    if bins < 2:
        raise ValueError("bins must be at least 2")
    valid = np.isfinite(a) & np.isfinite(b)
    if mask is not None:
        valid &= np.asarray(mask, dtype=bool)
    av = a[valid].astype(np.float64)
    bv = b[valid].astype(np.float64)
    if av.size == 0:
        return np.zeros((bins, bins))
    flat = _bin_index(av, bins) * bins + _bin_index(bv, bins)
    return np.bincount(flat, minlength=bins * bins).astype(np.float64).reshape(bins, bins)


def _bin_index(x: np.ndarray, bins: int) -> np.ndarray:
    lo, hi = float(x.min()), float(x.max())
    if hi <= lo:
        return np.zeros(x.size, dtype=np.int64)
    idx = ((x - lo) * (bins / (hi - lo))).astype(np.int64)
    return np.minimum(idx, bins - 1)


def _entropies(hist: np.ndarray) -> tuple[float, float, float]:
    n = hist.sum()
    if n <= 0:
        return 0.0, 0.0, 0.0
    p = hist / n
    pa = p.sum(axis=1)
    pb = p.sum(axis=0)

    def ent(q: np.ndarray) -> float:
        q = q[q > 0]
        return float(-(q * np.log(q)).sum())

    return ent(pa), ent(pb), ent(p.ravel())


def mutual_information(
    a: np.ndarray, b: np.ndarray, mask: np.ndarray | None = None, bins: int = 32
) -> float:
    """Mutual information ``H(a) + H(b) - H(a, b)`` of two images, in nats.

    Parameters
    ----------
    a, b : ndarray, shape (H, W)
        Images of the same shape; NaN marks no-data.
    mask : ndarray of bool, shape (H, W), optional
        Pixels to use.
    bins : int
        Bins per image (each spans its image's range over the used pixels).

    Returns
    -------
    float
        MI in nats (0 for independent images, ``H(a)`` for ``a`` against itself); 0 when no
        pixel is usable.
    """
    ha, hb, hab = _entropies(joint_histogram(a, b, mask, bins))
    return max(ha + hb - hab, 0.0)


def normalized_mutual_information(
    a: np.ndarray, b: np.ndarray, mask: np.ndarray | None = None, bins: int = 32
) -> float:
    """Studholme's normalised mutual information ``(H(a) + H(b)) / H(a, b)``.

    Ranges from 1 (independent) to 2 (one image a function of the other); same definition as
    :func:`skimage.metrics.normalized_mutual_information`. Arguments as
    :func:`mutual_information`; returns 1 when the joint entropy is zero.
    """
    ha, hb, hab = _entropies(joint_histogram(a, b, mask, bins))
    if hab <= 0:
        return 1.0
    return (ha + hb) / hab
