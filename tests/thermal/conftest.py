"""Shared fixtures for the thermal-model tests: a clear mid-November day in Cyprus."""

from __future__ import annotations

import numpy as np
import pytest

from clearfast_gis.thermal import MATERIALS, build_site_table, clear_sky_forcing
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


#: The inversion tests' object and soil: an AP-sized TNT cylinder in moist sand.
TNT_RADIUS_M, TNT_HEIGHT_M = 0.052, 0.05
SAND = MATERIALS["moist_sand"]


@pytest.fixture(scope="session")
def table(forcing, scans):
    """Site table of :data:`TNT_RADIUS_M` objects in :data:`SAND` on the 48 scans."""
    return build_site_table(
        forcing, SAND, TNT_RADIUS_M, scans, height_m=TNT_HEIGHT_M,
        depths_m=[0.0, 0.01, 0.02, 0.03, 0.04, 0.06, 0.08, 0.10, 0.15, 0.20],
        log10_alpha=[-7.5, -7.25, -7.0, -6.5, -6.0, -5.0, -4.5],
    )
