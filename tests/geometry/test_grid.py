"""GroundGrid corner convention and transform."""

from __future__ import annotations

import numpy as np
import pytest
from affine import Affine

from clearfast_gis.geometry import GroundGrid


def test_transform_and_centres():
    g = GroundGrid(500000.0, 3890030.0, 0.05, 600, 400, 32636)
    assert g.transform == Affine(0.05, 0, 500000.0, 0, -0.05, 3890030.0)
    x, y = g.cell_centres()
    assert x.shape == y.shape == (400, 600)
    assert (x[3, 7], y[3, 7]) == pytest.approx((500000.0 + 7.5 * 0.05, 3890030.0 - 3.5 * 0.05))
    # the rasterio transform maps (col + 0.5, row + 0.5) to the centre
    assert g.transform @ (7.5, 3.5) == pytest.approx((x[3, 7], y[3, 7]))
    row, col = g.rowcol(x[3, 7], y[3, 7])
    assert (row, col) == pytest.approx((3.0, 7.0))


def test_from_bounds_covers():
    g = GroundGrid.from_bounds(10.0, 20.0, 40.0, 40.0, 0.07, 32636)
    xmin, ymin, xmax, ymax = g.bounds
    assert (g.x0, g.y0) == (10.0, 40.0)
    assert xmin == 10.0 and ymax == 40.0 and xmax >= 40.0 and ymin <= 20.0
    assert xmax - 40.0 < 0.07 and 20.0 - ymin < 0.07
    g = GroundGrid.from_bounds(0, 0, 30, 20, 0.1)
    assert g.shape == (200, 300)


def test_bad_grid():
    with pytest.raises(ValueError):
        GroundGrid(0, 0, 0.0, 10, 10)
    with pytest.raises(ValueError):
        GroundGrid.from_bounds(0, 0, -1, 1, 0.1)
    assert np.all(np.diff(GroundGrid(0, 0, 1, 3, 3).y_centres()) < 0)
