"""The site's soil (diffusivity from the thermocouples, surface terms from the background
pixels) and the characterisation of each anomaly with the thermal model on it."""

from __future__ import annotations

import dataclasses

import numpy as np

from clearfast_gis.detection.features import AnomalyFeatures
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.thermal import (
    Inversion,
    build_site_table,
    fit_soil_diffusivity,
    fit_surface_parameters,
    get_soil,
    invert_anomaly,
)
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.units import ZERO_CELSIUS_K


def first_band(series: np.ndarray) -> np.ndarray:
    """Band 0 of a per-scan series (N,) or (N, B)."""
    s = np.asarray(series, dtype=np.float64)
    return s[:, 0] if s.ndim == 2 else s


def site_soil(soil_log, forcing: Forcing, times_s: np.ndarray, background_c: np.ndarray):
    """The site's soil: diffusivity from the thermocouples, surface terms from the background.

    Returns
    -------
    soil : Soil
    alpha_m2s, sigma_m2s : float
        Fitted soil diffusivity and its 1-sigma uncertainty.
    """
    alpha, sigma = fit_soil_diffusivity(soil_log)
    base = get_soil("moist_sand" if alpha > 4e-7 else "dry_sand")
    soil = dataclasses.replace(base, k_wmk=alpha * base.rho_c_jm3k)
    ok = np.isfinite(background_c)
    if ok.sum() >= 4:
        soil, _ = fit_surface_parameters(soil, forcing, times_s[ok],
                                         background_c[ok] + ZERO_CELSIUS_K)
    return soil, alpha, sigma


def radius_nodes(radii_m: np.ndarray, max_nodes: int = 3) -> np.ndarray:
    """A few object radii (m) spanning the anomalies', for the site table."""
    r = np.clip(np.asarray(radii_m, dtype=float), 0.02, 0.25)
    if r.size == 0:
        return np.array([0.05])
    q = np.unique(np.round(np.quantile(r, np.linspace(0, 1, max_nodes)), 2))
    return q


def characterise(features: list[AnomalyFeatures], times_s: np.ndarray, forcing: Forcing,
                 soil, progress: Progress = NULL_PROGRESS) -> dict[int, Inversion]:
    """Depth and diffusivity of each anomaly with the thermal model (one site table).

    Parameters
    ----------
    features : list of AnomalyFeatures
        With ``centre_k`` and ``ring_k`` series in degrees C (mosaic units).
    times_s : float64 (N,)
        Scan times.
    forcing : Forcing
    soil : Soil
        The site's fitted soil.

    Returns
    -------
    dict[int, Inversion]
        Anomalies seen in fewer than 4 scans (with their background ring) are left out: their
        status is ``not_characterised``.
    """
    if not features:
        return {}
    radii = np.array([0.5 * f.diameter_m for f in features])
    nodes = radius_nodes(radii)
    progress.message(f"thermal model table for radii {', '.join(f'{r:.2f}' for r in nodes)} m")
    table = build_site_table(forcing, soil, nodes if nodes.size > 1 else float(nodes[0]),
                             times_s)
    out: dict[int, Inversion] = {}
    progress.start("characterise", len(features))
    for f, r in zip(features, radii, strict=True):
        centre = first_band(f.centre_k) + ZERO_CELSIUS_K
        ring = first_band(f.ring_k) + ZERO_CELSIUS_K
        r_tab = float(np.clip(r, nodes.min(), nodes.max()))
        if (np.isfinite(centre) & np.isfinite(ring)).sum() >= 4:
            out[f.id] = invert_anomaly(times_s, centre, ring, forcing, soil, r_tab, table=table)
        progress.advance()
    progress.close()
    return out
