"""Mine likelihood ``p_mine`` of a suspect and the planner's ``priority`` order.

The model (docs/likelihood.md) is a logistic regression on features of the suspect record:

============  ==========================================================================
feature       definition
============  ==========================================================================
strength      ``log10(max(score, 0.1))``: the detection score (contrast-to-noise ratio
              times shape and size terms, docs/detection.md)
size_misfit   ``min_k |ln(diameter_m / D_k)|`` over the survey's mine types ``D_k``
              (:data:`MINE_TYPE_DIAMETERS_M`): 0 for a footprint the size of a mine type
circularity   0-1 (docs/detection.md)
diurnal       1 for ``warm_day_cool_night`` (an explosive's signature), else 0
cool_by_day   1 when the daytime contrast is negative (stones, metal), else 0
characterised 1 when the inversion's fit status is ``ok`` (``fit_status``: the curve is
              explained by a buried object on the fit's own and the propagated chain
              terms; a depth flagged only because a gain error moves it onto another
              branch still counts), else 0; ``status`` when the record has no
              ``fit_status``
curve_match   ``mine_curve_r``: correlation of the contrast curve with the day's modelled
              mine curve (:mod:`clearfast_gis.detection.curve`), -1 to 1; 0 when unknown
curve_offset  ``min(|mine_curve_level|, 2)``: how far the curve sits off the modelled mine
              curve, in swings of that curve (0 for a mine; about 1 for the bare edge of a
              grass patch, warm at night); 0 when unknown
stack_core    1 for a deep core (``found_by`` ``stack``): found only by the matched filter
              over the day's stack (docs/detection.md), a disc laid at the score's peak, so
              its circularity (1) is not measured; soil texture that follows a buried
              object's curve gives such cores too, and only a depth profile that explains
              the curve (``characterised``) tells a deep mine from it
============  ==========================================================================

The object's diffusivity is not a feature (it was, as ``alpha_misfit``, in ``logistic-2``):
on dry soils the inversion puts TNT-filled mines at 2.8-4.4e-7 m2/s instead of 1e-7 (demo
tropics and southern winter, seeds 10-11), and the fit over those days gave the misfit a
weight of the wrong sign. Diffusivity stays a clutter cue of the class cue (stone, metal).

The share of scans that support a detection is not a feature: on the 6-scan demo surveys the
model was first fitted on, nearly every detection is seen in 5 or 6 scans and the fit gave it
a negative weight that the physics does not; on a 48-scan survey under a drifting lift clutter
is seen in 10-30 % of the scans, far outside that range, and the weight put stones at
p_mine 0.97 (trial seed 1). The screening's scan rule (a single scan) is what remains of it.

``p_mine = 1 / (1 + exp(-(b0 + sum_i b_i (x_i - mean_i) / scale_i)))``. The coefficients, the
feature means and scales, the surveys the model was fitted on and its reliability table are
data (``clearfast_gis/data/likelihood.json``), written by ``benchmarks/calibrate_likelihood.py``
from simulated surveys that are never the ones it is scored on. Nothing is fitted at run time.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from functools import lru_cache
from importlib import resources

import numpy as np

from clearfast_gis.detection.features import FOUND_BY_STACK
from clearfast_gis.minetypes import MINE_TYPES

FEATURES = ("strength", "size_misfit", "circularity", "diurnal", "cool_by_day",
            "characterised", "curve_match", "curve_offset", "stack_core")
"""Model features, in the order of the coefficients."""

MINE_TYPE_DIAMETERS_M = {t.name: t.diameter_m for t in MINE_TYPES}
"""Diameters of the mine types expected on the surveys
(:data:`~clearfast_gis.minetypes.MINE_TYPES`), m."""

MAX_CURVE_OFFSET = 2.0
"""``curve_offset`` is capped here (swings of the modelled mine curve): farther off says no
more."""

PARAMETERS = "likelihood.json"
"""The fitted model's file in ``clearfast_gis/data``."""


