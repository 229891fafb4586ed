"""Thermal and optical properties of soils and buried objects.

Values are representative figures from the literature, each with its source; the soils'
diffusivity is replaced in practice by the value fitted to the site's thermocouples
(:func:`clearfast_gis.thermal.soilfit.fit_soil_diffusivity`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from clearfast_gis.thermal.moisture import SurfaceWater


@dataclass(frozen=True)
class Material:
    """A homogeneous material.

    Attributes
    ----------
    name : str
        Identifier, lower-case (``"tnt"``, ``"moist_sand"``).
    k_wmk : float
        Thermal conductivity, W m-1 K-1.
    rho_c_jm3k : float
        Volumetric heat capacity (density times specific heat), J m-3 K-1.
    emissivity : float
        Broadband thermal-IR emissivity of an exposed surface, 0..1.
    albedo : float
        Broadband solar reflectance of an exposed surface, 0..1.
    source : str
        Where the figures come from.
    kind : str
        ``"soil"``, ``"explosive"``, ``"plastic"``, ``"wood"``, ``"stone"`` or ``"metal"``.
    """

    name: str
    k_wmk: float
    rho_c_jm3k: float
    emissivity: float
    albedo: float
    source: str
    kind: str

    def __post_init__(self) -> None:
        if not (self.k_wmk > 0 and self.rho_c_jm3k > 0):
            raise ValueError(f"{self.name}: conductivity and heat capacity must be positive")
        if not (0 <= self.emissivity <= 1 and 0 <= self.albedo <= 1):
            raise ValueError(f"{self.name}: emissivity and albedo must lie in [0, 1]")

    @property
    def alpha_m2s(self) -> float:
        """Thermal diffusivity k / (rho c), m2 s-1."""
        return self.k_wmk / self.rho_c_jm3k

    def with_alpha(self, alpha_m2s: float) -> Material:
        """The same material with diffusivity ``alpha_m2s``, keeping rho c (k changes)."""
        return replace(self, k_wmk=float(alpha_m2s) * self.rho_c_jm3k)


@dataclass(frozen=True)
class Soil(Material):
    """A soil: a :class:`Material` whose surface exchanges heat with the air.

    Attributes
    ----------
    hc_scale : float
        Multiplier on the convective coefficient ``h_c = 5.7 + 3.8 v`` W m-2 K-1 (1 = nominal);
        fitted with the albedo to background pixels by
        :func:`clearfast_gis.thermal.surface_fit.fit_surface_parameters`.
    water : SurfaceWater or None
        Water of the surface layer: with it the surface evaporates, takes dew and rain
        (latent heat, :mod:`clearfast_gis.thermal.moisture`); None: a dry surface without
        latent heat (the default twin's sand; the inversion's soil has the wetness fitted to
        its shallowest thermocouple, :func:`clearfast_gis.thermal.surface_fit.fit_surface_balance`).
    """

    hc_scale: float = 1.0
    water: SurfaceWater | None = None


_SAND = (
    "de Vries (1963) Thermal properties of soils, in Physics of Plant Environment; "
    "Hillel (1982) Introduction to Soil Physics, Table 9.3; Thanh et al. (2008) Infrared "
    "thermography for buried landmine detection: inverse problem setting, IEEE TGRS 46(12)"
)

MATERIALS: dict[str, Material] = {
    "dry_sand": Soil(
        "dry_sand", 0.30, 1.28e6, 0.92, 0.30, _SAND + " (dry sand, porosity 0.4)", "soil"
    ),
    "moist_sand": Soil(
        "moist_sand", 1.10, 1.80e6, 0.95, 0.22, _SAND + " (sand, volumetric water 0.15-0.2)", "soil"
    ),
    "tnt": Material(
        "tnt", 0.23, 2.28e6, 0.90, 0.30,
        "Dobratz & Crawford (1985) LLNL Explosives Handbook UCRL-52997 (k 0.234 W/m/K, "
        "rho 1.65 g/cm3, c 1.38 kJ/kg/K); Thanh et al. (2008) IEEE TGRS 46(12)", "explosive",
    ),
    "comp_b": Material(
        "comp_b", 0.22, 2.01e6, 0.90, 0.30,
        "Dobratz & Crawford (1985) LLNL Explosives Handbook UCRL-52997 (Composition B, "
        "RDX/TNT 60/40: k 0.22 W/m/K, rho 1.72 g/cm3, c 1.17 kJ/kg/K)", "explosive",
    ),
    "pine": Material(
        "pine", 0.147, 1.80e6, 0.90, 0.35,
        "Incropera & DeWitt (2002) Table A.3 (yellow pine, cross grain: k 0.147 W/m/K, "
        "rho 640 kg/m3, c 2805 J/kg/K; alpha 0.82e-7 m2/s): the body of a wooden box mine",
        "wood",
    ),
    "plastic": Material(
        "plastic", 0.30, 1.80e6, 0.92, 0.20,
        "Incropera & DeWitt (2002) Fundamentals of Heat and Mass Transfer, Table A.3 "
        "(polyethylene/ABS casing materials, k 0.2-0.4, rho c 1.3-2.2e6)", "plastic",
    ),
    "stone": Material(
        "stone", 2.80, 2.10e6, 0.93, 0.25,
        "Incropera & DeWitt (2002) Table A.3 (granite k 2.79 W/m/K, rho 2630 kg/m3, "
        "c 775 J/kg/K)", "stone",
    ),
    "steel": Material(
        "steel", 43.0, 3.60e6, 0.80, 0.35,
        "Incropera & DeWitt (2002) Table A.1 (plain carbon steel, k 43-60, rho 7854, c 434; "
        "alpha ~1.2e-5 m2/s); emissivity of oxidised steel", "metal",
    ),
    "aluminium": Material(
        "aluminium", 237.0, 2.44e6, 0.20, 0.40,
        "Incropera & DeWitt (2002) Table A.1 (pure aluminium k 237, rho 2702, c 903; "
        "alpha 9.7e-5 m2/s); emissivity of weathered aluminium", "metal",
    ),
}
"""Named materials: soils ``dry_sand``, ``moist_sand`` (as :class:`Soil`), objects ``tnt``,
``comp_b``, ``pine``, ``plastic``, ``stone``, ``steel``, ``aluminium``."""

MINE_FILLS = ("tnt", "comp_b", "plastic", "pine")
"""The bodies a simulated mine can have (:data:`MATERIALS` names): TNT and Composition B
fills, a plastic-bodied mine, a wooden box mine. Their diffusivities (0.82-1.7e-7 m2/s) and
heat capacities (1.8-2.3e6 J/m3/K) span the handbook spread that :data:`MINE_FILL_LOG10_ALPHA`
states, so a twin drawing from them tests that prior and the fixed heat capacity of the
inversion's object."""

