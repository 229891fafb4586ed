"""Simulation settings: the presets ``demo``, ``trial`` and ``full`` and their overrides.

A :class:`SimConfig` holds every number that shapes a simulated survey (site, area, lift,
camera, schedule, clutter counts, instrument rates). Presets are plain functions returning a
config; a scenario file (:mod:`clearfast_gis.simulate.scenario`) overrides any of its fields.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from clearfast_gis.errors import InvalidInput

#: Default site: a clear mid-November day near Nicosia, Cyprus (the 2004 trial's region).
NICOSIA_LAT_DEG = 35.17
NICOSIA_LON_DEG = 33.36
NICOSIA_ALT_M = 160.0
NICOSIA_EPSG = 32636


@dataclass(frozen=True)
class Band:
    """One spectral band of the multi-spectral camera (filter-wheel position).

    ``shift_px`` is the fixed filter-wheel misregistration (du, dv) of this band, pixels.
    """

    name: str
    lambda_min_um: float
    lambda_max_um: float
    shift_px: tuple[float, float] = (0.0, 0.0)

    @property
    def centre_um(self) -> float:
        """Centre wavelength, micrometres."""
        return 0.5 * (self.lambda_min_um + self.lambda_max_um)


@dataclass(frozen=True)
class ObjectCounts:
    """How many objects of each kind a preset draws from the seed."""

    at_mine: int = 2
    ap_mine: int = 4
    stone: int = 4
    metal: int = 2
    vegetation: int = 2
    disturbed_soil: int = 2
    marker: int = 3


@dataclass(frozen=True)
class RainEvent:
    """A shower: start (UTC epoch seconds), duration (s) and total (mm = kg m-2)."""

    start_s: float
    duration_s: float
    total_mm: float


@dataclass(frozen=True)
class WeatherSpec:
    """The twin's weather (:mod:`clearfast_gis.simulate.weather`).

    Attributes
    ----------
    cloud_cover : tuple of (hours_after_start, fraction)
        Cloud cover fraction 0..1, linear between the pairs (one pair: constant); empty: clear.
    rain : tuple of RainEvent
        Showers.
    wind_scale : float
        Multiplier on the clear day's wind.
    gusts : float
        Relative standard deviation of the 1-minute gust factor (0: none).
    air_temp_c : (float, float)
        Daily minimum and maximum air temperature, degrees C.
    rh_pct : (float, float)
        Relative humidity at the warmest and at the coolest time, percent.
    file : str or None
        A measured weather table (TOA5) that replaces the modelled day.
    """

    cloud_cover: tuple[tuple[float, float], ...] = ()
    rain: tuple[RainEvent, ...] = ()
    wind_scale: float = 1.0
    gusts: float = 0.0
    air_temp_c: tuple[float, float] = (10.0, 23.0)
    rh_pct: tuple[float, float] = (60.0, 70.0)
    file: str | None = None


@dataclass(frozen=True)
class SimConfig:
    """Everything that shapes one simulated survey.

    Lengths are metres, angles degrees, times seconds (UTC epoch for instants). The survey area
    is the rectangle ``[0, area_width_m] x [0, area_length_m]`` in *local* metres (x east,
    y north) whose south-west corner sits at ``origin_m`` in the survey CRS. The lift stands
    ``lift_offset_m`` south of the area's south edge, centred on it (beside the long side).

    The ground: ``soil_type`` None is the default sand mixture without evaporation (the
    figures of BENCHMARKS.md up to issue 22); a type of
    :data:`clearfast_gis.thermal.soils.SOIL_TYPES` with ``soil_moisture`` (degree of
    saturation) gives an evaporating soil; ``vegetation_cover`` 0..1 a uniform grass canopy.
    ``mine_fills`` (:data:`clearfast_gis.thermal.materials.MINE_FILLS` names): each drawn
    mine's body is one of them, drawn from the seed; empty, every mine is TNT-filled.
    """

    name: str = "demo"
    site_name: str = "Nicosia buffer zone (simulated)"
    latitude_deg: float = NICOSIA_LAT_DEG
    longitude_deg: float = NICOSIA_LON_DEG
    ground_altitude_m: float = NICOSIA_ALT_M
    epsg: int = NICOSIA_EPSG
    start_utc: str = "2026-11-15T00:00:00Z"
    duration_s: float = 24 * 3600.0
    n_scans: int = 6
    first_scan_offset_s: float = 3600.0
    area_width_m: float = 8.0
    area_length_m: float = 6.0
    lift_offset_m: float = 2.0
    lift_height_m: float = 8.0
    antenna_to_camera_m: tuple[float, float, float] = (0.0, 0.0, -0.4)
    camera_model: str = "equiangular"
    resolution: tuple[int, int] = (160, 128)
    aperture_deg: float = 24.0
    bit_depth: int = 14
    netd_k: float = 0.05
    bands: tuple[Band, ...] = (
        Band("LW1", 8.0, 9.2, (0.0, 0.0)),
        Band("LW2", 10.3, 11.3, (0.6, -0.4)),
    )
    overlap: float = 0.3
    grid_cell_m: float = 0.015
    objects: ObjectCounts = field(default_factory=ObjectCounts)
    gnss_interval_s: float = 5.0
    position_dwell_s: float = 3.0
    band_interval_s: float = 0.4
    blackbody_frames: int = 10
    drift_height_loss_m: float = 2.0
    drift_roll_deg: float = -3.0
    drift_pitch_deg: float = 1.5
    drift_yaw_deg: float = 2.5
    weather: WeatherSpec = field(default_factory=WeatherSpec)
    soil_type: str | None = None
    soil_moisture: float = 0.5
    vegetation_cover: float = 0.0
    mine_fills: tuple[str, ...] = ()

    @property
    def width(self) -> int:
        """Image width W, pixels."""
        return int(self.resolution[0])

    @property
    def height(self) -> int:
        """Image height H, pixels."""
        return int(self.resolution[1])


def demo() -> SimConfig:
    """The embedded demo: 8 m x 6 m, 6 scans over 24 h, 160x128, 2 bands, a handful of mines."""
    return SimConfig()


def trial() -> SimConfig:
    """The paper's layout: 30 m x 20 m, 48 scans over 24 h, ~250 positions, 320x256, 3 bands.

    The 9 degree aperture from a 13 m lift gives the planner about 250 positions per scan at
    30 % overlap (the 2004 trial: 261).
    """
    return SimConfig(
        name="trial",
        n_scans=48,
        first_scan_offset_s=0.0,
        area_width_m=30.0,
        area_length_m=20.0,
        lift_offset_m=2.0,
        lift_height_m=13.0,
        resolution=(320, 256),
        aperture_deg=9.0,
        bands=(
            Band("LW1", 8.0, 9.2, (0.0, 0.0)),
            Band("LW2", 9.2, 10.4, (1.3, -0.7)),
            Band("LW3", 10.4, 12.0, (-0.5, 1.8)),
        ),
        grid_cell_m=0.02,
        objects=ObjectCounts(at_mine=6, ap_mine=14, stone=25, metal=8, vegetation=8,
                             disturbed_soil=6, marker=4),
        gnss_interval_s=1.0,
        position_dwell_s=2.0,
        band_interval_s=0.3,
        drift_height_loss_m=3.0,
        drift_roll_deg=-4.5,
        drift_pitch_deg=2.0,
        drift_yaw_deg=3.0,
    )


def full() -> SimConfig:
    """As :func:`trial` at 640x512 with a finer truth grid."""
    return replace(trial(), name="full", resolution=(640, 512), grid_cell_m=0.015)


PRESETS = {"demo": demo, "trial": trial, "full": full}


def preset(name: str) -> SimConfig:
    """The preset called ``name`` (``demo``, ``trial`` or ``full``)."""
    try:
        return PRESETS[name]()
    except KeyError:
        raise InvalidInput(f"unknown preset {name!r}; expected one of {', '.join(PRESETS)}",
                           field="preset", ) from None