def features(record: Mapping) -> np.ndarray:
    """Feature vector (len(FEATURES),) of one suspect record (module notes for units)."""
    score = float(record.get("score") or 0.0)
    d = record.get("diameter_m")
    d = math.nan if d is None else float(d)
    size = (min(abs(math.log(d / dk)) for dk in MINE_TYPE_DIAMETERS_M.values())
            if math.isfinite(d) and d > 0 else 3.0)
    circ = float(record.get("circularity") or 0.0)
    diurnal = 1.0 if record.get("diurnal_behaviour") == "warm_day_cool_night" else 0.0
    day = record.get("contrast_day_k")
    cool = 1.0 if day is not None and math.isfinite(float(day)) and float(day) < 0 else 0.0
    ok = (record.get("fit_status") or record.get("status")) == "ok"
    match = record.get("mine_curve_r")
    match = float(match) if match is not None and math.isfinite(float(match)) else 0.0
    level = record.get("mine_curve_level")
    offset = min(abs(float(level)), MAX_CURVE_OFFSET) \
        if level is not None and math.isfinite(float(level)) else 0.0
    core = 1.0 if record.get("found_by") == FOUND_BY_STACK else 0.0
    return np.array([math.log10(max(score, 0.1)), min(size, 3.0), circ, diurnal, cool,
                     1.0 if ok else 0.0, match, offset, core])


@lru_cache(maxsize=1)
def load_model() -> dict:
    """The fitted model (``clearfast_gis/data/likelihood.json``)."""
    text = resources.files("clearfast_gis").joinpath("data", PARAMETERS).read_text()
    model = json.loads(text)
    if tuple(model["features"]) != FEATURES:
        raise ValueError(f"{PARAMETERS}: features {model['features']} are not {FEATURES}")
    return model


def p_mine_from_features(x: np.ndarray, model: Mapping) -> np.ndarray:
    """``p_mine`` of feature rows ``x`` (M, len(FEATURES)) under ``model``, (M,) in 0-1."""
    x = np.atleast_2d(np.asarray(x, dtype=float))
    z = (x - np.asarray(model["mean"])) / np.asarray(model["scale"])
    eta = float(model["intercept"]) + z @ np.asarray(model["coef"])
    return 1.0 / (1.0 + np.exp(-eta))


def rank(records: list[dict], model: Mapping | None = None) -> list[dict]:
    """The records with ``p_mine`` (0-1, 3 decimals) and ``priority`` (1 = first), sorted by
    priority: decreasing ``p_mine``, ties by decreasing score, then by ``anomaly_id``."""
    if not records:
        return []
    model = load_model() if model is None else model
    x = np.array([features(r) for r in records])
    p = p_mine_from_features(x, model)
    out = [{**r, "p_mine": round(float(pi), 3)} for r, pi in zip(records, p, strict=True)]
    out.sort(key=lambda r: (-r["p_mine"], -float(r.get("score") or 0.0), str(r["anomaly_id"])))
    for i, r in enumerate(out, start=1):
        r["priority"] = i
    return out


def screen_and_rank(records: list[dict], n_scans_total: int,
                    model: Mapping | None = None) -> list[dict]:
    """Every detection record, in the input order, with ``set_aside_reason`` (candidates,
    :mod:`clearfast_gis.detection.screening`) or ``p_mine`` and ``priority`` (suspects); the
    fields a record does not get are None."""
    from clearfast_gis.detection.screening import screen

    suspects, candidates = screen(records, n_scans_total)
    ranked = {r["anomaly_id"]: r for r in rank(suspects, model)}
    aside = {r["anomaly_id"]: r for r in candidates}
    out = []
    for r in records:
        aid = r["anomaly_id"]
        if aid in ranked:
            out.append({**ranked[aid], "set_aside_reason": None})
        else:
            out.append({**aside[aid], "p_mine": None, "priority": None})
    return out


def likelihood_model_id() -> str:
    """Short description of the fitted model (``products.json``): its version and the surveys
    it was fitted on."""
    m = load_model()
    return f"{m['version']} (fitted on {', '.join(m['fitted_on'])})"
