"""Shared fixtures for the thermal-model tests: a clear mid-November day in Cyprus."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.thermal import clear_sky_forcing
from clearfast_gis.timeutil import parse_utc

LAT_DEG, LON_DEG = 35.17, 33.36
DAY0_S = parse_utc("2026-11-15T00:00:00Z")


@pytest.fixture(scope="session")
def forcing():
    return clear_sky_forcing(LAT_DEG, LON_DEG, DAY0_S, 86400.0)


@pytest.fixture(scope="session")
def scans():
    """48 scans over 24 h."""
    return DAY0_S + 900.0 + 1800.0 * np.arange(48)
