"""Shared fixtures of the radiometry tests."""

from __future__ import annotations

import pytest

from clearfast_gis.radiometry import BandTable


@pytest.fixture(scope="session")
def lw_table() -> BandTable:
    """The 8-12 um band, 200-400 K."""
    return BandTable(8.0, 12.0)


@pytest.fixture(scope="session")
def lw1_table() -> BandTable:
    """The demo camera's LW1 band, 8.0-9.2 um."""
    return BandTable(8.0, 9.2)
