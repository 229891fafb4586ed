"""True surface temperature and emissivity of the scene at each scan.

Thermal runs (``clearfast_gis.thermal``): one 1-D background run per soil end-member (dry sand,
moist sand, disturbed soil: dry sand loosened to 70 % conductivity and 90 % heat capacity) and
one axisymmetric run per distinct (kind, depth, diameter, height, body material) object in
the site soil (the mean of the two end-members); objects of the same kind, size, depth and
material share a run. Thin layers
(vegetation, marker plates) come from :mod:`clearfast_gis.simulate.thin_layers`.

Composition on the truth grid for a scan ``s``::

    T_bg = (1 - m) T_dry + m T_moist                   m: moisture fraction field
    T    = mix of T_bg, T_disturbed, T_leaf, T_plate   by the cover fractions
    T    = gaussian(T, sigma = 1 cm)                   lateral conduction at class edges
    T   += T_obj(r, s) - T_site(s)                     each object's radial contrast

Emissivity per band mixes the same way; inside surface-laid objects it is the object's.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import cv2
import numpy as np

from clearfast_gis.simulate.emissivity import band_emissivity
from clearfast_gis.simulate.objects import SceneObject
from clearfast_gis.simulate.scene import SceneFields
from clearfast_gis.simulate.thin_layers import leaf_temperature_k, plate_temperature_k
from clearfast_gis.thermal.canopy import seen_share, under_canopy
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.thermal.forward import BuriedObject, simulate_background, simulate_object
from clearfast_gis.thermal.materials import MATERIALS
from clearfast_gis.thermal.soils import soil_of_type

#: thermal material of each object kind's body
OBJECT_MATERIAL = {"at_mine": "tnt", "ap_mine": "tnt", "stone": "stone", "metal": "steel"}
#: surface (optical) material of each object kind when surface-laid
OBJECT_SURFACE = {"at_mine": "mine_casing", "ap_mine": "mine_casing", "stone": "stone",
                  "metal": "metal_debris"}
#: marker plates: (albedo, broadband emissivity, spectral material)
MARKER_PLATES = {"hot": (0.05, 0.95, "marker_hot"), "cold": (0.15, 0.07, "marker_cold")}
#: lateral smoothing of the composited class temperatures, metres (Gaussian sigma)
LATERAL_SIGMA_M = 0.01
#: the moisture field's end-members lie this far (degree of saturation) around the site's
MOISTURE_SPREAD = 0.1


@dataclass(frozen=True)
class Ground:
    """The twin's ground: soil end-members (:func:`soils`) and a grass cover fraction 0..1."""

    soils: dict
    vegetation_cover: float = 0.0


def ground_of(soil_type: str | None, moisture: float, vegetation_cover: float) -> Ground:
    """The :class:`Ground` of a config's ``soil_type``, ``soil_moisture``, ``vegetation_cover``."""
    return Ground(soils(soil_type, moisture), float(vegetation_cover))


def soils(soil_type: str | None = None, moisture: float = 0.5) -> dict:
    """The soil end-members: ``dry``, ``moist``, ``disturbed`` and the ``site`` soil.

    Without a ``soil_type``: dry and moist sand (no evaporation) and their mean. With one
    (:data:`clearfast_gis.thermal.soils.SOIL_TYPES`): that soil at degree of saturation
    ``moisture`` (the site) and ``MOISTURE_SPREAD`` drier and wetter (the end-members of the
    moisture field), all evaporating.
    """
    if soil_type is not None:
        dry = soil_of_type(soil_type, max(moisture - MOISTURE_SPREAD, 0.0))
        moist = soil_of_type(soil_type, min(moisture + MOISTURE_SPREAD, 1.0))
        site = soil_of_type(soil_type, moisture)
    else:
        dry, moist = MATERIALS["dry_sand"], MATERIALS["moist_sand"]
        site = replace(moist, name="site_sand", k_wmk=0.5 * (dry.k_wmk + moist.k_wmk),
                       rho_c_jm3k=0.5 * (dry.rho_c_jm3k + moist.rho_c_jm3k),
                       emissivity=0.5 * (dry.emissivity + moist.emissivity),
                       albedo=0.5 * (dry.albedo + moist.albedo))
    disturbed = replace(dry, name="disturbed_sand", k_wmk=0.7 * dry.k_wmk,
                        rho_c_jm3k=0.9 * dry.rho_c_jm3k, albedo=dry.albedo + 0.03)
    return {"dry": dry, "moist": moist, "disturbed": disturbed, "site": site}


