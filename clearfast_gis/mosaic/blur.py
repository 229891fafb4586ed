"""The blur of the mosaics at a ground point: the camera's pixel footprint and the mosaic cell.

A pixel of a thermal camera integrates the ground over its footprint, ``R ifov`` across the
line of sight and ``R ifov / sin(grazing)`` along it (range ``R``, pixel angle ``ifov``),
through optics whose spot is about a pixel: its point-spread function is close to a Gaussian
of sigma :data:`PSF_SIGMA_PER_FOOTPRINT` times the footprint's geometric mean (a pixel's box
alone would give ``1/sqrt(12)`` = 0.29). The mosaic interpolates the frame's pixels bilinearly
at its cells' centres (:func:`clearfast_gis.mosaic.project.resample`): between samples one
footprint apart a linear interpolation is, over the cells' random phase against the pixels, a
triangle of half-width a footprint, sigma ``1/sqrt(6)`` = 0.41 footprints
(:data:`RESAMPLE_SIGMA_PER_FOOTPRINT`), as large as the optics' own term. The cell's box adds
``cell / sqrt(12)``. A small object's contrast, averaged over a disc, loses to this blur what
spreads beyond the disc (and the background ring gains it): the thermal inversion models it
(:meth:`clearfast_gis.thermal.table.SiteTable.contrast_for`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

PSF_SIGMA_PER_FOOTPRINT = 0.4
"""Gaussian sigma of a camera pixel's point-spread function on the ground, in footprints (the
geometric mean of the across and along footprints): the pixel's box (0.29) widened by an
optical spot about a pixel across."""

RESAMPLE_SIGMA_PER_FOOTPRINT = 1.0 / np.sqrt(6.0)
"""Gaussian sigma of the mosaic's bilinear interpolation between a frame's pixels, in
footprints: the triangle kernel's, ``1/sqrt(6)`` (module notes)."""


def pixel_angle_rad(camera) -> float:
    """Angle one pixel subtends, rad: ``ifov_rad`` of an equiangular camera, ``1 / fx`` of a
    pinhole one."""
    ifov = getattr(camera, "ifov_rad", None)
    return float(ifov) if ifov is not None else 1.0 / float(camera.fx)


def mosaic_blur_sigma_m(camera_xyz_m: ArrayLike, pixel_angle: float, x_m: ArrayLike,
                        y_m: ArrayLike, cell_m: float) -> np.ndarray:
    """Gaussian sigma (m) of the mosaics' blur at ground points ``(x_m, y_m)`` (K,).

    ``camera_xyz_m``: the camera's (E, N, height above ground), m; ``pixel_angle``: rad;
    ``cell_m``: the mosaic cell, m. The camera's pixel point-spread function
    (:data:`PSF_SIGMA_PER_FOOTPRINT` of the footprint), the bilinear interpolation between
    pixels (:data:`RESAMPLE_SIGMA_PER_FOOTPRINT`) and the cell's box in quadrature.
    """
    cx, cy, h = (float(v) for v in camera_xyz_m)
    x, y = np.asarray(x_m, dtype=float), np.asarray(y_m, dtype=float)
    rng = np.sqrt((x - cx) ** 2 + (y - cy) ** 2 + h**2)
    across = rng * pixel_angle
    along = across * rng / max(h, 1e-3)
    pixel = np.hypot(PSF_SIGMA_PER_FOOTPRINT, RESAMPLE_SIGMA_PER_FOOTPRINT) \
        * np.sqrt(across * along)
    return np.sqrt(pixel**2 + cell_m**2 / 12.0)


def survey_blur_sigma_m(ctx, x_m: ArrayLike, y_m: ArrayLike, cell_m: float) -> np.ndarray:
    """:func:`mosaic_blur_sigma_m` at ground points ``(x_m, y_m)`` (K,) of a survey: the
    camera at the platform track's median position plus the mount offset (``survey.json``
    ``platform.antenna_to_camera_m``), the survey's camera, the mosaic cell ``cell_m`` (m);
    zeros without a usable fix. ``ctx``: the survey's
    :class:`~clearfast_gis.mosaic.frames.SurveyContext`."""
    x = np.atleast_1d(np.asarray(x_m, dtype=float))
    track = ctx.track
    ok = track.usable & np.all(np.isfinite(track.position_m), axis=1)
    if not ok.any():
        return np.zeros(x.shape)
    offset = ctx.survey.manifest.get("platform", {}).get("antenna_to_camera_m", [0, 0, 0])
    camera = np.median(track.position_m[ok], axis=0) + np.asarray(offset, dtype=float)
    return mosaic_blur_sigma_m(camera, pixel_angle_rad(ctx.camera), x, y_m, cell_m)
