"""Are the chain's statuses honest? Each true mine's suspect status against its true depth.

A status is honest when it flags (``weak_contrast``, ``not_characterised``), or when the depth
it gives with ``ok`` or ``at_bound`` lies within 2 sigma (at least 1 cm) of the true depth.
A confident depth further off is a confidently wrong answer, worse than "not characterised".
Mines are matched to suspects as in :func:`~clearfast_gis.evaluation.truth.score_against_truth`
(within the mine's radius plus 5 cm).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from clearfast_gis.evaluation.truth import MINE_KINDS, nearest_match, read_truth_objects

#: Statuses that withhold a depth or flag it.
FLAGS = ("weak_contrast", "not_characterised")
#: A confident depth is wrong beyond this many sigma and this many metres.
WRONG_SIGMA = 2.0
WRONG_FLOOR_M = 0.01


def _finite(v) -> float | None:
    if v is None:
        return None
    v = float(v)
    return v if math.isfinite(v) else None


def honest(status: str, depth_m: float | None, sigma_m: float | None,
           true_depth_m: float) -> bool:
    """True unless a confident (``ok``/``at_bound``) depth misses the truth by more than
    ``max(2 sigma, 1 cm)``."""
    if status in FLAGS or depth_m is None:
        return True
    return abs(depth_m - true_depth_m) <= max(WRONG_SIGMA * (sigma_m or 0.0), WRONG_FLOOR_M)


@dataclass(frozen=True)
class MineStatus:
    """A true mine and the status of the suspect that matched it (metres)."""

    mine_id: str
    true_depth_m: float
    status: str
    depth_m: float | None
    depth_sigma_m: float | None

    @property
    def honest(self) -> bool:
        """See :func:`honest`."""
        return honest(self.status, self.depth_m, self.depth_sigma_m, self.true_depth_m)

    @property
    def confident(self) -> bool:
        """A depth given with ``ok`` or ``at_bound``."""
        return self.status not in FLAGS and self.depth_m is not None


def mine_statuses(survey: str | Path, products: str | Path) -> list[MineStatus]:
    """The status of every true mine (any depth) that a suspect matched."""
    import geopandas as gpd

    sus = gpd.read_file(Path(products) / "anomalies.gpkg", layer="suspects")
    sx, sy = sus["x"].to_numpy(float), sus["y"].to_numpy(float)
    out = []
    for m in read_truth_objects(survey):
        j = nearest_match(sx, sy, m) if m["kind"] in MINE_KINDS else None
        if j is None:
            continue
        rec = sus.iloc[j]
        out.append(MineStatus(str(m["id"]), float(m["depth_m"]), str(rec["status"]),
                              _finite(rec["depth_m"]), _finite(rec["depth_sigma_m"])))
    return out
