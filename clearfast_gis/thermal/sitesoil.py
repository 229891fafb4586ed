"""The site's soil for the inversion (diffusivity from the thermocouples; albedo, convective
scale, surface wetness and heat capacity from the shallowest thermocouple) and the
characterisation of each anomaly with the thermal model on it.

Why the shallowest thermocouple and not the mosaics' background: the mosaics hold *apparent*
temperature. A sandy soil's band emissivity is 0.84-0.96 (quartz reststrahlen at 8-9.5 um)
and it reflects the cold sky, so its apparent temperature is several kelvin below its kinetic
temperature, with another diurnal amplitude. Fitted to it, the surface terms of the 1-D model
(albedo, convective scale) settle far from the soil's (on the demo survey: albedo 0.55 and
``hc_scale`` 0.2, the bound, against 0.29 and 0.75 from the thermocouple); together with a
moist-sand heat capacity for a half-moist soil they put the buried mines about 1 cm too
shallow (BENCHMARKS.md, "Depth bias"). A thermocouple reads the kinetic temperature the model
computes.
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np

from clearfast_gis.detection.features import AnomalyFeatures
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.thermal.bodies import fit_bodies, other_bodies_needed
from clearfast_gis.thermal.canopy import cover_gain_sigma, seen_share, under_canopy
from clearfast_gis.thermal.error_budget import gain_sigma, with_chain_errors
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.thermal.inversion import Inversion, invert_anomaly
from clearfast_gis.thermal.materials import (
    MATERIALS,
    MINE_BODY_RHO_C_JM3K,
    MINE_FILL_LOG10_ALPHA,
    Soil,
    get_soil,
)
from clearfast_gis.thermal.measure import anomaly_measure
from clearfast_gis.thermal.soilfit import fit_soil_diffusivity, soil_log_field
from clearfast_gis.thermal.surface_fit import fit_surface_balance, fit_surface_parameters
from clearfast_gis.thermal.table import (
    DEFAULT_HEIGHT_M,
    OBJECT_RHO_C_JM3K,
    SiteTable,
    build_site_table,
)
from clearfast_gis.thermal.tables_ahead import TablesAhead
from clearfast_gis.units import ZERO_CELSIUS_K

SURFACE_SENSOR_MAX_DEPTH_M = 0.05
"""Deepest thermocouple that still constrains the surface terms, m."""

CHAIN_TABLE_CENTRE = "disc"
"""The chain measures each anomaly's contrast as the mean over its half-maximum footprint, so
its table holds the model's mean over the disc of that radius (not the axis value). On the
truth rasters (no sensor, no mosaic) of trial seed 0 this took the 1-4 cm mines' depth
MAE from 0.62 to 0.26 cm and their diffusivity from 1.61 to 1.20 times the truth; on the
mosaics from 0.42 to 0.31 cm and 1.65 to 1.38 (BENCHMARKS.md, "Depth bias")."""

MAX_SURFACE_SAMPLES = 64
"""Thermocouple samples used for the surface fit (evenly spread over the scans' period)."""


def soil_from_diffusivity(alpha_m2s: float) -> Soil:
    """A sand of diffusivity ``alpha_m2s`` (m2 s-1): heat capacity interpolated between the dry
    and moist sand end-members in proportion to the diffusivity (moisture raises both), and
    conductivity ``alpha * rho c``; optical terms of the nearer end-member.

    The thermocouples give the diffusivity only; the inversion needs the conductivity (the
    object's contrast depends on the conductivity ratio). A moist-sand ``rho c`` for a half-
    moist soil overstates its conductivity by 17 % and the object diffusivity by 60 %.
    """
    dry, moist = MATERIALS["dry_sand"], MATERIALS["moist_sand"]
    w = float(np.clip((alpha_m2s - dry.alpha_m2s) / (moist.alpha_m2s - dry.alpha_m2s), 0, 1))
    rho_c = dry.rho_c_jm3k + w * (moist.rho_c_jm3k - dry.rho_c_jm3k)
    base = get_soil("moist_sand" if w >= 0.5 else "dry_sand")
    return dataclasses.replace(base, k_wmk=alpha_m2s * rho_c, rho_c_jm3k=rho_c)


def site_soil(soil_log, forcing: Forcing, times_s: np.ndarray, background_c: np.ndarray,
              canopy: float = 0.0) -> tuple[Soil, float, float]:
    """The site's soil: diffusivity from the thermocouples; albedo, convective scale, surface
    wetness and heat capacity from the shallowest thermocouple (<= 5 cm,
    :func:`~clearfast_gis.thermal.surface_fit.fit_surface_balance`); without one, albedo and
    convective scale from the background's apparent temperature (a dry surface, the sand
    end-members' heat capacity).

    Parameters
    ----------
    soil_log : SoilLog or mapping
        ``time_s`` (T,), ``depth_m`` (D,), ``temp_c`` (T, D) degrees C.
    forcing : Forcing
    times_s : float (N,)
        Scan times, UTC epoch seconds.
    background_c : float (N,)
        Median apparent temperature of the background per scan, degrees C (the fallback).
    canopy : float
        Grass cover recorded for the site, 0-1: the soil is fitted under it
        (:func:`clearfast_gis.thermal.canopy.under_canopy`).

    Returns
    -------
    soil : Soil
    alpha_m2s, sigma_m2s : float
        Fitted soil diffusivity and its 1-sigma uncertainty.
    """
    alpha, sigma = fit_soil_diffusivity(soil_log)
    soil = soil_from_diffusivity(alpha)
    forcing = under_canopy(forcing, canopy)
    depths = soil_log_field(soil_log, "depth_m")
    shallow = int(np.argmin(depths))
    if depths[shallow] <= SURFACE_SENSOR_MAX_DEPTH_M:
        t = soil_log_field(soil_log, "time_s")
        temp = soil_log_field(soil_log, "temp_c")[:, shallow]
        sel = np.flatnonzero((t >= np.min(times_s)) & (t <= np.max(times_s)) & np.isfinite(temp))
        if sel.size >= 4:
            sel = sel[np.unique(np.linspace(0, sel.size - 1, MAX_SURFACE_SAMPLES).round()
                                .astype(int))]
            soil, _ = fit_surface_balance(soil, forcing, t[sel], temp[sel] + ZERO_CELSIUS_K,
                                          depth_m=float(depths[shallow]))
            return soil, alpha, sigma
    ok = np.isfinite(background_c)
    if ok.sum() >= 4:
        soil, _ = fit_surface_parameters(soil, forcing, times_s[ok],
                                         background_c[ok] + ZERO_CELSIUS_K)
    return soil, alpha, sigma


def first_band(series: np.ndarray) -> np.ndarray:
    """Band 0 of a per-scan series (N,) or (N, B)."""
    s = np.asarray(series, dtype=np.float64)
    return s[:, 0] if s.ndim == 2 else s


def radius_nodes(radii_m: np.ndarray, max_nodes: int = 3) -> np.ndarray:
    """A few object radii (m) spanning ``radii_m``, for one site table of several radii."""
    r = np.clip(np.asarray(radii_m, dtype=float), 0.02, 0.25)
    if r.size == 0:
        return np.array([0.05])
    return np.unique(np.round(np.quantile(r, np.linspace(0, 1, max_nodes)), 2))


def chain_site_table(soil_forcing: Forcing, soil: Soil, radius_m, times_s: np.ndarray,
                     canopy: float = 0.0, height_m: float = DEFAULT_HEIGHT_M,
                     object_rho_c_jm3k: float = OBJECT_RHO_C_JM3K) -> SiteTable:
    """The chain's site table: disc means (:data:`CHAIN_TABLE_CENTRE`) of objects in ``soil``
    under ``soil_forcing`` (the weather under the site's canopy,
    :func:`clearfast_gis.thermal.canopy.under_canopy`), their contrast as seen through a
    canopy of cover ``canopy`` (times ``1 - canopy``). ``radius_m`` float or (Q,) m;
    ``times_s`` (N,) UTC epoch s; ``height_m`` the objects' height, m;
    ``object_rho_c_jm3k`` the objects' volumetric heat capacity, J m-3 K-1."""
    table = build_site_table(soil_forcing, soil, radius_m, times_s, height_m=height_m,
                             centre=CHAIN_TABLE_CENTRE, object_rho_c_jm3k=object_rho_c_jm3k)
    if canopy > 0:
        seen = seen_share(canopy)
        table = dataclasses.replace(table, contrast_k=seen * table.contrast_k,
                                    over_k=seen * table.over_k)
    return table


def characterise(features: list[AnomalyFeatures], times_s: np.ndarray, forcing: Forcing,
                 soil, progress: Progress = NULL_PROGRESS, canopy: float = 0.0,
                 gain: np.ndarray | None = None, blur_m: np.ndarray | None = None
                 ) -> dict[int, Inversion]:
    """Depth and diffusivity of each anomaly with the thermal model.

    Each anomaly is modelled as the expected mine type nearest its footprint's size, its
    contrast taken as the chain measured it: the mean over its half-maximum footprint minus
    the mean over its background ring (:func:`clearfast_gis.thermal.measure.anomaly_measure`),
    through the mosaics' blur, times the apparent contrast's gain (one site table per mine
    type).

    Parameters
    ----------
    features : list of AnomalyFeatures
        With ``centre_k`` and ``ring_k`` series in degrees C (mosaic units).
    times_s : float64 (N,)
        Scan times.
    forcing : Forcing
    soil : Soil
        The site's fitted soil.
    canopy : float
        Grass cover recorded for the site, 0-1: the objects lie under it and their contrast
        is seen times ``1 - canopy`` (:mod:`clearfast_gis.thermal.canopy`), a gain uncertain
        by :func:`~clearfast_gis.thermal.canopy.cover_gain_sigma` (in the sigmas).
    gain : float (N,), optional
        Per-scan factor from the kinetic to the apparent contrast
        (:func:`clearfast_gis.thermal.apparent.apparent_gain`); 1 when omitted.
    blur_m : float (K,), optional
        Gaussian sigma of the mosaics' blur at each feature, m
        (:func:`clearfast_gis.mosaic.blur.survey_blur_sigma_m`); 0 when omitted.

    Returns
    -------
    dict[int, Inversion]
        With the chain's error terms in the sigmas
        (:func:`clearfast_gis.thermal.error_budget.with_chain_errors`). Anomalies seen in
        fewer than 4 scans (with their background ring) are left out: their status is
        ``not_characterised``.
    """
    if not features:
        return {}
    measures = [anomaly_measure(f) for f in features]
    blur = np.zeros(len(features)) if blur_m is None else np.asarray(blur_m, dtype=float)
    forcing = under_canopy(forcing, canopy)
    shapes: dict = {kind: (kind.radius_m, kind.height_m) for kind in
                    sorted({m.kind for m in measures if m.kind is not None},
                           key=lambda k: k.diameter_m)}
    others = [m.radius_m for m in measures if m.kind is None and m.radius_m > 0]
    if others:  # footprints of no mine type's size: cylinders of the footprint's radius
        nodes = radius_nodes(np.array(others))
        shapes[None] = (nodes if nodes.size > 1 else float(nodes[0]), DEFAULT_HEIGHT_M)
        lo, hi = float(nodes.min()), float(nodes.max())
        measures = [m if m.kind is not None else
                    dataclasses.replace(m, radius_m=float(np.clip(m.radius_m, lo, hi)))
                    for m in measures]

    def build(key: tuple) -> SiteTable:
        """The site table of a mine type's shape (``key[0]``) and body (``key[1]``)."""
        kind, body = key
        radius, height = shapes[kind]
        return chain_site_table(forcing, soil, radius, times_s, canopy, height,
                                MINE_BODY_RHO_C_JM3K[body])

    def ask(key: tuple) -> None:
        """Ask for a table ahead, saying which."""
        kind, body = key
        if tables.ahead(key):
            radius = shapes[kind][0]
            name = (f"{kind.name} ({kind.diameter_m:.3f} m)" if kind is not None else
                    "radii " + ", ".join(f"{r:.2f}" for r in np.atleast_1d(radius)) + " m")
            progress.message(f"thermal model table for {name}, body "
                             f"{MINE_BODY_RHO_C_JM3K[body] / 1e6:.2f} MJ/m3/K")

    extra = cover_gain_sigma(canopy)
    middle = len(MINE_BODY_RHO_C_JM3K) // 2
    fits: dict[int, tuple] = {}  # anomaly id -> (fit function, mine type)
    firsts: dict[int, Inversion] = {}  # anomaly id -> its fit with the middle body
    out: dict[int, Inversion] = {}
    with TablesAhead(build) as tables:
        for f, m, b in zip(features, measures, blur, strict=True):
            centre = first_band(f.centre_k) + ZERO_CELSIUS_K
            ring = first_band(f.ring_k) + ZERO_CELSIUS_K
            if (np.isfinite(centre) & np.isfinite(ring)).sum() >= 4 and m.over_m > 0:
                fits[f.id] = (functools.partial(
                    invert_anomaly, times_s, centre, ring, forcing, soil, m.radius_m,
                    over_m=m.over_m, ring_m=m.ring_m,
                    blur_m=float(b) if np.isfinite(b) else 0.0, gain=gain,
                    gain_sigma=gain_sigma(extra), alpha_prior=MINE_FILL_LOG10_ALPHA),
                    m.kind)
        kinds = list(dict.fromkeys(kind for _fit, kind in fits.values()))
        for kind in kinds:
            ask((kind, middle))
        # every curve with the middle body first, a mine type at a time (the next types'
        # tables are built meanwhile, and the other bodies' tables of a type from its first
        # curve that needs them); the results do not depend on this order
        progress.start("characterise", len(features))
        for fid in sorted(fits, key=lambda k: kinds.index(fits[k][1])):
            fit, kind = fits[fid]
            firsts[fid] = fit(table=tables.get((kind, middle)))
            if other_bodies_needed(firsts[fid]):
                for body in range(len(MINE_BODY_RHO_C_JM3K)):
                    ask((kind, body))  # the middle one was asked for already
            progress.advance()
        progress.advance(len(features) - len(fits))
        progress.close()
        # then each curve over the bodies (thermal.bodies; the middle body's fit reused)
        progress.start("characterise, other bodies", len(fits))
        for fid, (fit, kind) in fits.items():
            first = firsts[fid]
            inv = fit_bodies(lambda i, fit=fit, kind=kind, first=first: first if i == middle
                             else fit(table=tables.get((kind, i))),
                             MINE_BODY_RHO_C_JM3K, MINE_FILL_LOG10_ALPHA, gain_sigma(extra))
            out[fid] = with_chain_errors(inv, extra)
            progress.advance()
    progress.close()
    return out
