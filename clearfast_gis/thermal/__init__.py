"""Soil heat transfer with buried objects, and burial depth / diffusivity inversion.

Forcing (weather) -> forward model (1-D soil column, 2-D axisymmetric soil with a cylinder)
-> soil diffusivity from thermocouples, surface parameters from background pixels
-> per-site table of forward runs -> depth and diffusivity per anomaly -> material cue.
"""

from clearfast_gis.thermal.cue import material_cue
from clearfast_gis.thermal.forcing import (
    Forcing,
    clear_sky_emissivity,
    clear_sky_forcing,
    clear_sky_longwave,
    forcing_from_weather,
)
from clearfast_gis.thermal.forward import (
    BackgroundRun,
    BuriedObject,
    ObjectModel,
    ObjectRun,
    simulate_background,
    simulate_object,
)
from clearfast_gis.thermal.inversion import STATUSES, Inversion, invert_anomaly
from clearfast_gis.thermal.materials import MATERIALS, Material, Soil, get_material, get_soil
from clearfast_gis.thermal.soilfit import fit_soil_diffusivity
from clearfast_gis.thermal.solar import clear_sky_ghi, solar_position, sun_times
from clearfast_gis.thermal.surface_fit import fit_surface_parameters
from clearfast_gis.thermal.table import SiteTable, build_site_table, object_material

__all__ = [
    "MATERIALS",
    "STATUSES",
    "BackgroundRun",
    "BuriedObject",
    "Forcing",
    "Inversion",
    "Material",
    "ObjectModel",
    "ObjectRun",
    "SiteTable",
    "Soil",
    "build_site_table",
    "clear_sky_emissivity",
    "clear_sky_forcing",
    "clear_sky_ghi",
    "clear_sky_longwave",
    "fit_soil_diffusivity",
    "fit_surface_parameters",
    "forcing_from_weather",
    "get_material",
    "get_soil",
    "invert_anomaly",
    "material_cue",
    "object_material",
    "simulate_background",
    "simulate_object",
    "solar_position",
    "sun_times",
]
