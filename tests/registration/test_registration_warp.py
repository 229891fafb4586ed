"""warp_conformal against scipy's reference resampling, and registration round trips."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import ndimage

from clearfast_gis.registration import ConformalTransform, register_conformal, warp_conformal
from clearfast_gis.registration.synthetic import make_pair, thermal_scene


def test_matches_scipy_map_coordinates() -> None:
    image = thermal_scene((120, 160), 0).astype(np.float32)
    t = ConformalTransform(0.07, 3.3, -2.6, 1.03, center_px=(79.5, 59.5))
    out = warp_conformal(image, t, (100, 140))
    vv, uu = np.mgrid[0:100, 0:140].astype(float)
    src = t.apply(np.column_stack([uu.ravel(), vv.ravel()]))
    ref = ndimage.map_coordinates(image.astype(float), [src[:, 1], src[:, 0]], order=1,
                                  mode="constant", cval=np.nan).reshape(100, 140)
    both = np.isfinite(out) & np.isfinite(ref)
    assert both.mean() > 0.9
    # OpenCV resolves positions to 1/32 px: differences stay within ~gradient / 64
    assert np.max(np.abs(out[both] - ref[both])) < 0.1
    outside = ~np.isfinite(ref)
    outside[1:-1, 1:-1] &= outside[:-2, 1:-1] & outside[2:, 1:-1]
    assert np.isnan(out[outside]).all()
    assert out.dtype == np.float32


def test_identity_and_nan_propagation() -> None:
    image = thermal_scene((50, 60), 1).astype(np.float32)
    image[10:20, 10:20] = np.nan
    out = warp_conformal(image, ConformalTransform.identity((29.5, 24.5)), image.shape)
    # the image edges survive; no-data grows by at most one pixel (interpolation neighbours)
    assert np.isfinite(out[:, -1]).all() and np.isfinite(out[-1, :]).all()
    assert np.isnan(out[10:20, 10:20]).all()
    assert np.isnan(out).sum() <= (11 * 11)
    ok = np.isfinite(out)
    np.testing.assert_allclose(out[ok], image[ok])


@pytest.mark.parametrize("order", [0, 1, 3])
def test_registered_moving_image_lands_on_the_fixed_one(order: int) -> None:
    shape = (160, 200)
    truth = ConformalTransform(math.radians(3), 6.4, -4.2, center_px=(99.5, 79.5))
    fixed, moving = make_pair(shape, truth, seed=3, noise_k=0.0)
    result = register_conformal(fixed, moving)
    back = warp_conformal(moving, result, shape, order=order)
    valid = np.isfinite(back)
    assert valid.mean() > 0.85
    err = np.abs(back[valid] - fixed[valid])
    assert np.median(err) < (0.5 if order == 0 else 0.05)


def test_bad_order() -> None:
    with pytest.raises(ValueError, match="order"):
        warp_conformal(np.zeros((4, 4)), ConformalTransform(), (4, 4), order=2)