def object_key(obj: SceneObject) -> tuple:
    """Objects with the same key share one thermal run."""
    return (obj.kind, round(obj.depth_m, 4), round(obj.diameter_m, 4), round(obj.height_m, 4),
            object_material(obj))


def object_material(obj: SceneObject) -> str:
    """The name of the object's body material: its own (a mine's fill), else its kind's
    (:data:`OBJECT_MATERIAL`; ``aluminium`` for markers, ``disturbed_sand``, ``vegetation``)."""
    if obj.material:
        return obj.material
    return OBJECT_MATERIAL.get(obj.kind, {"marker": "aluminium",
                                          "disturbed_soil": "disturbed_sand"}.get(
                                              obj.kind, "vegetation"))


def object_diffusivity_m2s(obj: SceneObject, ground: Ground | None = None) -> float:
    """Thermal diffusivity of the object's material (m2/s; NaN for vegetation)."""
    if obj.kind in OBJECT_MATERIAL:
        return MATERIALS[object_material(obj)].alpha_m2s
    if obj.kind == "disturbed_soil":
        return (soils() if ground is None else ground.soils)["disturbed"].alpha_m2s
    if obj.kind == "marker":
        return MATERIALS["aluminium"].alpha_m2s
    return float("nan")


@dataclass(frozen=True)
class ObjectProfile:
    """Radial surface-temperature contrast of one thermal run: radii (R,), contrast (S, R) K."""

    radii_m: np.ndarray
    contrast_k: np.ndarray


@dataclass(frozen=True)
class ThermalTruth:
    """Surface temperatures at the scan times (S,), kelvin.

    ``soil_k`` maps ``dry``/``moist``/``disturbed``/``site`` to (S,); ``leaf_k``, ``plate_k``
    (dict hot/cold) are (S,); ``objects`` maps :func:`object_key` to an :class:`ObjectProfile`;
    ``canopy`` is the grass cover fraction over soil and buried objects.
    """

    time_s: np.ndarray
    soil_k: dict
    leaf_k: np.ndarray
    plate_k: dict
    objects: dict
    canopy: float = 0.0


def forcing_at(forcing: Forcing, time_s: np.ndarray) -> dict[str, np.ndarray]:
    """The forcing's channels linearly interpolated to ``time_s`` (dict of arrays)."""
    t = np.asarray(time_s, float)
    return forcing.at(t)


def thermal_truth(forcing: Forcing, scan_time_s: np.ndarray, objects: list[SceneObject],
                  ground: Ground | None = None) -> ThermalTruth:
    """Run the thermal model for the backgrounds, thin layers and every distinct object.

    ``ground`` (default: the sand mixture, no grass) gives the soils and the grass cover;
    soils and objects under grass are forced by :func:`under_canopy`.
    """
    t = np.asarray(scan_time_s, float)
    ground = Ground(soils()) if ground is None else ground
    sl = ground.soils
    open_air = forcing
    forcing = under_canopy(forcing, ground.vegetation_cover)
    soil_k = {name: background_surface_k(soil, forcing, t) for name, soil in sl.items()}
    f = forcing_at(open_air, t)
    drive = (f["solar_wm2"], f["sky_lw_wm2"], f["air_temp_k"], f["wind_ms"])
    site_k = soil_k["site"]
    leaf = leaf_temperature_k(*drive, site_k)
    plates = {v: plate_temperature_k(*drive, site_k, a, e)
              for v, (a, e, _) in MARKER_PLATES.items()}
    runs: dict = {}
    for obj in objects:
        if obj.kind not in OBJECT_MATERIAL:
            continue
        key = object_key(obj)
        if key not in runs:
            runs[key] = object_profile(sl["site"], obj, forcing, t)
    return ThermalTruth(t, soil_k, leaf, plates, runs, ground.vegetation_cover)


