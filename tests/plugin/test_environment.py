"""The venv's own geospatial stack works beside Debian's QGIS in one process.

A venv made with --system-site-packages sees Debian's older Python packages (Debian's affine
breaks current rasterio); the venv must shadow them with its own versions.
"""

from __future__ import annotations

import numpy as np
import pytest
from affine import Affine

pytestmark = pytest.mark.qgis


def test_toolkit_stack_is_the_venvs_and_works_with_qgis(qgis_app, tmp_path):
    import affine
    import rasterio
    from qgis.core import QgsRasterLayer

    from clearfast_gis.export import read_mosaic, write_cog

    for module in (affine, rasterio):
        assert "/usr/lib/python3/dist-packages" not in module.__file__
    major, minor = (int(v) for v in affine.__version__.split(".")[:2])
    assert (major, minor) >= (2, 4)
    path = tmp_path / "scan_000.tif"
    bands = np.linspace(5.0, 25.0, 64 * 96, dtype=np.float32).reshape(1, 64, 96)
    write_cog(path, bands, Affine(0.1, 0, 532780.0, 0, -0.1, 3891985.0), 32636, ["LW1 8.0-9.2 um"])
    np.testing.assert_array_equal(read_mosaic(path).bands_c, bands)
    layer = QgsRasterLayer(str(path), "scan", "gdal")
    assert layer.isValid() and layer.crs().authid() == "EPSG:32636"
    assert layer.bandName(1).endswith("LW1 8.0-9.2 um")
    stats = layer.dataProvider().bandStatistics(1)
    assert stats.minimumValue == pytest.approx(5.0) and stats.maximumValue == pytest.approx(25.0)
