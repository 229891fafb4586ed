"""The box mean's fast kernel is scipy's uniform_filter (mode nearest), bit for bit."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy import ndimage

from clearfast_gis.detection._boxmean import box_mean_nearest


@given(arrays(np.float64, st.tuples(st.integers(1, 40), st.integers(1, 40)),
              elements=st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False)),
       st.integers(1, 45))
@settings(max_examples=200, deadline=None)
def test_box_mean_is_scipys_uniform_filter(image, size):
    ref = ndimage.uniform_filter(image, size=size, mode="nearest")
    assert np.array_equal(box_mean_nearest(image, size), ref)


def test_box_mean_on_a_mosaic_sized_image_and_float32_input():
    rng = np.random.default_rng(5)
    image = (20.0 + np.cumsum(rng.normal(0, 0.05, (1097, 160)), axis=1)).astype(np.float32)
    ref = ndimage.uniform_filter(image.astype(np.float64), size=15, mode="nearest")
    out = box_mean_nearest(image, 15)
    assert out.dtype == np.float64 and np.array_equal(out, ref)
