"""Rendering of camera frames from a radiance grid: ray tracing, footprint sampling, atmosphere.

Every pixel's ray (shifted by the band's filter-wheel misregistration) is intersected with the
ground plane (:meth:`Camera.ground_points`); the surface-leaving radiance is sampled there with
``cv2.remap`` from a small stack of pre-blurred copies of the truth grid, choosing per pixel
the copy whose Gaussian width matches the pixel's ground footprint (anti-aliasing: a pixel
integrates the radiance over its footprint). The atmosphere between ground and camera uses the
per-pixel slant range (Eq. 4 forward). Rays that miss the ground see the sky.
"""

from __future__ import annotations

from dataclasses import dataclass

import cv2
import numpy as np

from clearfast_gis.geometry.pose import CameraPose
from clearfast_gis.radiometry.atmosphere import atmospheric_transmittance, observed_radiance
from clearfast_gis.radiometry.table import BandTable
from clearfast_gis.simulate.scene import GridSpec

#: Gaussian widths (sigma, truth-grid cells) of the pre-blurred radiance copies.
BLUR_SIGMAS_CELLS = (0.0, 1.0, 2.0, 4.0, 8.0)


@dataclass(frozen=True)
class RadianceGrid:
    """Surface-leaving radiance of one band at one time on the truth grid, pre-blurred.

    levels : list of float32 (H, W) arrays, one per :data:`BLUR_SIGMAS_CELLS`
    sky_radiance : band radiance of rays that miss the ground, W m-2 sr-1
    """

    grid: GridSpec
    levels: tuple[np.ndarray, ...]
    sky_radiance: float


def radiance_grid(radiance: np.ndarray, grid: GridSpec, sky_radiance: float) -> RadianceGrid:
    """Pre-blur a surface radiance grid (H, W) for footprint sampling."""
    rad = np.ascontiguousarray(radiance, dtype=np.float32)
    levels = [rad]
    for s in BLUR_SIGMAS_CELLS[1:]:
        levels.append(cv2.GaussianBlur(rad, (0, 0), sigmaX=s, borderType=cv2.BORDER_REPLICATE))
    return RadianceGrid(grid, tuple(levels), float(sky_radiance))


@dataclass(frozen=True)
class Atmosphere:
    """Air between ground and camera: temperature (K), relative humidity (%), pressure (hPa)."""

    t_air_k: float
    rh_pct: float
    pressure_hpa: float


def pixel_grid(width: int, height: int, shift_px: tuple[float, float] = (0.0, 0.0)
               ) -> tuple[np.ndarray, np.ndarray]:
    """Pixel-centre coordinates (u, v), each (H*W,), shifted by ``shift_px`` (du, dv)."""
    v, u = np.mgrid[0:height, 0:width].astype(np.float64)
    return (u.ravel() + shift_px[0], v.ravel() + shift_px[1])


def footprint_m(range_m: np.ndarray, ray_z: np.ndarray, ifov_rad: float) -> np.ndarray:
    """Geometric-mean ground footprint of pixels, metres.

    Across the line of sight the footprint is ``R ifov``; along it, ``R ifov / sin(grazing)``.
    """
    sin_graze = np.clip(np.abs(ray_z), 0.05, 1.0)
    return range_m * ifov_rad / np.sqrt(sin_graze)


def surface_radiance_frame(camera, pose: CameraPose, rgrid: RadianceGrid, ifov_rad: float,
                           shift_px: tuple[float, float] = (0.0, 0.0)
                           ) -> tuple[np.ndarray, np.ndarray]:
    """Surface-leaving radiance seen by each pixel, and the pixel's slant range.

    Parameters
    ----------
    camera : EquiangularCamera or PinholeCamera
    pose : CameraPose
        True pose of the camera.
    rgrid : RadianceGrid
    ifov_rad : float
        Angular size of a pixel, radians.
    shift_px : (float, float)
        Filter-wheel misregistration of the band, pixels.

    Returns
    -------
    radiance : float32 (H, W)
        W m-2 sr-1 (the sky radiance where the ray misses the ground).
    range_m : float32 (H, W)
        Slant range camera-ground, metres (0 where the ray misses the ground).
    """
    h, w = camera.height, camera.width
    u, v = pixel_grid(w, h, shift_px)
    rays = camera.rays(u, v, pose)
    with np.errstate(invalid="ignore", divide="ignore"):
        t = np.where(rays[:, 2] < -1e-6, -pose.position_m[2] / rays[:, 2], np.nan)
    hit = np.isfinite(t)
    gx = pose.position_m[0] + t * rays[:, 0]
    gy = pose.position_m[1] + t * rays[:, 1]
    rng_m = np.where(hit, t, 0.0)
    grid = rgrid.grid
    map_x = ((gx - grid.x0) / grid.pixel_size - 0.5).astype(np.float32).reshape(h, w)
    map_y = ((grid.y0 - gy) / grid.pixel_size - 0.5).astype(np.float32).reshape(h, w)
    map_x[~hit.reshape(h, w)] = 0.0
    map_y[~hit.reshape(h, w)] = 0.0
    fp_cells = footprint_m(rng_m, rays[:, 2], ifov_rad).reshape(h, w) / grid.pixel_size
    # the pixel's box footprint matches a Gaussian of sigma ~ 0.4 footprint
    want = 0.4 * fp_cells
    sig = np.asarray(BLUR_SIGMAS_CELLS)
    level = np.abs(want[..., None] - sig).argmin(axis=-1)
    out = np.empty((h, w), np.float32)
    for k in np.unique(level):
        sample = cv2.remap(rgrid.levels[k], map_x, map_y, cv2.INTER_LINEAR,
                           borderMode=cv2.BORDER_REPLICATE)
        sel = level == k
        out[sel] = sample[sel]
    out[~hit.reshape(h, w)] = rgrid.sky_radiance
    return out, rng_m.reshape(h, w).astype(np.float32)


def at_camera_radiance(surface_radiance: np.ndarray, range_m: np.ndarray, atmos: Atmosphere,
                       table: BandTable) -> np.ndarray:
    """Radiance reaching the camera (H, W) float32: surface attenuated plus path emission."""
    tau = atmospheric_transmittance(np.clip(range_m, 0.0, 1000.0), atmos.t_air_k, atmos.rh_pct,
                                    atmos.pressure_hpa, table.lambda_min_um,
                                    table.lambda_max_um)
    return observed_radiance(surface_radiance, tau, atmos.t_air_k, table).astype(np.float32)
