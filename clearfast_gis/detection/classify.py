"""Class cue and confidence of an anomaly from size, shape, temporal behaviour and diffusivity.

Rules (documented in docs/detection.md):

1. clutter when any clutter cue holds: circularity < 0.5 (irregular outline); summary polarity
   'mixed' over several supporting scans (inconsistent thermal behaviour) unless the contrast
   curve follows the day's modelled mine curve (``mine_curve_r`` at least ``MINE_CURVE_R``:
   a mine is warm by day and cool at night, and a weak one is supported by a day scan or two
   and the cool morning scan; such an anomaly is ``unknown``); a characterised
   diffusivity like stone or metal (``clearfast_gis.thermal.cue.material_cue`` says stone or metal).
   An anomaly cool around midday is clutter too (stones and low-emissivity metal are cool by
   day; an explosive-filled object, a worse conductor than the soil, is warm by day), and so
   is one whose contrast curve runs against the modelled mine's (``mine_curve_r`` below
   ``CLUTTER_CURVE_R``, :mod:`clearfast_gis.detection.curve`): a stone on a soil that
   stores heat is warm at every scan through its emissivity, but least warm at midday.
   A curve correlated less than ``MINE_CURVE_R`` (0.5) with the modelled mine's is not cued
   as a mine (``unknown``), nor is one whose curve follows the mine's shape but sits above it
   by more than ``MAX_MINE_CURVE_LEVEL`` of its swing (``mine_curve_level``, warm at night
   when a mine is cool: the bare-soil edge of a grass patch).
   Anomalies scoring below ``MIN_MINE_SCORE`` (2) are ``unknown``: too weak to cue.
2. otherwise, by the equivalent diameter: at_mine for 0.25-0.45 m (e.g. M6A2, 33.7 cm), ap_mine
   for 0.06-0.16 m (e.g. M2A4, 10.4 cm); unknown outside both ranges or without a metric size.

The confidence (0-1) is the product of a detection term ``1 - exp(-score / 3)``, a shape term
(circularity), a temporal term (1.0 for 'warm_day_cool_night', 0.8 for 'warm'/'cool', 0.5 for
'mixed'/'none'; 0.8 when N = 1) and a diffusivity term (1.0 when a characterised diffusivity
is mine-like, alpha <= 4e-7 m2/s; 0.7 for soil-like 4e-7 to 1e-6; 0.4 for stone/metal; 0.8
without a characterised inversion). For the clutter class the same product is the confidence
that the anomaly is *not* a mine: ``1 - product``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from clearfast_gis.detection.features import AnomalyFeatures

__all__ = ["AT_DIAMETER_M", "AP_DIAMETER_M", "CLASSES", "CLUTTER_CURVE_R", "MAX_MINE_CURVE_LEVEL",
           "MIN_MINE_SCORE", "MINE_CURVE_R", "classify", "diffusivity_cue"]

CLASSES = ("at_mine", "ap_mine", "clutter", "unknown")
AT_DIAMETER_M = (0.25, 0.45)
AP_DIAMETER_M = (0.06, 0.16)
MINE_ALPHA_MAX = 4e-7
STONE_ALPHA_MIN = 1e-6


def diffusivity_cue(alpha_m2s: float) -> str:
    """'mine' (explosive/plastic, alpha <= 4e-7 m2/s), 'soil' or 'stone_metal' (>= 1e-6)."""
    if alpha_m2s <= MINE_ALPHA_MAX:
        return "mine"
    if alpha_m2s < STONE_ALPHA_MIN:
        return "soil"
    return "stone_metal"


def _inversion_alpha(inversion) -> float | None:
    """The characterised diffusivity of an inversion result (object or mapping), else None.

    Accepted fields: ``diffusivity_m2s`` (or ``alpha_m2s``) and an optional ``characterised``
    flag (False means the fit did not determine the parameters).
    """
    if inversion is None:
        return None

    def get(name):
        if isinstance(inversion, Mapping):
            return inversion.get(name)
        return getattr(inversion, name, None)

    if get("characterised") is False:
        return None
    alpha = get("diffusivity_m2s")
    if alpha is None:
        alpha = get("alpha_m2s")
    if alpha is None or not math.isfinite(float(alpha)) or float(alpha) <= 0:
        return None
    return float(alpha)


_CUE_CLASS = {"explosive": "mine", "soil": "soil", "stone": "stone_metal", "metal": "stone_metal"}


def _material(alpha: float, inversion) -> str:
    """Material cue of a diffusivity: ``clearfast_gis.thermal.cue.material_cue`` (with the
    inversion's ``diffusivity_sigma_m2s`` when given) mapped to mine / soil / stone_metal;
    the thresholds of :func:`diffusivity_cue` when the thermal package is not available."""
    try:
        from clearfast_gis.thermal.cue import material_cue
    except ImportError:
        return diffusivity_cue(alpha)
    if isinstance(inversion, Mapping):
        sigma = inversion.get("diffusivity_sigma_m2s")
    else:
        sigma = getattr(inversion, "diffusivity_sigma_m2s", None)
    best = material_cue(alpha, float("nan") if sigma is None else float(sigma))["best"]
    return _CUE_CLASS.get(best, diffusivity_cue(alpha))


MIN_MINE_SCORE = 2.0
"""Below this detection score an anomaly is too weak to be cued as a mine (``unknown``)."""

CLUTTER_CURVE_R = 0.0
"""A contrast curve correlated below this with every modelled mine curve of the day
(:func:`clearfast_gis.detection.curve.mine_curve_match`) runs against a mine's: clutter."""

MINE_CURVE_R = 0.5
"""A mine cue needs at least this correlation: the mines at 0-5 cm of the demo's clear, clay
and tropical surveys of seeds 10-11 gave 0.92-1.00, stones -0.77 to -0.50 (docs/detection.md);
below it the curve says nothing of a mine (``unknown``)."""


MAX_MINE_CURVE_LEVEL = 0.5
"""A mine cue needs its contrast curve to sit at most this far above the best-matching
modelled mine curve, in swings of that curve (:func:`clearfast_gis.detection.curve.
mine_curve_level`; docs/detection.md gives the measured ranges)."""


def classify(features: AnomalyFeatures, inversion=None, contrast_day_k: float | None = None,
             min_score: float = MIN_MINE_SCORE, mine_curve_r: float | None = None,
             mine_curve_level: float | None = None) -> tuple[str, float]:
    """Class cue and confidence of one anomaly.

    Parameters
    ----------
    features : AnomalyFeatures
        From :func:`clearfast_gis.detection.blob_features` (needs ``diameter_m`` for the mine
        classes).
    inversion : mapping or object, optional
        Thermal inversion of the anomaly with ``diffusivity_m2s`` (m2/s) and optionally
        ``characterised`` (bool).
    contrast_day_k : float, optional
        Contrast around midday (centre minus background), K. An explosive-filled object
        conducts heat worse than the soil and shows warm by day; an object cool by day
        (a stone, or metal and other low-emissivity debris) is clutter.
    min_score : float
        Anomalies scoring lower are ``unknown`` (too weak to cue as a mine).
    mine_curve_r : float, optional
        Correlation of the anomaly's contrast curve with the day's modelled mine curves
        (-1 to 1, :func:`clearfast_gis.detection.curve.mine_curve_match`); below
        :data:`CLUTTER_CURVE_R` the anomaly is clutter, below :data:`MINE_CURVE_R` it is
        not cued as a mine.
    mine_curve_level : float, optional
        Offset of the contrast curve from the best-matching modelled mine curve, in swings
        of that curve (:func:`clearfast_gis.detection.curve.mine_curve_level`); above
        :data:`MAX_MINE_CURVE_LEVEL` (warm at every scan, where a mine is cool at night) the
        anomaly is not cued as a mine.

    Returns
    -------
    (class_cue, confidence) : (str, float)
        class_cue in ``CLASSES``; confidence in [0, 1].
    """
    alpha = _inversion_alpha(inversion)
    material = None if alpha is None else _material(alpha, inversion)
    n_total = len(features.polarity_per_scan)
    irregular = features.circularity < 0.5
    # warm in some scans and cool in others is what a mine does when its curve follows the
    # day's modelled mine curve (a weak mine misses the day or the night scans' support):
    # then not clutter, but not a mine cue either (``unknown``)
    follows = mine_curve_r is not None and math.isfinite(mine_curve_r) \
        and mine_curve_r >= MINE_CURVE_R
    mixed = features.polarity == "mixed" and features.n_scans >= 3
    inconsistent = mixed and not follows
    hard = material == "stone_metal"

    detect_term = 1.0 - math.exp(-max(features.score, 0.0) / 3.0)
    shape_term = max(0.0, min(1.0, features.circularity))
    if n_total <= 1:
        time_term = 0.8
    else:
        time_term = {"warm_day_cool_night": 1.0, "warm": 0.8, "cool": 0.8}.get(
            features.polarity, 0.5)
    diff_term = {"mine": 1.0, "soil": 0.7, "stone_metal": 0.4, None: 0.8}[material]
    product = detect_term * shape_term * time_term * diff_term

    cool_by_day = contrast_day_k is not None and math.isfinite(contrast_day_k) \
        and contrast_day_k < 0.0
    against = mine_curve_r is not None and math.isfinite(mine_curve_r) \
        and mine_curve_r < CLUTTER_CURVE_R
    if (irregular or inconsistent or hard or cool_by_day or against) \
            and features.score >= min_score:
        return "clutter", round(1.0 - product, 4)
    unlike = mine_curve_r is not None and math.isfinite(mine_curve_r) \
        and mine_curve_r < MINE_CURVE_R
    unlike = unlike or mixed or (mine_curve_level is not None
                                 and math.isfinite(mine_curve_level)
                                 and mine_curve_level > MAX_MINE_CURVE_LEVEL)
    if features.score < min_score or irregular or inconsistent or hard or unlike:
        return "unknown", round(product, 4)
    d = features.diameter_m
    if math.isfinite(d) and AT_DIAMETER_M[0] <= d <= AT_DIAMETER_M[1]:
        return "at_mine", round(product, 4)
    if math.isfinite(d) and AP_DIAMETER_M[0] <= d <= AP_DIAMETER_M[1]:
        return "ap_mine", round(product, 4)
    return "unknown", round(product, 4)
