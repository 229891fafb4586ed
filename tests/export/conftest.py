"""Fixtures of the product-writer tests."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="session")
def demo_products(tmp_path_factory):
    """A small products folder made by the writers (3 scans, 0.1 m pixels, no figures)."""
    from clearfast_gis.export.testing import make_demo_products

    return make_demo_products(tmp_path_factory.mktemp("products"), n_scans=3, pixel_size_m=0.1,
                              figures=False)
