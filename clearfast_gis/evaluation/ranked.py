"""Score a ranked suspect list and its depth estimates against a simulated survey's truth.

Used by ``benchmarks/detection_accuracy.py`` and the tests; the chain never reads ``truth/``.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from clearfast_gis.evaluation.operating import operating_curve, pd_at_false_alarm_rate
from clearfast_gis.evaluation.truth import MINE_KINDS, mine_match_radius_m, read_truth_objects

SCORED_MAX_DEPTH_M = 0.05
"""Mines at most this deep are scored for detection (the issue's goal)."""


@dataclass
class DepthRow:
    """One matched mine's depth and diffusivity estimate (metres, m2/s)."""

    mine_id: str
    true_depth_m: float
    depth_m: float
    depth_sigma_m: float
    status: str
    true_alpha_m2s: float
    alpha_m2s: float
    alpha_sigma_m2s: float


@dataclass
class RankedScore:
    """How a ranked suspect list of one survey compares with its truth.

    Attributes
    ----------
    n_scored_mines : int
        Mines at most :data:`SCORED_MAX_DEPTH_M` deep inside the footprint.
    footprint_m2 : float
    pd, fa_per_m2 : float arrays (K + 1,)
        Measured operating curve down the list (:func:`operating_curve`).
    p_mine, is_mine : arrays (K,)
        Per suspect in priority order: its p_mine and whether it lies on a mine (any depth).
    depths : list of DepthRow
        Every mine matched by a suspect (any depth, any status).
    n_candidate_mines : int
        Mines (any depth) that only a candidate (set aside) matched.
    n_candidates : int
        Detections set aside.
    """

    n_scored_mines: int
    footprint_m2: float
    pd: np.ndarray
    fa_per_m2: np.ndarray
    p_mine: np.ndarray
    is_mine: np.ndarray
    depths: list[DepthRow] = field(default_factory=list)
    n_candidate_mines: int = 0
    n_candidates: int = 0

    def pd_at(self, max_fa_per_m2: float) -> float:
        """Pd reached before the false alarms exceed ``max_fa_per_m2``."""
        return pd_at_false_alarm_rate(self.pd, self.fa_per_m2, max_fa_per_m2)


def _near(sx: np.ndarray, sy: np.ndarray, m: dict) -> np.ndarray:
    return np.hypot(sx - m["x"], sy - m["y"]) <= mine_match_radius_m(m)


def _reranked(gpkg: Path, model: Mapping) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Suspects (in priority order) and candidates of the ``anomalies`` layer, screened and
    ranked again under ``model``."""
    import geopandas as gpd

    from clearfast_gis.detection.likelihood import screen_and_rank

    frame = gpd.read_file(gpkg, layer="anomalies")
    recs = frame.drop(columns="geometry").astype(object).where(frame.notna(), None)
    n_scans = len(json.loads((gpkg.parent / "products.json").read_text())["scans"])
    out = pd.DataFrame(screen_and_rank(recs.to_dict("records"), n_scans, model))
    aside = out["set_aside_reason"].notna()
    return (out[~aside].sort_values("priority").reset_index(drop=True),
            out[aside].reset_index(drop=True))


def score_ranked(survey: str | Path, products: str | Path,
                 model: Mapping | None = None) -> RankedScore:
    """Score ``PRODUCTS/anomalies.gpkg`` (layers ``suspects`` in priority order,
    ``candidates``, ``footprint``) against ``SURVEY/truth/objects.csv``.

    A suspect is a false alarm when it lies within no mine's radius plus 5 cm (mines of any
    depth: a deep mine found is no false alarm). A scored mine is found at the rank of the
    first suspect within its radius plus 5 cm. With a likelihood ``model``
    (:func:`clearfast_gis.detection.likelihood.load_model`'s form) the detections of the
    ``anomalies`` layer are screened and ranked again under it instead.
    """
    import geopandas as gpd
    from shapely.geometry import Point

    gpkg = Path(products) / "anomalies.gpkg"
    if model is None:
        sus = gpd.read_file(gpkg, layer="suspects").sort_values("priority")
        sus = sus.reset_index(drop=True)
        cand = gpd.read_file(gpkg, layer="candidates")
    else:
        sus, cand = _reranked(gpkg, model)
    fp = gpd.read_file(gpkg, layer="footprint")
    footprint = fp.geometry.union_all()
    mines = [m for m in read_truth_objects(survey) if m["kind"] in MINE_KINDS
             and footprint.contains(Point(m["x"], m["y"]))]
    sx, sy = sus["x"].to_numpy(float), sus["y"].to_numpy(float)
    cx, cy = cand["x"].to_numpy(float), cand["y"].to_numpy(float)
    on_mine = np.zeros(len(sus), dtype=bool)
    hit = np.full(len(sus), -1)
    scored = [m for m in mines if m["depth_m"] <= SCORED_MAX_DEPTH_M + 1e-9]
    depths, n_cand = [], 0
    for m in mines:
        near = _near(sx, sy, m)
        on_mine |= near
        if near.any():
            j = int(np.flatnonzero(near)[0])
            r = sus.iloc[j]

            def val(k, r=r):
                v = r.get(k)
                return float(v) if v is not None and np.isfinite(v) else math.nan

            depths.append(DepthRow(m["id"], m["depth_m"], val("depth_m"), val("depth_sigma_m"),
                                   str(r["status"]), m["diffusivity_m2s"],
                                   val("diffusivity_m2s"), val("diffusivity_sigma_m2s")))
        elif len(cx) and _near(cx, cy, m).any():
            n_cand += 1
    for k, m in enumerate(scored):
        near = np.flatnonzero(_near(sx, sy, m))
        if near.size:
            first = int(near[0])
            if hit[first] < 0:
                hit[first] = k
            else:  # two mines first found by one suspect: count the second at the next free
                later = [j for j in near if hit[j] < 0]
                if later:
                    hit[later[0]] = k
    pd, fa = operating_curve(hit, ~on_mine, len(scored), float(footprint.area))
    p = sus["p_mine"].to_numpy(float) if "p_mine" in sus else np.full(len(sus), np.nan)
    return RankedScore(len(scored), float(footprint.area), pd, fa, p, on_mine, depths, n_cand,
                       len(cand))
