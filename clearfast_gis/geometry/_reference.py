"""The ground projection's reference kernel (``--kernels reference``): the registry's
reference of ``ground_maps`` (:mod:`clearfast_gis.kernels`), every cell projected by the
camera model itself."""

from __future__ import annotations

import numpy as np

from clearfast_gis.geometry.cameras import Camera
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.geometry.pose import CameraPose
from clearfast_gis.geometry.projection import NOT_SEEN


def ground_maps(camera: Camera, pose: CameraPose, grid: GroundGrid, z: float = 0.0,
                bound: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """:func:`clearfast_gis.geometry.projection.ground_maps` computed with the camera's numpy
    ``project`` for every cell (the reference of ``--kernels reference``); same shapes and
    conventions (``bound`` changes nothing in the maps)."""
    x, y = grid.cell_centres()
    uv = camera.project(np.column_stack([x.ravel(), y.ravel(), np.full(x.size, float(z))]),
                        pose)
    uv[~camera.in_frame(uv)] = NOT_SEEN
    return (uv[:, 0].reshape(grid.shape).astype(np.float32),
            uv[:, 1].reshape(grid.shape).astype(np.float32))
