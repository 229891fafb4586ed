"""Fast per-pixel ray directions for rendering whole frames (tested against ``Camera.rays``).

Rendering needs the world direction of every pixel of every frame; the general
:meth:`Camera.rays` works on point lists. Two structural shortcuts make whole frames cheap:

- equiangular camera (paper Eq. 6): azimuth depends only on the column and elevation only on
  the row, so the base-frame direction ``(sin A cos E, cos A cos E, sin E)`` is an outer
  product of per-column and per-row sines and cosines; the platform attitude is then a 3x3
  rotation applied component-wise;
- pinhole camera: the undistorted camera-frame direction of each pixel does not depend on the
  pose, so it is computed once per band and rotated by ``R_world_from_cam`` per frame.
"""

from __future__ import annotations

import numpy as np

from clearfast_gis.geometry.cameras import EquiangularCamera, PinholeCamera
from clearfast_gis.geometry.pose import CameraPose


class FrameRays:
    """World ray directions of all pixels of a camera, for a fixed pixel shift.

    Parameters
    ----------
    camera : EquiangularCamera or PinholeCamera
    shift_px : (float, float)
        Offset (du, dv) added to every pixel centre (filter-wheel misregistration), pixels.
    """

    def __init__(self, camera, shift_px: tuple[float, float] = (0.0, 0.0)) -> None:
        self.camera = camera
        self.shift_px = (float(shift_px[0]), float(shift_px[1]))
        h, w = camera.height, camera.width
        if isinstance(camera, EquiangularCamera):
            u = np.arange(w) + self.shift_px[0]
            v = np.arange(h) + self.shift_px[1]
            self._d_az = (u - (w - 1) / 2.0) * camera.ifov_rad
            self._d_el = -(v - (h - 1) / 2.0) * camera.ifov_rad
            self._cam = None
        elif isinstance(camera, PinholeCamera):
            vv, uu = np.mgrid[0:h, 0:w].astype(np.float64)
            ident = CameraPose(np.zeros(3), 0.0, 0.0)
            # rays for the identity-like pose, then back to the camera frame once
            d_world = camera.rays(uu.ravel() + self.shift_px[0], vv.ravel() + self.shift_px[1],
                                  ident)
            d_cam = d_world @ ident.rotation()
            self._cam = tuple(d_cam[:, k].reshape(h, w) for k in range(3))
        else:
            raise TypeError(f"unsupported camera {type(camera).__name__}")

    def directions(self, pose: CameraPose) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Unit world directions (east, north, up components), each (H, W) float64."""
        if self._cam is None:
            az = np.radians(pose.azimuth_deg) + self._d_az
            el = np.radians(pose.elevation_deg) + self._d_el
            ce, se = np.cos(el)[:, None], np.sin(el)[:, None]
            bx = np.sin(az)[None, :] * ce
            by = np.cos(az)[None, :] * ce
            bz = np.broadcast_to(se, bx.shape)
            rot = pose.attitude()
        else:
            bx, by, bz = self._cam
            rot = pose.rotation()
        return (rot[0, 0] * bx + rot[0, 1] * by + rot[0, 2] * bz,
                rot[1, 0] * bx + rot[1, 1] * by + rot[1, 2] * bz,
                rot[2, 0] * bx + rot[2, 1] * by + rot[2, 2] * bz)
