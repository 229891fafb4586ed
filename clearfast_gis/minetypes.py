"""The mine types a survey expects: the sizes the chain compares anomalies against.

A survey in the project's area of work expects the blast AP mine M2A4 and the AT mine M6A2
(the paper's trial site); their sizes are public (ORDATA). The chain uses them in two places:
the mine likelihood's size cue (:mod:`clearfast_gis.detection.likelihood`) and the thermal
inversion's object (:mod:`clearfast_gis.thermal.sitesoil`), which models an anomaly as the
mine type nearest its footprint rather than as an object of the footprint's size.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class MineType:
    """A mine type: ``name``, casing ``diameter_m`` and ``height_m`` (metres)."""

    name: str
    diameter_m: float
    height_m: float

    @property
    def radius_m(self) -> float:
        """Radius, m."""
        return 0.5 * self.diameter_m


MINE_TYPES = (MineType("AP M2A4", 0.104, 0.08), MineType("AT M6A2", 0.337, 0.094))
"""The mine types expected on the surveys."""


def nearest_mine_type(diameter_m: float, types: tuple[MineType, ...] = MINE_TYPES) -> MineType:
    """The type whose diameter is nearest ``diameter_m`` (m) in ratio (``|ln(d / D)|``);
    the first type for a diameter that is not positive and finite."""
    if not (math.isfinite(diameter_m) and diameter_m > 0):
        return types[0]
    return min(types, key=lambda t: abs(math.log(diameter_m / t.diameter_m)))
