"""The detected and characterised anomalies of a survey (:class:`AnomalySet`, what the
products writers take) and the attribute records of the ``suspects`` layer
(``schemas/anomaly.schema.json``)."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from clearfast_gis.detection import classify
from clearfast_gis.detection.curve import match_curves, mine_curve_level, mine_curve_match
from clearfast_gis.detection.features import AnomalyFeatures, found_by
from clearfast_gis.detection.markers import MarkerMatch
from clearfast_gis.solar import mean_solar_hour
from clearfast_gis.thermal import Inversion
from clearfast_gis.thermal.daycontrast import DayContrast
from clearfast_gis.thermal.sitesoil import first_band
from clearfast_gis.timeutil import format_utc


@dataclass
class AnomalySet:
    """Detected anomalies of a survey.

    Attributes
    ----------
    labels : int32 (H, W)
        Anomaly label per mosaic cell (0 = background), ids matching ``features``.
    features : list of AnomalyFeatures
        Highest score first, at most ``max_anomalies``.
    inversions : dict[int, Inversion]
        Thermal characterisation per anomaly id (missing when not attempted).
    soil_alpha_m2s, soil_alpha_sigma_m2s : float
        Soil diffusivity from the thermocouples.
    notes : list of str
        What the characterisation had to skip, and why.
    markers : list of MarkerMatch
        Known markers found among the anomalies (removed from ``features``).
    day : DayContrast or None
        How much contrast the day gave (the thermal model of the logs), when characterised.
    """

    labels: np.ndarray
    features: list[AnomalyFeatures]
    inversions: dict[int, Inversion]
    soil_alpha_m2s: float = math.nan
    soil_alpha_sigma_m2s: float = math.nan
    notes: list[str] = dataclasses.field(default_factory=list)
    markers: list[MarkerMatch] = dataclasses.field(default_factory=list)
    day: DayContrast | None = None


def _day_night_contrast(times_s: np.ndarray, contrast: np.ndarray, longitude_deg: float
                        ) -> tuple[float, float]:
    # Mean solar time and the 10-16 h / 22-05 h windows (both ends included): the largest
    # contrast of the hottest and the coldest part of the day, as the records always gave.
    hour = mean_solar_hour(times_s, longitude_deg)
    day = (hour >= 10) & (hour <= 16)
    night = (hour >= 22) | (hour <= 5)
    c = first_band(contrast)

    def pick(sel):
        v = c[sel & np.isfinite(c)]
        return float(v[np.argmax(np.abs(v))]) if v.size else math.nan

    return pick(day), pick(night)


def _daytime_sign(behaviour: str, contrast_day_k: float, contrast_k: np.ndarray) -> str:
    """``hot``/``cold``: the sign of the daytime contrast (schemas/anomaly.schema.json)."""
    if behaviour in ("warm_day_cool_night", "warm"):
        return "hot"
    if behaviour == "cool":
        return "cold"
    if math.isfinite(contrast_day_k):
        return "hot" if contrast_day_k >= 0 else "cold"
    series = first_band(contrast_k)
    mean = float(np.nanmean(series)) if np.isfinite(series).any() else 0
    return "hot" if mean >= 0 else "cold"


def suspect_records(anomalies: AnomalySet, times_s: np.ndarray, longitude_deg: float,
                    fix_quality: int | None, survey_code: str) -> list[dict]:
    """Attribute records of the ``suspects`` layer (schemas/anomaly.schema.json)."""
    from clearfast_gis.report.html import figure_name

    records = []
    day_model = anomalies.day
    curves = None if day_model is None or day_model.curves_k is None \
        else match_curves(day_model.depths_m, day_model.curves_k)
    for f in anomalies.features:
        inv = anomalies.inversions.get(f.id)
        aid = f"{survey_code}-{f.id:04d}"
        day, night = _day_night_contrast(times_s, f.contrast_k, longitude_deg)
        series = first_band(f.contrast_k)
        match = math.nan if curves is None else mine_curve_match(series, curves)
        level = math.nan if curves is None else mine_curve_level(series, curves)
        cue, conf = classify(f, inv, contrast_day_k=day, mine_curve_r=match,
                             mine_curve_level=level)
        rec = {
            "anomaly_id": aid, "x": float(f.x), "y": float(f.y),
            "area_m2": float(f.area_m2), "diameter_m": float(f.diameter_m),
            "circularity": float(f.circularity),
            "depth_m": inv.depth_m if inv else None,
            "depth_sigma_m": inv.depth_sigma_m if inv else None,
            "diffusivity_m2s": inv.diffusivity_m2s if inv else None,
            "diffusivity_sigma_m2s": inv.diffusivity_sigma_m2s if inv else None,
            "status": inv.status if inv else "not_characterised",
            "fit_status": (inv.fit_status or inv.status) if inv else "not_characterised",
            "polarity": _daytime_sign(f.polarity, day, f.contrast_k),
            "found_by": found_by(f),
            "diurnal_behaviour": f.polarity, "class_cue": cue, "cue_confidence": float(conf),
            "n_scans": int(f.n_scans), "contrast_day_k": day, "contrast_night_k": night,
            "mine_curve_r": round(match, 3) if math.isfinite(match) else None,
            "mine_curve_level": round(level, 3) if math.isfinite(level) else None,
            "fix_quality": fix_quality, "figure": figure_name(aid),
            "contrast_series": {"time_utc": [format_utc(t) for t in times_s],
                                "contrast_k": [float(v) for v in first_band(f.contrast_k)]},
            "score": float(f.score),
        }
        records.append(rec)
    return records
