"""The survey-wide attitude adjustment stage: fit, then project again the scans it moves."""

from __future__ import annotations

import numpy as np

from clearfast_gis.mosaic.adjust import LinearTie, adjust_attitudes, attitude_at
from clearfast_gis.progress import Progress

ADJUST_MIN_DEG = 0.01
"""A scan is projected again when the adjustment changes the attitude of one of its frames by
more than this, degrees (0.01 deg moves the ground by 0.35 cm at 20 m range)."""

UNIT = "attitude_adjustment"
"""Run-state unit of the adjustment."""


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


def stored_model(state) -> tuple[np.ndarray, np.ndarray] | None:
    """The adjusted attitude recorded in the run state, if the adjustment ran."""
    unit = state.done(UNIT)
    if unit is None:
        return None
    return np.array(unit["node_times_s"], dtype=float), np.array(unit["nodes_rpy_deg"],
                                                                   dtype=float)


def adjust_survey_attitude(job, state, order: list[int], scan_records: dict[int, dict],
                           attitudes: dict[int, tuple], progress: Progress) -> dict:
    """Adjust the attitude of every scan at once and mosaic again the scans it moves.

    Parameters
    ----------
    job : the pipeline's scan job (``frame_times``, ``build``)
    state : RunState
        The adjustment is a unit of its own; re-projected scans are marked ``adjusted`` so an
        interrupted run resumes where it stopped.
    order : list of int
        Scans in time order.
    scan_records : dict
        Per-scan run-state records, updated in place.
    attitudes : dict
        Each scan's own fitted attitude, degrees (the prior).
    progress : Progress

    Returns
    -------
    dict
        Summary for products.json: RMS of the ties before and after (metres), ties, inliers,
        the scans projected again.
    """
    survey = job.ctx.survey
    times = {s: survey.frames.time_s[survey.scan_rows(s, 0)] for s in order}
    unit = state.done(UNIT)
    if unit is None:
        ties = [LinearTie.from_list(v) for s in order
                for v in (scan_records[s].get("ties") or [])]
        prior = np.array([attitudes.get(s, (0.0, 0.0, 0.0)) for s in order], dtype=float)
        node_times = np.array([scan_records[s]["time_s"] for s in order], dtype=float)
        adj = adjust_attitudes(ties, order, node_times, prior)
        rebuild = [s for s in order
                   if np.max(np.abs(attitude_at(times[s], node_times, adj.nodes_rpy_deg)
                                    - placement_attitude(scan_records[s], None, times[s])))
                   > ADJUST_MIN_DEG]
        unit = {"node_times_s": node_times.tolist(), "nodes_rpy_deg": adj.nodes_rpy_deg.tolist(),
                "rms_before_m": _finite_or_none(adj.rms_before_m),
                "rms_m": _finite_or_none(adj.rms_m), "n_ties": adj.n_ties,
                "n_used": adj.n_used, "rebuild": rebuild}
        state.finish(UNIT, unit)
    model = stored_model(state)
    todo = [s for s in unit["rebuild"] if not scan_records[s].get("adjusted")]
    if todo:
        job.plan(todo)
        progress.start("attitude adjustment", len(todo))
        for s in todo:
            scan_records[s] = dict(job.build(s, [], attitudes.get(s, (0.0, 0.0, 0.0)),
                                             model=model, fitted=scan_records[s]))
            progress.advance(1, scan=s)
        progress.close()
    for k, s in enumerate(order):
        if scan_records[s].get("attitude"):
            scan_records[s]["attitude"] = dict(scan_records[s]["attitude"],
                                               adjusted_rpy_deg=list(model[1][k]))
    return {key: unit[key] for key in ("rms_before_m", "rms_m", "n_ties", "n_used", "rebuild")}
