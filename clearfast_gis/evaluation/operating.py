"""Operating curves of a ranked suspect list and the calibration of ``p_mine``.

A planner clears suspects in ``priority`` order. After the first k suspects:

- expected (no truth; what ``products.json`` and ``report.html`` state): the expected number
  of mines found is ``sum_{i<=k} p_i`` and of false alarms ``sum_{i<=k} (1 - p_i)``, per m2 of
  the surveyed footprint;
- measured (simulated surveys, :func:`operating_curve`): the share of the true mines matched by
  one of the first k suspects (Pd) and the suspects among them that match no object of a mine
  kind, per m2.
"""

from __future__ import annotations

import numpy as np


def expected_operating_curve(p_mine: np.ndarray, area_m2: float) -> dict[str, list[float]]:
    """The expected curve of a list ranked by decreasing ``p_mine`` (K,).

    Returns
    -------
    dict with lists (K,): ``priority`` (1..K), ``p_mine``, ``expected_mines`` (cumulative),
    ``expected_false_alarms_per_m2`` (cumulative, per m2 of ``area_m2``).
    """
    p = np.asarray(p_mine, dtype=float)
    area = float(area_m2) if area_m2 > 0 else float("nan")
    return {"priority": list(range(1, p.size + 1)),
            "p_mine": [round(float(v), 3) for v in p],
            "expected_mines": [round(float(v), 3) for v in np.cumsum(p)],
            "expected_false_alarms_per_m2": [round(float(v), 5)
                                             for v in np.cumsum(1.0 - p) / area]}


def operating_curve(hit_mine: np.ndarray, is_false_alarm: np.ndarray, n_mines: int,
                    area_m2: float) -> tuple[np.ndarray, np.ndarray]:
    """Measured Pd and false alarms per m2 after each of K ranked suspects.

    Parameters
    ----------
    hit_mine : int (K,)
        Per suspect in priority order, the index of the scored mine it is the first to match,
        or -1 (no scored mine, or a mine an earlier suspect already matched).
    is_false_alarm : bool (K,)
        The suspect matches no object of a mine kind.
    n_mines : int
        Scored mines.
    area_m2 : float

    Returns
    -------
    pd, fa_per_m2 : float (K + 1,)
        Starting at 0 suspects.
    """
    hits = np.concatenate([[0], np.cumsum(np.asarray(hit_mine) >= 0)])
    fas = np.concatenate([[0], np.cumsum(np.asarray(is_false_alarm, dtype=bool))])
    return hits / max(n_mines, 1), fas / float(area_m2)


def pd_at_false_alarm_rate(pd: np.ndarray, fa_per_m2: np.ndarray, max_fa_per_m2: float
                           ) -> float:
    """Highest Pd reached before the false alarms exceed ``max_fa_per_m2``."""
    ok = np.asarray(fa_per_m2) <= max_fa_per_m2 + 1e-12
    return float(np.max(np.asarray(pd)[ok])) if ok.any() else 0.0


def reliability_table(p: np.ndarray, is_mine: np.ndarray,
                      edges: tuple[float, ...] = (0.0, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0)
                      ) -> list[dict]:
    """Of the suspects predicted in each ``p_mine`` bin, how many are mines.

    Returns
    -------
    list of dict: ``bin`` ("0.7-0.9"), ``n``, ``mean_p``, ``mine_fraction`` (None when empty).
    """
    p = np.asarray(p, dtype=float)
    y = np.asarray(is_mine, dtype=bool)
    rows = []
    for k, (lo, hi) in enumerate(zip(edges[:-1], edges[1:], strict=True)):
        sel = (p >= lo) & ((p < hi) if k < len(edges) - 2 else (p <= hi))
        n = int(sel.sum())
        rows.append({"bin": f"{lo:.1f}-{hi:.1f}", "n": n,
                     "mean_p": round(float(p[sel].mean()), 3) if n else None,
                     "mine_fraction": round(float(y[sel].mean()), 3) if n else None})
    return rows
