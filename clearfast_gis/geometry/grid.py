"""The ground grid: a north-up raster on the survey CRS (docs/contracts.md §1)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from affine import Affine


@dataclass(frozen=True)
class GroundGrid:
    """A north-up grid of square cells on the ground plane.

    Parameters
    ----------
    x0, y0 : float
        Upper-left corner (west edge, north edge), metres in the survey CRS.
    pixel_size : float
        Cell size, metres.
    width, height : int
        Number of columns and rows.
    epsg : int or None
        EPSG code of the CRS (None for a local metric frame).
    """

    x0: float
    y0: float
    pixel_size: float
    width: int
    height: int
    epsg: int | None = None

    def __post_init__(self) -> None:
        if not (self.pixel_size > 0 and math.isfinite(self.pixel_size)):
            raise ValueError(f"pixel_size must be positive, got {self.pixel_size}")
        if int(self.width) != self.width or int(self.height) != self.height \
                or self.width < 1 or self.height < 1:
            raise ValueError(f"grid size must be positive integers, got {self.width}x"
                             f"{self.height}")
        object.__setattr__(self, "width", int(self.width))
        object.__setattr__(self, "height", int(self.height))

    @classmethod
    def from_bounds(cls, xmin: float, ymin: float, xmax: float, ymax: float,
                    pixel_size: float, epsg: int | None = None) -> GroundGrid:
        """The grid with upper-left corner (xmin, ymax) covering the bounds (rounded up)."""
        if not (xmax > xmin and ymax > ymin):
            raise ValueError("bounds must have xmax > xmin and ymax > ymin")
        width = max(1, math.ceil((xmax - xmin) / pixel_size - 1e-9))
        height = max(1, math.ceil((ymax - ymin) / pixel_size - 1e-9))
        return cls(float(xmin), float(ymax), float(pixel_size), width, height, epsg)

    @property
    def shape(self) -> tuple[int, int]:
        """(height, width) in cells."""
        return (self.height, self.width)

    @property
    def transform(self) -> Affine:
        """rasterio transform ``Affine(ps, 0, x0, 0, -ps, y0)``."""
        return Affine(self.pixel_size, 0.0, self.x0, 0.0, -self.pixel_size, self.y0)

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """(xmin, ymin, xmax, ymax) of the grid's outer edges."""
        return (self.x0, self.y0 - self.height * self.pixel_size,
                self.x0 + self.width * self.pixel_size, self.y0)

    def x_centres(self) -> np.ndarray:
        """Easting of the column centres, shape (W,)."""
        return self.x0 + (np.arange(self.width) + 0.5) * self.pixel_size

    def y_centres(self) -> np.ndarray:
        """Northing of the row centres, shape (H,)."""
        return self.y0 - (np.arange(self.height) + 0.5) * self.pixel_size

    def cell_centres(self) -> tuple[np.ndarray, np.ndarray]:
        """Easting and northing of every cell centre, two arrays of shape (H, W)."""
        return np.meshgrid(self.x_centres(), self.y_centres())

    def rowcol(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Fractional (row, col) of points, cell centres at integers."""
        col = (np.asarray(x, dtype=float) - self.x0) / self.pixel_size - 0.5
        row = (self.y0 - np.asarray(y, dtype=float)) / self.pixel_size - 0.5
        return row, col
