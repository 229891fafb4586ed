"""Grey-scale and binary morphological reconstruction (Vincent 1993, hybrid algorithm).

Reconstruction by dilation of a *seed* under a *mask* (``seed <= mask``) is the limit of
geodesic dilations of the seed inside the mask with the 3x3 element B (8-connectivity).
Vincent's hybrid algorithm does raster and anti-raster scans, the last of which also queues
the pixels that can still propagate, and then a FIFO-queue propagation; it gives exactly the
values of :func:`skimage.morphology.reconstruction` (only min and max are used, so no
rounding) and is several times faster on thermal images. A binary reconstruction is the
8-connected components of the mask that hold a seed: a fill from the seeds.

No-data: NaN pixels of a floating-point mask (or seed) are not part of the image. They neither
receive nor pass on values, so they behave like walls, and they are NaN in the result. This is
the same as giving them the value -inf in both seed and mask for reconstruction by dilation (and
+inf for reconstruction by erosion).

The compiled kernel and the functions that prepare its input live in
:mod:`clearfast_gis.detection._kernels` (the package's fast kernels); this module is their
public face.

Reference: L. Vincent, "Morphological grayscale reconstruction in image analysis: applications
and efficient algorithms", IEEE Trans. Image Processing 2(2), 176-201, 1993.
"""

from __future__ import annotations

import numpy as np

from clearfast_gis.detection._kernels import (
    binary_reconstruction,
    reconstruction_by_dilation,
    reconstruction_by_erosion,
)

__all__ = ["binary_reconstruction", "reconstruction", "reconstruction_by_dilation",
           "reconstruction_by_erosion"]


def reconstruction(seed: np.ndarray, mask: np.ndarray, method: str = "dilation") -> np.ndarray:
    """Reconstruction by ``'dilation'`` or ``'erosion'`` (skimage's calling convention)."""
    if method == "dilation":
        return reconstruction_by_dilation(seed, mask)
    if method == "erosion":
        return reconstruction_by_erosion(seed, mask)
    raise ValueError(f"method must be 'dilation' or 'erosion', got {method!r}")


