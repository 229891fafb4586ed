"""A grass canopy over the soil: the weather the soil sees under it and the share of the soil
the camera sees through it.

A canopy of cover fraction ``f`` (0-1) intercepts that share of the sun and replaces that
share of the sky by its own long-wave emission, taken at air temperature (a leaf is within a
few kelvin of the air); wind and rain reach the soil unchanged. Seen from above, the leaves
hide that share of the soil, so a buried object's surface contrast reaches the mosaics times
``1 - f``. The twin forces its soil and objects under grass this way; the chain does the same
with the cover the survey records for its site (``survey.json`` ``site.vegetation_cover``).
"""

from __future__ import annotations

from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.units import STEFAN_BOLTZMANN

LEAF_EMISSIVITY = 0.97
"""Broadband long-wave emissivity of grass leaves (Campbell & Norman 1998, Table 11.3)."""

RECORDED_COVER_SIGMA = 0.1
"""1-sigma error of a cover a survey team records by eye (0-1 scale): the share of the
contrast seen through the canopy is uncertain by this over ``1 - cover``."""


def under_canopy(forcing: Forcing, cover: float) -> Forcing:
    """The weather the soil sees under a grass canopy of cover fraction ``cover`` (0-1).

    Short-wave times ``1 - cover``; sky long-wave ``(1 - cover) L_sky + cover eps_leaf sigma
    T_air^4`` (W m-2); air temperature, wind, humidity and rain unchanged.
    """
    if cover <= 0.0:
        return forcing
    f = float(cover)
    air = forcing.air_temp_k
    sky = (1.0 - f) * forcing.sky_lw_wm2 + f * LEAF_EMISSIVITY * STEFAN_BOLTZMANN * air**4
    return Forcing(forcing.time_s, (1.0 - f) * forcing.solar_wm2, sky, air, forcing.wind_ms,
                   forcing.rh_pct, forcing.rain_mm_h)


def seen_share(cover: float) -> float:
    """Share of the soil's surface (and of a buried object's contrast) seen through a canopy
    of cover fraction ``cover``: ``1 - cover``."""
    return 1.0 - min(max(float(cover), 0.0), 1.0)


def cover_gain_sigma(cover: float) -> float:
    """1-sigma relative error of the seen contrast from the recorded cover:
    :data:`RECORDED_COVER_SIGMA` / ``(1 - cover)`` under a canopy, 0 on bare ground."""
    if cover <= 0.0:
        return 0.0
    return RECORDED_COVER_SIGMA / max(seen_share(cover), RECORDED_COVER_SIGMA)
