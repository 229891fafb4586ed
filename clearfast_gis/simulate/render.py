"""Rendering of camera frames from a radiance grid: ray tracing, footprint sampling, atmosphere.

Every pixel's ray (shifted by the band's filter-wheel misregistration,
:class:`~clearfast_gis.simulate.rays.FrameRays`) is intersected with the ground plane; the
surface-leaving radiance is sampled there with
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
from clearfast_gis.simulate.rays import FrameRays
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


def footprint_m(range_m: np.ndarray, ray_z: np.ndarray, ifov_rad: float) -> np.ndarray:
    """Geometric-mean ground footprint of pixels, metres.

    Across the line of sight the footprint is ``R ifov``; along it, ``R ifov / sin(grazing)``.
    """
    sin_graze = np.clip(np.abs(ray_z), 0.05, 1.0)
    return range_m * np.float32(ifov_rad) / np.sqrt(sin_graze)


def surface_radiance_frame(rays: FrameRays, pose: CameraPose, rgrid: RadianceGrid,
                           ifov_rad: float) -> tuple[np.ndarray, np.ndarray]:
    """Surface-leaving radiance seen by each pixel, and the pixel's slant range.

    Parameters
    ----------
    rays : FrameRays
        The camera's pixel rays (with the band's filter-wheel misregistration).
    pose : CameraPose
        True pose of the camera.
    rgrid : RadianceGrid
    ifov_rad : float
        Angular size of a pixel, radians.

    Returns
    -------
    radiance : float32 (H, W)
        W m-2 sr-1 (the sky radiance where the ray misses the ground).
    range_m : float32 (H, W)
        Slant range camera-ground, metres (0 where the ray misses the ground).
    """
    dx, dy, dz = (d.astype(np.float32) for d in rays.directions(pose))
    hit = dz < -1e-6
    t = np.where(hit, np.float32(-pose.position_m[2]) / np.where(hit, dz, np.float32(-1.0)),
                 np.float32(0.0))
    grid = rgrid.grid
    inv = np.float32(1.0 / grid.pixel_size)
    # offsets from the grid corner in float64 first (UTM coordinates), then float32 per pixel
    cx = np.float32((pose.position_m[0] - grid.x0) / grid.pixel_size - 0.5)
    cy = np.float32((grid.y0 - pose.position_m[1]) / grid.pixel_size - 0.5)
    map_x = cx + (t * dx) * inv
    map_y = cy - (t * dy) * inv
    # the pixel's box footprint matches a Gaussian of sigma ~ 0.4 footprint
    want = (np.float32(0.4) * inv) * footprint_m(t, dz, ifov_rad)
    sig = np.asarray(BLUR_SIGMAS_CELLS)
    level = np.digitize(want, 0.5 * (sig[1:] + sig[:-1]))
    k_lo, k_hi = int(level.min()), int(level.max())
    out = cv2.remap(rgrid.levels[k_lo], map_x, map_y, cv2.INTER_LINEAR,
                    borderMode=cv2.BORDER_REPLICATE)
    for k in range(k_lo + 1, k_hi + 1):
        sel = level == k
        if sel.any():
            sample = cv2.remap(rgrid.levels[k], map_x, map_y, cv2.INTER_LINEAR,
                               borderMode=cv2.BORDER_REPLICATE)
            out[sel] = sample[sel]
    out[~hit] = rgrid.sky_radiance
    return out, t


def at_camera_radiance(surface_radiance: np.ndarray, range_m: np.ndarray, atmos: Atmosphere,
                       table: BandTable) -> np.ndarray:
    """Radiance reaching the camera (H, W) float32: surface attenuated plus path emission."""
    tau = atmospheric_transmittance(np.clip(range_m, 0.0, 1000.0), atmos.t_air_k, atmos.rh_pct,
                                    atmos.pressure_hpa, table.lambda_min_um,
                                    table.lambda_max_um)
    return observed_radiance(surface_radiance, tau, atmos.t_air_k, table).astype(np.float32)
