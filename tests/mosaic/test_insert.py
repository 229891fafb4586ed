"""Insertion of projected frames: per cell, the frame seen closest to nadir."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.mosaic.insert import MosaicCanvas
from clearfast_gis.mosaic.project import ProjectedFrame, Window


def _frame(rng, h, w, b):
    values = rng.normal(20.0, 3.0, (b, h, w)).astype(np.float32)
    inc = rng.uniform(0.0, 80.0, (h, w)).astype(np.float32)
    unseen = rng.random((h, w)) < 0.3
    inc[unseen] = np.nan
    values[:, unseen] = np.nan
    return values, inc


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 2**31 - 1), st.integers(1, 6))
def test_insert_keeps_the_smallest_incidence_per_cell(seed, n_frames):
    """Golden: after inserting frames on overlapping windows, each cell holds the values,
    incidence and index of the frame that saw it at the smallest angle (first one on a tie),
    and nothing where no frame saw it."""
    rng = np.random.default_rng(seed)
    bands, height, width = 2, 20, 24
    canvas = MosaicCanvas(bands, height, width)
    best_inc = np.full((height, width), np.inf)
    best_val = np.full((bands, height, width), np.nan)
    best_src = np.full((height, width), -1)
    for k in range(n_frames):
        h, w = int(rng.integers(1, height + 1)), int(rng.integers(1, width + 1))
        r0, c0 = int(rng.integers(0, height - h + 1)), int(rng.integers(0, width - w + 1))
        values, inc = _frame(rng, h, w, bands)
        n = canvas.insert(ProjectedFrame(values, inc, Window(r0, c0, h, w)), 10 + k)
        sub = (slice(r0, r0 + h), slice(c0, c0 + w))
        better = np.isfinite(inc) & (inc < best_inc[sub])
        assert n == int(better.sum())
        best_inc[sub][better] = inc[better]
        best_src[sub][better] = 10 + k
        best_val[:, sub[0], sub[1]][:, better] = values[:, better]
    np.testing.assert_array_equal(canvas.incidence_deg, best_inc.astype(np.float32))
    np.testing.assert_array_equal(canvas.source, best_src)
    np.testing.assert_array_equal(canvas.values, best_val.astype(np.float32))
    assert np.array_equal(canvas.covered, best_src >= 0)
