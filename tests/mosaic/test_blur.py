"""The mosaics' blur model (:mod:`clearfast_gis.mosaic.blur`) against direct computations."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.mosaic.blur import (
    PSF_SIGMA_PER_FOOTPRINT,
    RESAMPLE_SIGMA_PER_FOOTPRINT,
    mosaic_blur_sigma_m,
)
from clearfast_gis.mosaic.project import resample


def _resampled_variance(psf_px: float, phase: float, step: float = 0.02) -> float:
    """Variance (px2) along the rows of a point seen by pixels of point-spread sigma
    ``psf_px`` (one pixel apart, the point ``phase`` px off a pixel centre), resampled
    bilinearly onto cells ``step`` px apart as the mosaic resamples a frame."""
    k = np.arange(64, dtype=float)
    row = np.exp(-0.5 * ((k - 32.0 - phase) / psf_px) ** 2)
    frame = np.repeat(row[None, :], 3, axis=0).astype(np.float32)
    x = np.arange(20.0, 44.0, step, dtype=np.float32)
    map_x = x[None, :]
    map_y = np.ones_like(map_x)
    prof = resample(frame, map_x, map_y, 0.0)[0].astype(float)
    mean = np.sum(prof * x) / np.sum(prof)
    return float(np.sum(prof * (x - mean) ** 2) / np.sum(prof))


def test_bilinear_resampling_adds_a_sixth_of_a_pixel_squared():
    """Over the point's phases against the pixels, the resampled spread is the pixels'
    point-spread in quadrature with the linear interpolation's triangle (1/6 px2)."""
    phases = np.linspace(0.0, 1.0, 16, endpoint=False)
    var = np.mean([_resampled_variance(PSF_SIGMA_PER_FOOTPRINT, p) for p in phases])
    expected = PSF_SIGMA_PER_FOOTPRINT**2 + RESAMPLE_SIGMA_PER_FOOTPRINT**2
    assert RESAMPLE_SIGMA_PER_FOOTPRINT**2 == pytest.approx(1.0 / 6.0)
    assert var == pytest.approx(expected, rel=0.03)
    # the point-spread alone would understate it by a half
    assert var > 1.9 * PSF_SIGMA_PER_FOOTPRINT**2


def test_blur_at_nadir_and_off_nadir():
    """A camera 10 m up, 1 mrad pixels, 2 cm cells: at nadir the footprint is 1 cm; 10 m
    off, the range is sqrt(2) times (1.41 cm across) and the grazing view stretches the
    footprint along the line of sight by range / height again (2 cm along)."""
    cell = 0.02
    k = np.hypot(PSF_SIGMA_PER_FOOTPRINT, RESAMPLE_SIGMA_PER_FOOTPRINT)
    got = mosaic_blur_sigma_m((0.0, 0.0, 10.0), 1e-3, [0.0, 10.0], [0.0, 0.0], cell)
    fp_nadir = 0.01
    fp_off = np.sqrt(0.01 * np.sqrt(2.0) * 0.02)  # geometric mean of across and along
    np.testing.assert_allclose(got, np.sqrt((k * np.array([fp_nadir, fp_off])) ** 2
                                            + cell**2 / 12.0), rtol=1e-12)
