"""Reading plain thermal images for snapshot mode (file I/O at the edge).

PNG, JPEG, BMP and other raster formats OpenCV reads are loaded as grey (colour images are
converted with OpenCV's luminance weights); TIFF goes through tifffile (radiometric float or
integer images keep their values; the first page, first band of a multi-band page).
"""

from __future__ import annotations

from pathlib import Path

import cv2
import numpy as np

from clearfast_gis.errors import InvalidInput

__all__ = ["read_image"]


def read_image(path: str | Path) -> np.ndarray:
    """Read one image as float32 (H, W).

    Raises
    ------
    InvalidInput
        When the file is missing, unreadable or not a 2-D image.
    """
    path = Path(path)
    if not path.is_file():
        raise InvalidInput("no such file", path)
    if path.suffix.lower() in (".tif", ".tiff"):
        import tifffile

        try:
            image = tifffile.imread(path, key=0)
        except Exception as exc:  # tifffile raises many types on corrupt files
            raise InvalidInput(f"not a readable TIFF ({type(exc).__name__})", path) from None
        image = np.asarray(image)
        if image.ndim == 3 and image.shape[-1] in (3, 4) and image.dtype == np.uint8:
            image = cv2.cvtColor(image[..., :3], cv2.COLOR_RGB2GRAY)
        elif image.ndim == 3:
            image = image[0] if image.shape[0] < image.shape[-1] else image[..., 0]
    else:
        image = cv2.imread(str(path), cv2.IMREAD_GRAYSCALE | cv2.IMREAD_ANYDEPTH)
        if image is None:
            raise InvalidInput("not a readable image (PNG, JPEG, TIFF, ...)", path)
    if image.ndim != 2 or min(image.shape) < 3:
        raise InvalidInput(f"expected a 2-D image, got shape {image.shape}", path)
    return image.astype(np.float32)
