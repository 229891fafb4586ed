"""Which attitude a scan was placed with, and which scans a survey-wide adjustment moves.

A scan's frames are placed with its own fitted attitude, or (``adjusted`` in its run-state
record) with the survey-wide attitude of the adjustment (:mod:`.adjust`).
:func:`fit_survey_attitude` adjusts and lists the scans whose placement moves by more than
:data:`ADJUST_MIN_DEG`, which the chain projects again (:mod:`clearfast_gis.pipeline`).
"""

from __future__ import annotations

import numpy as np

from clearfast_gis.attitude.adjust import adjust_attitudes, attitude_at
from clearfast_gis.attitude.ties import LinearTie

ADJUST_MIN_DEG = 0.01
"""A scan is projected again when the adjustment changes the attitude of one of its frames by
more than this, degrees (0.01 deg moves the ground by 0.35 cm at 20 m range)."""


REFINE_MIN_SHARE = 0.25
"""The refined adjustment runs (by default) when the first one re-projects at least this share
of the scans: the platform moved during the survey (the trial's sinking lift), the per-scan
fits were chained through weak ties and the neighbour ties pay off. When the first adjustment
leaves (almost) every scan in place, the per-scan fits already agree and a second pass,
which measures about as many ties again as the whole mosaic stage, would only cost time."""


def placement_attitude(rec: dict, model: tuple[np.ndarray, np.ndarray] | None,
                       times_s: np.ndarray) -> np.ndarray:
    """Attitude (N, 3), degrees, that a scan's frames at ``times_s`` (N,) were placed with.

    Parameters
    ----------
    rec : dict
        The scan's run-state record.
    model : (node_times_s (S,), nodes_rpy_deg (S, 3)) or None
        The survey-wide attitude, for scans placed with it (``rec["adjusted"]``).
    times_s : float (N,)
        UTC epoch seconds.
    """
    t = np.atleast_1d(np.asarray(times_s, dtype=float))
    if rec.get("adjusted"):
        if model is None:
            raise ValueError(f"scan {rec.get('scan')} was placed with the adjusted attitude, "
                             "which is not known here")
        return attitude_at(t, *model)
    att = (rec.get("attitude") or {}).get("attitude_rpy_deg") or (0.0, 0.0, 0.0)
    return np.tile(np.asarray(att, dtype=float), (t.size, 1))


def _finite_or_none(v: float) -> float | None:
    return float(v) if np.isfinite(v) else None


def fit_survey_attitude(ties: list[LinearTie], order: list[int], node_times: np.ndarray,
                        prior: np.ndarray, times: dict[int, np.ndarray],
                        placed: dict[int, np.ndarray]) -> dict:
    """Adjust the survey's attitude to ``ties`` (:func:`adjust_attitudes`: ``order`` the scans
    in time order, ``node_times`` (S,) UTC epoch s, ``prior`` (S, 3) degrees) and list, under
    ``rebuild``, the scans whose frames the result moves by more than :data:`ADJUST_MIN_DEG`
    from their placement ``placed[s]`` (N, 3) at ``times[s]`` (N,); the run-state record of
    the adjustment (nodes, tie RMS before and after in metres, ties and inliers)."""
    adj = adjust_attitudes(ties, order, node_times, prior)
    rebuild = [s for s in order
               if np.max(np.abs(attitude_at(times[s], node_times, adj.nodes_rpy_deg)
                                - placed[s])) > ADJUST_MIN_DEG]
    return {"node_times_s": node_times.tolist(), "nodes_rpy_deg": adj.nodes_rpy_deg.tolist(),
            "rms_before_m": _finite_or_none(adj.rms_before_m),
            "rms_m": _finite_or_none(adj.rms_m), "n_ties": adj.n_ties,
            "n_used": adj.n_used, "rebuild": rebuild}


def nearest_attitude(scan: int, done: dict[int, tuple]) -> tuple:
    """Attitude (roll, pitch, yaw degrees) of the processed scan nearest ``scan`` in
    ``done`` (scan -> attitude), the start of its fit; zero attitude if none."""
    if not done:
        return (0.0, 0.0, 0.0)
    return done[min(done, key=lambda s: abs(s - scan))]
