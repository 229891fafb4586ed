"""Registration results do not depend on where the images sit in memory.

numpy's and OpenCV's vectorised loops may split a buffer into an unaligned head, aligned
vector blocks and a tail; a kernel whose rounding differs between the parts gives last-bit
differences that depend on the buffers' addresses, i.e. differ from run to run. Each image is
copied to 16 byte offsets (every 4-byte alignment inside a 64-byte line) and every result must
be the same bits.
"""

from __future__ import annotations

import math

import cv2
import numpy as np

from clearfast_gis.registration import ConformalTransform, register_conformal
from clearfast_gis.registration.search import gradient_magnitude
from clearfast_gis.registration.synthetic import make_pair, ragged_mask

N_OFFSETS = 16


def _at_offset(image: np.ndarray, offset: int) -> np.ndarray:
    """A copy of ``image`` starting ``offset`` elements into a fresh buffer."""
    buf = np.empty(image.size + N_OFFSETS, dtype=image.dtype)
    out = buf[offset:offset + image.size].reshape(image.shape)
    out[...] = image
    return out


def _pair() -> tuple[np.ndarray, np.ndarray]:
    shape = (61, 48)
    truth = ConformalTransform(0.0, 0.31, -0.17, center_px=((48 - 1) / 2, (61 - 1) / 2))
    fixed, moving = make_pair(shape, truth, seed=3, noise_k=0.1)
    fixed = fixed.astype(np.float32)
    fixed[~ragged_mask(shape, seed=3)] = np.nan
    return fixed, moving.astype(np.float32)


def test_gradient_magnitude_is_the_same_bits_at_every_alignment():
    fixed, _ = _pair()
    outs = [gradient_magnitude(_at_offset(fixed, k)) for k in range(N_OFFSETS)]
    for out in outs[1:]:
        np.testing.assert_array_equal(out, outs[0])
    # and the value is the correctly rounded magnitude of the Sobel derivatives
    valid = np.isfinite(fixed)
    filled = np.where(valid, fixed, np.nanmean(fixed)).astype(np.float32)
    gx = cv2.Sobel(filled, cv2.CV_32F, 1, 0, ksize=3, borderType=cv2.BORDER_REFLECT)
    gy = cv2.Sobel(filled, cv2.CV_32F, 0, 1, ksize=3, borderType=cv2.BORDER_REFLECT)
    exact = np.sqrt(gx.astype(np.float64) ** 2 + gy.astype(np.float64) ** 2)
    inside = outs[0] != 0
    mean = float(exact[inside].mean() - outs[0][inside].mean())  # the zero-mean shift
    np.testing.assert_allclose(outs[0][inside] + mean, exact[inside], rtol=0, atol=1e-5)


def test_registration_is_the_same_bits_at_every_alignment():
    fixed, moving = _pair()
    results = {repr(register_conformal(_at_offset(fixed, k), _at_offset(moving, k),
                                       max_shift_px=8.0, max_angle_deg=0.0, bins=24))
               for k in range(N_OFFSETS)}
    assert len(results) == 1, results
    t = register_conformal(fixed, moving, max_shift_px=8.0, max_angle_deg=0.0, bins=24)
    assert t.converged
    assert math.hypot(t.tx_px - 0.31, t.ty_px + 0.17) < 0.1
