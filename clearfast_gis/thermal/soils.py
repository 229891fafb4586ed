"""Soil types and their thermal properties as a function of moisture.

A soil type (``sand``, ``loamy_sand``, ``loam``, ``clay``, ``gravel``) and a moisture given as
the degree of saturation ``S`` (0 dry .. 1 saturated; volumetric water ``theta = S * porosity``)
give a :class:`~clearfast_gis.thermal.materials.Soil`:

- conductivity by Johansen (1975, *Thermal conductivity of soils*, PhD thesis, Trondheim; in
  Farouki 1981, CRREL Monograph 81-1): ``k = k_dry + Ke (k_sat - k_dry)`` with the Kersten
  number ``Ke = 0.7 log10 S + 1`` (coarse soils) or ``log10 S + 1`` (fine soils), at least 0;
  ``k_dry = (0.135 rho_b + 64.7) / (2700 - 0.947 rho_b)`` (``rho_b`` dry bulk density,
  kg m-3; crushed rock: ``0.039 porosity^-2.2``), ``k_sat = k_solid^(1 - n) k_water^n``,
  ``k_solid = k_quartz^q k_other^(1 - q)`` (``k_quartz = 7.7``, ``k_other = 2.0`` for
  ``q > 0.2`` else 3.0, ``k_water = 0.594`` W m-1 K-1);
- volumetric heat capacity by de Vries (1963): ``rho c = 1.92e6 (1 - n) + 4.18e6 theta``
  J m-3 K-1 (minerals and water; organic matter neglected);
- porosity, quartz content and field capacity per type: Clapp & Hornberger (1978, Water
  Resour. Res. 14, 601-604) and Campbell & Norman (1998, *An Introduction to Environmental
  Biophysics*, Tables 9.1 and 8.2); albedo and emissivity from dry to wet: Campbell & Norman
  Tables 11.2 and 11.3 (linear in S).

The surface layer's water (``Soil.water``) starts at the soil's moisture, so a soil built here
evaporates (latent heat in the heat model).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from clearfast_gis.errors import InvalidInput
from clearfast_gis.thermal.materials import Soil
from clearfast_gis.thermal.moisture import SurfaceWater

K_QUARTZ_WMK = 7.7
K_WATER_WMK = 0.594
MINERAL_RHO_KGM3 = 2650.0
MINERAL_HEAT_JM3K = 1.92e6
WATER_HEAT_JM3K = 4.18e6


@dataclass(frozen=True)
class SoilType:
    """Texture class parameters (see the module docstring for sources).

    ``porosity``, ``field_capacity`` m3 m-3; ``quartz`` share of the solids; ``coarse``
    selects Johansen's Kersten relation; ``crushed`` his dry conductivity of crushed rock;
    ``albedo`` and ``emissivity`` as (dry, saturated).
    """

    name: str
    porosity: float
    field_capacity: float
    quartz: float
    coarse: bool
    crushed: bool
    albedo: tuple[float, float]
    emissivity: tuple[float, float]


SOIL_TYPES: dict[str, SoilType] = {
    "sand": SoilType("sand", 0.40, 0.10, 0.90, True, False, (0.30, 0.20), (0.92, 0.95)),
    "loamy_sand": SoilType("loamy_sand", 0.42, 0.15, 0.75, True, False, (0.28, 0.18),
                           (0.93, 0.96)),
    "loam": SoilType("loam", 0.45, 0.27, 0.40, False, False, (0.23, 0.13), (0.94, 0.97)),
    "clay": SoilType("clay", 0.50, 0.36, 0.25, False, False, (0.20, 0.12), (0.95, 0.97)),
    "gravel": SoilType("gravel", 0.30, 0.05, 0.50, True, True, (0.25, 0.17), (0.93, 0.95)),
}
"""The soil types of scenario files (``"soil": {"type": ...}``)."""


def kersten_number(saturation: float, coarse: bool) -> float:
    """Johansen's Kersten number at degree of saturation ``saturation`` (0..1), 0..1."""
    if saturation <= 0.0:
        return 0.0
    ke = (0.7 if coarse else 1.0) * math.log10(saturation) + 1.0
    return min(max(ke, 0.0), 1.0)


def conductivity_wmk(soil_type: SoilType, saturation: float) -> float:
    """Thermal conductivity by Johansen (1975), W m-1 K-1."""
    n = soil_type.porosity
    if soil_type.crushed:
        k_dry = 0.039 * n ** -2.2
    else:
        rho_b = MINERAL_RHO_KGM3 * (1.0 - n)
        k_dry = (0.135 * rho_b + 64.7) / (2700.0 - 0.947 * rho_b)
    k_other = 2.0 if soil_type.quartz > 0.2 else 3.0
    k_solid = K_QUARTZ_WMK ** soil_type.quartz * k_other ** (1.0 - soil_type.quartz)
    k_sat = k_solid ** (1.0 - n) * K_WATER_WMK ** n
    return k_dry + kersten_number(saturation, soil_type.coarse) * (k_sat - k_dry)


def heat_capacity_jm3k(soil_type: SoilType, saturation: float) -> float:
    """Volumetric heat capacity by de Vries (1963), J m-3 K-1."""
    n = soil_type.porosity
    return MINERAL_HEAT_JM3K * (1.0 - n) + WATER_HEAT_JM3K * saturation * n


def soil_of_type(name: str, moisture: float) -> Soil:
    """The soil of type ``name`` at degree of saturation ``moisture`` (0..1), evaporating.

    Raises
    ------
    InvalidInput
        Unknown type, or moisture outside 0..1.
    """
    if name not in SOIL_TYPES:
        raise InvalidInput(f"unknown soil type {name!r}; expected one of "
                           f"{', '.join(SOIL_TYPES)}", field="soil.type")
    if not 0.0 <= moisture <= 1.0:
        raise InvalidInput("moisture must lie in 0..1 (degree of saturation)",
                           field="soil.moisture")
    st = SOIL_TYPES[name]
    s = float(moisture)
    theta = s * st.porosity
    return Soil(
        name=f"{name}_s{s:.2f}", k_wmk=conductivity_wmk(st, s),
        rho_c_jm3k=heat_capacity_jm3k(st, s),
        emissivity=st.emissivity[0] + s * (st.emissivity[1] - st.emissivity[0]),
        albedo=st.albedo[0] + s * (st.albedo[1] - st.albedo[0]),
        source="Johansen 1975; de Vries 1963; Clapp & Hornberger 1978; Campbell & Norman 1998",
        kind="soil",
        water=SurfaceWater(theta_deep=theta, theta_fc=st.field_capacity,
                           theta_sat=st.porosity),
    )
