"""Band co-registration: offsets estimated over many frames, then applied."""

from __future__ import annotations

import math

import numpy as np
import pytest

from clearfast_gis.errors import InvalidInput
from clearfast_gis.registration import (
    ConformalTransform,
    apply_band_offsets,
    estimate_band_offsets,
)
from clearfast_gis.registration.synthetic import make_pair, rms_displacement

SHAPE = (128, 160)
CENTER = ((SHAPE[1] - 1) / 2.0, (SHAPE[0] - 1) / 2.0)


def _bands(truths: list[ConformalTransform], n_frames: int) -> list[np.ndarray]:
    """Band b of frame p: the scene seen through the filter-wheel offset truths[b]."""
    stacks: list[list[np.ndarray]] = [[] for _ in truths]
    for p in range(n_frames):
        for b, t in enumerate(truths):
            band0, moving = make_pair(SHAPE, t, seed=p, noise_k=0.08)
            # each band sees the scene through its own monotone response
            stacks[b].append(band0 if b == 0 else 0.8 * moving + 0.01 * moving**2)
    return [np.stack(s) for s in stacks]


def test_recovers_translation_offsets() -> None:
    truths = [ConformalTransform.identity(CENTER),
              ConformalTransform(0.0, 1.35, -0.62, center_px=CENTER),
              ConformalTransform(0.0, -2.1, 0.45, center_px=CENTER)]
    stacks = _bands(truths, 5)
    # a corrupt frame in band 2 must not move the median
    stacks[2][3] = np.random.default_rng(0).normal(size=SHAPE)
    offsets = estimate_band_offsets(stacks)
    assert len(offsets) == 3
    assert offsets[0].tx_px == 0.0 and offsets[0].ty_px == 0.0
    for est, truth in zip(offsets[1:], truths[1:], strict=True):
        assert est.converged
        assert est.angle_rad == 0.0
        assert rms_displacement(truth, est, SHAPE) < 0.05
    assert offsets[1].n_samples == 5
    assert offsets[2].n_samples == 4


def test_same_offsets_on_any_thread_count(monkeypatch) -> None:
    """The frames are registered on threads; the offsets are the same bits on one."""
    truths = [ConformalTransform.identity(CENTER),
              ConformalTransform(0.0, 0.7, -1.2, center_px=CENTER),
              ConformalTransform(0.0, -1.6, 0.3, center_px=CENTER)]
    stacks = _bands(truths, 4)
    got = {}
    for threads in (1, 2):
        monkeypatch.setenv("CLEARFAST_THREADS", str(threads))
        got[threads] = estimate_band_offsets(stacks)
    assert repr(got[1]) == repr(got[2])  # every field to the last bit (repr round-trips)
    assert rms_displacement(truths[2], got[2][2], SHAPE) < 0.05


def test_conformal_offsets_from_lists_and_apply() -> None:
    truths = [ConformalTransform.identity(CENTER),
              ConformalTransform(math.radians(0.8), 0.9, 1.4, center_px=CENTER)]
    stacks = _bands(truths, 3)
    offsets = estimate_band_offsets([list(s) for s in stacks], conformal=True)
    assert rms_displacement(truths[1], offsets[1], SHAPE) < 0.05
    aligned = apply_band_offsets([stacks[0][0], stacks[1][0]], offsets)
    assert aligned[0].shape == SHAPE and aligned[1].dtype == np.float32
    np.testing.assert_allclose(aligned[0], stacks[0][0], rtol=1e-6)
    # band 1 resampled onto band 0: its response applied to band 0 reproduces it
    band0 = stacks[0][0]
    expected = 0.8 * band0 + 0.01 * band0**2
    inner = np.isfinite(aligned[1])
    assert inner.mean() > 0.9
    assert np.median(np.abs(aligned[1][inner] - expected[inner])) < 0.1
    stacked = apply_band_offsets(stacks, offsets)
    assert stacked[1].shape == stacks[1].shape


def test_all_frames_failing_is_reported() -> None:
    rng = np.random.default_rng(3)
    band0 = rng.normal(size=(2, *SHAPE))
    band1 = rng.normal(size=(2, *SHAPE))
    offsets = estimate_band_offsets([band0, band1])
    assert not offsets[1].converged
    assert offsets[1].n_samples == 0


def test_bad_inputs() -> None:
    with pytest.raises(InvalidInput):
        estimate_band_offsets([])
    with pytest.raises(InvalidInput):
        estimate_band_offsets([np.zeros((2, 20, 20)), np.zeros((3, 20, 20))])
    with pytest.raises(InvalidInput):
        apply_band_offsets([np.zeros((20, 20))], [])