def background_surface_k(soil, forcing: Forcing, time_s: np.ndarray) -> np.ndarray:
    """Surface temperature (S,) of a mine-free 1-D soil column at ``time_s``, kelvin."""
    return np.asarray(simulate_background(soil, forcing, time_s).surface_k, float)


def soil_profile_k(forcing: Forcing, time_s: np.ndarray, depths_m: np.ndarray,
                   ground: Ground | None = None) -> np.ndarray:
    """Temperature (T, D) of the site soil at the thermocouple depths, kelvin."""
    ground = Ground(soils()) if ground is None else ground
    run = simulate_background(ground.soils["site"], under_canopy(forcing, ground.vegetation_cover),
                              time_s, depths_m=depths_m)
    return np.asarray(run.profile_k, float)


def object_profile(soil, obj: SceneObject, forcing: Forcing, time_s: np.ndarray
                   ) -> ObjectProfile:
    """Radial surface contrast of ``obj`` in ``soil``: run minus the mine-free background."""
    body = BuriedObject(radius_m=obj.radius_m, height_m=max(obj.height_m, 0.01),
                        depth_m=obj.depth_m, material=MATERIALS[object_material(obj)])
    radii = np.linspace(0.0, obj.radius_m + 0.2, 48)
    run = simulate_object(soil, body, forcing, time_s, radii_m=radii)
    surface = np.asarray(run.surface_k, float)
    background = np.asarray(run.background_k, float)
    return ObjectProfile(radii, surface - background[:, None])


def surface_temperature_k(fields: SceneFields, truth: ThermalTruth, s: int) -> np.ndarray:
    """Kinetic surface temperature (H, W) float32 of the truth grid at scan ``s``, kelvin."""
    m = fields.moisture
    dry, moist = np.float32(truth.soil_k["dry"][s]), np.float32(truth.soil_k["moist"][s])
    t = dry + m * (moist - dry)
    t += fields.disturbed * (np.float32(truth.soil_k["disturbed"][s]) - t)
    if truth.canopy > 0:
        t += np.float32(truth.canopy) * (np.float32(truth.leaf_k[s]) - t)
    t += fields.vegetation * (np.float32(truth.leaf_k[s]) - t)
    t += fields.marker_hot * (np.float32(truth.plate_k["hot"][s]) - t)
    t += fields.marker_cold * (np.float32(truth.plate_k["cold"][s]) - t)
    sigma = LATERAL_SIGMA_M / fields.grid.pixel_size
    t = cv2.GaussianBlur(t, (0, 0), sigmaX=sigma, borderType=cv2.BORDER_REPLICATE)
    flat = t.reshape(-1)
    seen = np.float32(seen_share(truth.canopy))
    for fp in fields.footprints:
        prof = truth.objects[object_key(fp.obj)]
        flat[fp.index] += seen * np.interp(fp.r_m, prof.radii_m,
                                           prof.contrast_k[s]).astype(np.float32)
    return t


def emissivity_map(fields: SceneFields, lambda_min_um: float, lambda_max_um: float,
                   canopy: float = 0.0) -> np.ndarray:
    """Band emissivity (H, W) float32 of the truth grid (time-invariant); ``canopy`` is the
    grass cover over the soil and surface-laid objects."""
    def e(name: str) -> np.float32:
        return np.float32(band_emissivity(name, lambda_min_um, lambda_max_um))

    eps = e("dry_soil") + fields.moisture * (e("moist_soil") - e("dry_soil"))
    eps += fields.disturbed * (e("disturbed_soil") - eps)
    grass = np.float32(canopy)
    if canopy > 0:
        eps += grass * (e("vegetation") - eps)
    eps += fields.vegetation * (e("vegetation") - eps)
    eps += fields.marker_hot * (e("marker_hot") - eps)
    eps += fields.marker_cold * (e("marker_cold") - eps)
    flat = eps.reshape(-1)
    for fp in fields.footprints:
        if fp.obj.depth_m <= 0.0:
            inside = fp.r_m <= fp.obj.radius_m
            flat[fp.index[inside]] = (e(OBJECT_SURFACE[fp.obj.kind])
                                      + grass * (e("vegetation") - e(OBJECT_SURFACE[fp.obj.kind])))
    return eps.astype(np.float32)