MINE_BODY_RHO_C_JM3K = (1.8e6, 2.05e6, 2.3e6)
"""The volumetric heat capacities, J m-3 K-1, a mine's body is fitted with: the handbook
range of mine bodies (explosive fills 2.0-2.3e6: TNT 2.28, Composition B 2.01; a plastic
body 1.8; yellow pine 1.8; :data:`MATERIALS`) in three steps.
Each anomaly is fitted with the object at each (:mod:`clearfast_gis.thermal.bodies`): the
curve, not TNT's value, says which body it is, or the spread of the fits says how much that
matters."""


MINE_FILL_LOG10_ALPHA = (-6.92, 0.15)
"""Prior of a mine's diffusivity, (mean, 1 sigma) of log10 alpha (m2 s-1): the fills and
casings of blast mines, from handbook values (k / rho c): TNT 1.0e-7 (:data:`MATERIALS`),
Composition B 1.1e-7 (:data:`MATERIALS` ``comp_b``), RDX 1.2e-7, bakelite 1.1e-7, yellow
pine (wooden box mines) 0.82e-7 (``pine``), plastic casings 1.7e-7 (``plastic``): 1.2e-7,
with 1 sigma 0.85-1.7e-7.
The inversion weighs its fit of an anomaly's diffusivity against it
(:func:`clearfast_gis.thermal.inversion.invert_anomaly` ``alpha_prior``): a few scans of a
hot, dry day explain a mine at 3 cm as well as an object at 0.5 cm that conducts like dry
sand, and the prior says which of the two a mine is; a stone's or a metal's diffusivity,
which a curve does determine, stays its own."""


def get_material(name: str) -> Material:
    """The material called ``name``; ``KeyError`` lists the known names."""
    try:
        return MATERIALS[name]
    except KeyError:
        raise KeyError(f"unknown material {name!r}; known: {', '.join(MATERIALS)}") from None


def get_soil(name: str) -> Soil:
    """The soil called ``name`` (``dry_sand`` or ``moist_sand``)."""
    mat = get_material(name)
    if not isinstance(mat, Soil):
        raise KeyError(f"{name!r} is not a soil")
    return mat
