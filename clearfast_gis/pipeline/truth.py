"""Scoring products against a simulated survey's ground truth (``truth/objects.csv``).

Used by ``clearfast demo``, the end-to-end tests and the accuracy benchmarks. The processing
chain itself never reads ``truth/``.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

MINE_KINDS = ("at_mine", "ap_mine")
MINE_CUES = ("at_mine", "ap_mine")


@dataclass
class TruthScore:
    """How the suspects compare with the true mines.

    Attributes
    ----------
    n_mines, n_detected : int
        True mines (of the scored depths) and how many a suspect matched.
    n_suspects, n_false_alarms : int
        Suspects cued as mines, and those that match no mine.
    footprint_m2 : float
        Area of the mosaic footprint.
    centre_errors_m, diameter_rel_errors, depth_errors_m : list of float
        Per matched mine.
    missed : list of str
        Ids of the missed mines.
    """

    n_mines: int
    n_detected: int
    n_suspects: int
    n_false_alarms: int
    footprint_m2: float
    centre_errors_m: list[float] = field(default_factory=list)
    diameter_rel_errors: list[float] = field(default_factory=list)
    depth_errors_m: list[float] = field(default_factory=list)
    missed: list[str] = field(default_factory=list)

    @property
    def detection_probability(self) -> float:
        return self.n_detected / self.n_mines if self.n_mines else math.nan

    @property
    def false_alarms_per_m2(self) -> float:
        return self.n_false_alarms / self.footprint_m2 if self.footprint_m2 else math.nan

    def summary(self) -> str:
        """Human-readable one-paragraph summary."""
        def rms(v):
            return float(np.sqrt(np.mean(np.square(v)))) if v else math.nan

        lines = [
            f"ground truth: {self.n_detected} of {self.n_mines} mines detected "
            f"(Pd {self.detection_probability:.2f}); {self.n_false_alarms} false alarms among "
            f"{self.n_suspects} mine-cued suspects "
            f"({self.false_alarms_per_m2:.3f} per m2 of {self.footprint_m2:.0f} m2)",
            f"centre error RMS {100 * rms(self.centre_errors_m):.1f} cm; diameter error RMS "
            f"{100 * rms(self.diameter_rel_errors):.0f} %; depth error RMS "
            f"{100 * rms(self.depth_errors_m):.1f} cm over {len(self.depth_errors_m)} "
            "characterised mines",
        ]
        if self.missed:
            lines.append("missed: " + ", ".join(self.missed))
        return "\n".join(lines)


def read_truth_objects(survey: str | Path) -> list[dict]:
    """Rows of ``<survey>/truth/objects.csv`` with numeric fields converted (``survey`` is any
    folder holding ``truth/``: a simulated survey, or the device simulators' folder)."""
    with open(Path(survey) / "truth" / "objects.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    for r in rows:
        for k in ("x", "y", "depth_m", "diameter_m", "diffusivity_m2s"):
            r[k] = float(r[k]) if r.get(k) not in (None, "") else math.nan
    return rows


def score_against_truth(survey: str | Path, products: str | Path, max_depth_m: float = 0.05,
                        match_radius_m: float | None = None,
                        truth: str | Path | None = None) -> TruthScore:
    """Match suspects to true mines.

    A mine counts as detected when a suspect of any class lies within ``match_radius_m``
    (default: the mine's radius plus 5 cm) of its centre. False alarms are suspects cued
    ``at_mine``/``ap_mine`` that match no mine (buried or not).

    Parameters
    ----------
    survey, products : path
    max_depth_m : float
        Only mines surface-laid or buried at most this deep are scored for detection.
    truth : path, optional
        The folder holding ``truth/`` when it is not the survey (an acquisition from the
        device simulators: their folder).
    """
    import geopandas as gpd

    truth = read_truth_objects(survey if truth is None else truth)
    mines = [r for r in truth if r["kind"] in MINE_KINDS]
    gpkg = Path(products) / "anomalies.gpkg"
    sus = gpd.read_file(gpkg, layer="suspects")
    fp = gpd.read_file(gpkg, layer="footprint")
    footprint = fp.geometry.union_all() if len(fp) else None
    area = float(footprint.area) if footprint is not None else 0.0
    sx, sy = sus["x"].to_numpy(float), sus["y"].to_numpy(float)
    cue = sus["class_cue"].to_numpy(str)
    from shapely.geometry import Point

    score = TruthScore(0, 0, int(np.isin(cue, MINE_CUES).sum()), 0, area)
    matched_suspects = set()
    for m in mines:
        inside = footprint is None or footprint.contains(Point(m["x"], m["y"]))
        radius = match_radius_m if match_radius_m is not None else 0.5 * m["diameter_m"] + 0.05
        d = np.hypot(sx - m["x"], sy - m["y"]) if len(sx) else np.array([])
        hits = np.flatnonzero(d <= radius)
        matched_suspects.update(hits.tolist())
        if not inside or m["depth_m"] > max_depth_m + 1e-9:
            continue
        score.n_mines += 1
        if hits.size == 0:
            score.missed.append(f"{m['id']} ({m['kind']}, {100 * m['depth_m']:.0f} cm)")
            continue
        score.n_detected += 1
        j = hits[np.argmin(d[hits])]
        score.centre_errors_m.append(float(d[j]))
        score.diameter_rel_errors.append(float(sus["diameter_m"].iloc[j] / m["diameter_m"] - 1))
        if sus["status"].iloc[j] == "ok" and np.isfinite(sus["depth_m"].iloc[j]):
            score.depth_errors_m.append(float(sus["depth_m"].iloc[j] - m["depth_m"]))
    fa = [i for i in range(len(sus)) if cue[i] in MINE_CUES and i not in matched_suspects]
    score.n_false_alarms = len(fa)
    return score
