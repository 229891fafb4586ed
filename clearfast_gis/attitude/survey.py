"""The survey-wide attitude adjustment as the chain runs it: fit every scan's attitude at once,
project again the scans it moves, then (when the platform drifted) tie neighbouring adjusted
scans, adjust again and project again; each adjustment recorded as a unit of the stage's run
state so that an interrupted run resumes where it stopped."""

from __future__ import annotations

from typing import Protocol

import numpy as np

from clearfast_gis.attitude.neighbours import neighbour_ties
from clearfast_gis.attitude.placement import (
    REFINE_MIN_SHARE,
    fit_survey_attitude,
    placement_attitude,
)
from clearfast_gis.attitude.ties import LinearTie
from clearfast_gis.progress import Progress

REFINED = "refined"
"""Part of the stage's run state that records the refined adjustment (ties between
neighbouring adjusted scans); the first adjustment is the stage's own unit (part ``""``)."""


class UnitStore(Protocol):
    """A stage's finished units (:class:`clearfast_gis.pipeline.state.StageState`)."""

    def done(self, part: str = "") -> dict | None: ...

    def finish(self, part: str, record: dict) -> None: ...


def stored_model(state: UnitStore) -> tuple[np.ndarray, np.ndarray] | None:
    """The adjusted attitude recorded in the run state (the refined one once it exists), if
    the adjustment ran.

    Scans that the refined adjustment left in place (it moves none of their frames by more
    than :data:`~clearfast_gis.attitude.placement.ADJUST_MIN_DEG`) keep the first
    adjustment's placement; the refined model describes them to within that bound.
    """
    unit = state.done(REFINED) or state.done()
    if unit is None:
        return None
    return np.array(unit["node_times_s"], dtype=float), np.array(unit["nodes_rpy_deg"],
                                                                   dtype=float)


def _rebuild(job, unit: dict, level: int, scan_records: dict[int, dict],
             attitudes: dict[int, tuple], progress: Progress) -> None:
    """Project again, with the unit's attitude, the scans it moves that are not yet placed
    with it (``adjusted`` below ``level``: 1 for the first adjustment, 2 for the refined)."""
    model = (np.array(unit["node_times_s"], dtype=float),
             np.array(unit["nodes_rpy_deg"], dtype=float))
    todo = [s for s in unit["rebuild"] if int(scan_records[s].get("adjusted") or 0) < level]
    if not todo:
        return
    progress.start("attitude adjustment" if level == 1 else "refined attitude adjustment",
                   len(todo))
    job.plan(todo)
    for s in todo:
        scan_records[s] = dict(job.build(s, [], attitudes.get(s, (0.0, 0.0, 0.0)),
                                         model=model, fitted=scan_records[s],
                                         adjusted=level))
        progress.advance(1, scan=s)
    progress.close()


def adjust_survey_attitude(job, state, order: list[int], scan_records: dict[int, dict],
                           attitudes: dict[int, tuple], progress: Progress,
                           refine: bool | None = None, reference_scan: int | None = None
                           ) -> dict:
    """Adjust the attitude of every scan at once and mosaic again the scans it moves; then
    (``refine``) tie every scan to its neighbours in time and to the reference scan on those
    mosaics (:func:`neighbour_ties`), adjust again and mosaic again the scans that this moves.

    Parameters
    ----------
    job : the pipeline's scan job (``frame_times``, ``build``, ``reference``)
    state : UnitStore
        The stage's run state (:class:`clearfast_gis.pipeline.state.StageState`): each
        adjustment is a unit of its own; re-projected scans are
        marked ``adjusted`` (1, or 2 after the refined adjustment) so an interrupted run
        resumes where it stopped.
    order : list of int
        Scans in time order.
    scan_records : dict
        Per-scan run-state records, updated in place.
    attitudes : dict
        Each scan's own fitted attitude, degrees (the prior).
    progress : Progress
    refine : bool or None
        Run the second, refined adjustment; None: when the first one re-projects at least
        :data:`~clearfast_gis.attitude.placement.REFINE_MIN_SHARE` of the scans.
    reference_scan : int, optional
        The scan the temporal mosaics are co-registered to (tied to every scan in the
        refined adjustment).

    Returns
    -------
    dict
        Summary for products.json: RMS of the ties before and after (metres), ties, inliers,
        the scans projected again; the same for the refined adjustment under ``refined``.
    """
    survey = job.ctx.survey
    times = {s: survey.frames.time_s[survey.scan_rows(s, 0)] for s in order}
    node_times = np.array([scan_records[s]["time_s"] for s in order], dtype=float)
    prior = np.array([attitudes.get(s, (0.0, 0.0, 0.0)) for s in order], dtype=float)
    unit = state.done()
    if unit is None:
        ties = [LinearTie.from_list(v) for s in order
                for v in (scan_records[s].get("ties") or [])]
        unit = fit_survey_attitude(ties, order, node_times, prior, times,
                    {s: placement_attitude(scan_records[s], None, times[s]) for s in order})
        state.finish("", unit)
    _rebuild(job, unit, 1, scan_records, attitudes, progress)
    final = unit
    if refine is None:
        refine = state.done(REFINED) is not None \
            or len(unit["rebuild"]) >= REFINE_MIN_SHARE * len(order)
    refined = state.done(REFINED) if refine else None
    if refine and refined is None:
        model = (node_times, np.array(unit["nodes_rpy_deg"], dtype=float))
        markers = [t for s in order for t in map(LinearTie.from_list,
                                                 scan_records[s].get("ties") or [])
                   if t.ref_scan is None]
        ties = markers + neighbour_ties(job, order, scan_records, model, progress=progress,
                                        reference_scan=reference_scan)
        refined = fit_survey_attitude(ties, order, node_times, prior, times,
                       {s: placement_attitude(scan_records[s], model, times[s])
                        for s in order})
        state.finish(REFINED, refined)
    if refined is not None:
        _rebuild(job, refined, 2, scan_records, attitudes, progress)
        final = refined
    nodes = np.array(final["nodes_rpy_deg"], dtype=float)
    for k, s in enumerate(order):
        if scan_records[s].get("attitude"):
            scan_records[s]["attitude"] = dict(scan_records[s]["attitude"],
                                               adjusted_rpy_deg=list(nodes[k]))
    keys = ("rms_before_m", "rms_m", "n_ties", "n_used", "rebuild")
    out = {key: unit[key] for key in keys}
    out["refined"] = None if refined is None else {key: refined[key] for key in keys}
    return out
