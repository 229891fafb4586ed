"""Depth error of the chain's site soil alone, one cause at a time (issue #22).

For a simulated survey, the disc-mean surface contrast of an AP mine (TNT, 10.4 cm x 8 cm) at
0-5 cm is computed in the twin's own soil (``truth/scenario.json``: soil type, moisture,
grass cover; the canopy's forcing and its share of the seen contrast) under the logged
weather, at the survey's scan times; no sensor, mosaic or detector. It is then inverted with
the site soil the chain builds from the survey's logs in several ways:

- ``dry fit``: albedo and convective scale fitted to the shallowest thermocouple, no latent
  heat, heat capacity of the sand end-members (the chain before the balance fit);
- ``dry, true heat capacity``: the same with the twin's heat capacity;
- ``true water, sand heat capacity``: the twin's surface water, the chain's heat capacity,
  albedo and convective scale refitted;
- ``balance fit, bare ground``: the chain's (:func:`clearfast_gis.thermal.sitesoil.site_soil`)
  without the grass cover the survey records;
- ``balance fit``: the chain's, under the cover ``survey.json`` records
  (``site.vegetation_cover``; the same as the line before on bare ground);
- ``twin's soil, refitted``: the twin's soil with albedo and convective scale refitted.

Prints the depth error (cm) per depth and the mean absolute error at 0-4 cm.

    python benchmarks/site_soil_error.py SURVEY [SURVEY ...]
"""

from __future__ import annotations

import argparse
import json
from dataclasses import replace
from pathlib import Path

import numpy as np
from depth_bias import survey_inputs

from clearfast_gis.simulate import parse_scenario, preset
from clearfast_gis.simulate.surface import ground_of
from clearfast_gis.thermal import build_site_table, fit_surface_parameters, invert_anomaly
from clearfast_gis.thermal.canopy import under_canopy
from clearfast_gis.thermal.sitesoil import chain_site_table, site_soil, soil_from_diffusivity
from clearfast_gis.thermal.soilfit import fit_soil_diffusivity, soil_log_field
from clearfast_gis.units import ZERO_CELSIUS_K

RADIUS_M, HEIGHT_M = 0.052, 0.08
DEPTHS_M = (0.0, 0.01, 0.02, 0.03, 0.04, 0.05)
TNT_LOG10_ALPHA = -7.0


def refit(soil, log, forcing, times):
    """``soil`` with albedo and convective scale fitted to the shallowest thermocouple."""
    t, depth = soil_log_field(log, "time_s"), soil_log_field(log, "depth_m")
    temp = soil_log_field(log, "temp_c")[:, 0]
    sel = np.flatnonzero((t >= times.min()) & (t <= times.max()) & np.isfinite(temp))
    sel = sel[np.unique(np.linspace(0, sel.size - 1, 64).round().astype(int))]
    return fit_surface_parameters(soil, forcing, t[sel], temp[sel] + ZERO_CELSIUS_K,
                                  depth_m=float(depth[0]))[0]


def true_curves(forcing, ground, times) -> np.ndarray:
    """Seen disc-mean contrast (D, S) K of the TNT AP mine at DEPTHS_M in the twin's soil."""
    la = TNT_LOG10_ALPHA
    tab = build_site_table(under_canopy(forcing, ground.vegetation_cover),
                           ground.soils["site"], RADIUS_M, times, height_m=HEIGHT_M,
                           depths_m=(*DEPTHS_M, 0.06, 0.08),
                           log10_alpha=(la - 0.3, la - 0.1, la, la + 0.1), centre="disc")
    return (1.0 - ground.vegetation_cover) * tab.contrast_for(RADIUS_M, times)[:len(DEPTHS_M), 2]


def variants(log, forcing, times, ground, cover: float) -> dict:
    """The chain's soil built in the ways of the module docstring: {name: (soil, canopy)}."""
    alpha, _ = fit_soil_diffusivity(log)
    sand = soil_from_diffusivity(alpha)
    twin = ground.soils["site"]
    out = {"dry fit": (refit(sand, log, forcing, times), 0.0),
           "dry, true heat capacity": (refit(replace(sand, rho_c_jm3k=twin.rho_c_jm3k,
                                                     k_wmk=alpha * twin.rho_c_jm3k),
                                             log, forcing, times), 0.0)}
    if twin.water is not None:
        out["true water, sand heat capacity"] = (refit(replace(sand, water=twin.water), log,
                                                       forcing, times), 0.0)
    nan = np.full(times.size, np.nan)
    if cover > 0:
        out["balance fit, bare ground"] = (site_soil(log, forcing, times, nan)[0], 0.0)
    out["balance fit"] = (site_soil(log, forcing, times, nan, cover)[0], cover)
    out["twin's soil, refitted"] = (refit(twin, log, forcing, times), 0.0)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("surveys", nargs="+")
    args = ap.parse_args()
    print("| survey | site soil | error cm at " + " / ".join(f"{100 * d:.0f}" for d in DEPTHS_M)
          + " cm | MAE 0-4 cm |")
    print("|---|---|---|---|")
    for survey in args.surveys:
        doc = json.loads((Path(survey) / "truth" / "scenario.json").read_text())
        cfg = parse_scenario(doc, None, preset(doc.get("preset", "demo"))).config
        ground = ground_of(cfg.soil_type, cfg.soil_moisture, cfg.vegetation_cover)
        _, times, forcing, log = survey_inputs(survey)
        curves = true_curves(forcing, ground, times)
        base = np.full(times.size, 290.0)
        cover = float(json.loads((Path(survey) / "survey.json").read_text())["site"]
                      .get("vegetation_cover", 0.0))
        for name, (soil, canopy) in variants(log, forcing, times, ground, cover).items():
            tab = chain_site_table(under_canopy(forcing, canopy), soil, RADIUS_M, times,
                                   canopy)
            err = np.array([100 * (invert_anomaly(times, base + c, base, forcing, soil, RADIUS_M,
                                                  noise_k=0.05, table=tab).depth_m - d)
                            for d, c in zip(DEPTHS_M, curves, strict=True)])
            print(f"| {Path(survey).parent.name} | {name} | "
                  + " / ".join(f"{e:+.2f}" for e in err)
                  + f" | {np.mean(np.abs(err[:5])):.2f} |", flush=True)


if __name__ == "__main__":
    main()
