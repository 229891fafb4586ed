"""The digital twin of a survey: scene, platform, weather, instruments and camera, at any time.

:func:`build_twin` sets up everything that does not depend on when frames are taken: the
objects, the site origin, the camera model, the lift's true motion (with the trial's drift),
the planner's mission, the weather (:mod:`clearfast_gis.simulate.weather`), the ground
(soil and grass), the truth grid and its fields, band tables,
emissivities, detectors, and the blackbody truth on the loggers' minute grid. From it:

- :func:`~clearfast_gis.simulate.run.simulate_survey` renders the scheduled frames of a whole
  survey folder;
- the device simulators (:mod:`clearfast_gis.simulate.devices`) answer the drivers at the twin
  clock's time: receiver epochs, weather records, soil and blackbody temperatures, and frames
  rendered on request at the pan/tilt unit's true pose (:meth:`Twin.scene_counts`,
  :meth:`Twin.blackbody_counts`).

All random draws come from named streams of the seed (:func:`stream`), so the twin gives the
same scene, detectors and logs whoever builds it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.geometry.cameras import EquiangularCamera, PinholeCamera
from clearfast_gis.geometry.gnss import crs_to_lonlat, lonlat_to_crs
from clearfast_gis.geometry.pose import CameraPose, pose_from_ptu
from clearfast_gis.radiometry.surface import surface_leaving_radiance
from clearfast_gis.radiometry.table import BandTable
from clearfast_gis.simulate import instruments
from clearfast_gis.simulate.config import SimConfig
from clearfast_gis.simulate.detector import Detector, make_detector
from clearfast_gis.simulate.mission import plan_for
from clearfast_gis.simulate.objects import SceneObject, draw_objects
from clearfast_gis.simulate.platform import LiftMotion, gnss_epochs, lift_motion
from clearfast_gis.simulate.rays import FrameRays
from clearfast_gis.simulate.render import (
    Atmosphere,
    RadianceGrid,
    at_camera_radiance,
    surface_radiance_frame,
)
from clearfast_gis.simulate.scene import GridSpec, SceneFields, build_scene
from clearfast_gis.simulate.sky import sky_band_radiance
from clearfast_gis.simulate.surface import (
    Ground,
    emissivity_map,
    forcing_at,
    ground_of,
    soil_profile_k,
)
from clearfast_gis.simulate.weather import site_forcing
from clearfast_gis.survey.logs import BlackbodyLog, Markers, SoilLog
from clearfast_gis.survey.manifest import DEFAULT_FILES
from clearfast_gis.survey.nmea import GnssLog
from clearfast_gis.survey.toa5 import WeatherLog
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.timeutil import format_utc, parse_utc

#: independent random streams (numpy SeedSequence entropy [seed, stream])
STREAMS = {"objects": 1, "scene": 2, "detector": 3, "lift": 4, "gnss": 5, "noise": 6,
           "weather": 7, "soil": 8, "blackbody": 9, "camera": 10, "gusts": 11}

#: distortion of the simulated pinhole lens (k1, k2, p1, p2, k3)
PINHOLE_DISTORTION = (-0.06, 0.01, 0.0, 0.0, 0.0)

def stream(seed: int, name: str, index: int | None = None) -> np.random.Generator:
    """The random generator of the named stream for ``seed`` (and scan ``index``)."""
    key = [int(seed), STREAMS[name]] + ([] if index is None else [int(index)])
    return np.random.default_rng(key)


def make_camera(config: SimConfig):
    """The camera model of ``config``, its survey.json ``camera`` entry and its pixel angle
    (radians)."""
    w, h = config.resolution
    entry = {"model": config.camera_model, "resolution": [w, h],
             "aperture_deg": config.aperture_deg, "bit_depth": config.bit_depth,
             "netd_k": config.netd_k,
             "bands": [{"name": b.name, "lambda_min_um": b.lambda_min_um,
                        "lambda_max_um": b.lambda_max_um} for b in config.bands]}
    if config.camera_model == "pinhole":
        base = PinholeCamera.from_aperture(w, h, config.aperture_deg)
        cam = PinholeCamera(w, h, base.fx, base.fy, base.cx, base.cy, PINHOLE_DISTORTION)
        entry["intrinsics"] = {"fx": cam.fx, "fy": cam.fy, "cx": cam.cx, "cy": cam.cy,
                               "distortion": list(PINHOLE_DISTORTION)}
        return cam, entry, 1.0 / cam.fx
    if config.camera_model != "equiangular":
        raise InvalidInput(f"unknown camera model {config.camera_model!r}", field="camera.model")
    cam = EquiangularCamera(w, h, config.aperture_deg)
    return cam, entry, cam.ifov_rad


def site_origin(config: SimConfig) -> tuple[float, float]:
    """Survey-CRS coordinates of the area's south-west corner (whole metres, site centred)."""
    e, n = lonlat_to_crs(config.longitude_deg, config.latitude_deg, config.epsg)
    return (float(math.floor(float(e) - config.area_width_m / 2)),
            float(math.floor(float(n) - config.area_length_m / 2)))


def scene_objects(config: SimConfig, seed: int, objects: list[SceneObject] | None,
                  draw_clutter: bool) -> list[SceneObject]:
    """The scene's objects: the scenario's (plus drawn clutter if asked), or all drawn."""
    rng = stream(seed, "objects")
    if objects is None:
        return draw_objects(config, rng)
    listed = list(objects)
    if not draw_clutter:
        return listed
    from dataclasses import replace

    from clearfast_gis.simulate.config import ObjectCounts
    counts = ObjectCounts(0, 0, config.objects.stone, config.objects.metal,
                          config.objects.vegetation, config.objects.disturbed_soil, 0)
    clutter = draw_objects(replace(config, objects=counts), rng)
    keep = [c for c in clutter if all(
        math.hypot(c.x_m - o.x_m, c.y_m - o.y_m) > c.radius_m + o.radius_m + 0.25
        for o in listed)]
    return listed + keep


def truth_grid(config: SimConfig, origin: tuple[float, float], camera, poses) -> GridSpec:
    """The truth grid: the frames' ground footprints, clipped to the area plus a margin,
    snapped to whole cells from the area's corner."""
    ps = config.grid_cell_m
    w, l_m = config.area_width_m, config.area_length_m
    edge = camera.edge_pixels(16)
    pts = [camera.ground_points(edge[:, 0], edge[:, 1], p)[:, :2] for p in poses]
    pts = np.vstack(pts)
    pts = pts[np.all(np.isfinite(pts), axis=1)]
    clip = max(4.0, 0.5 * max(w, l_m))
    x_lo = max(pts[:, 0].min() if pts.size else origin[0], origin[0] - clip)
    x_hi = min(pts[:, 0].max() if pts.size else origin[0] + w, origin[0] + w + clip)
    y_lo = max(pts[:, 1].min() if pts.size else origin[1], origin[1] - clip)
    y_hi = min(pts[:, 1].max() if pts.size else origin[1] + l_m, origin[1] + l_m + clip)
    x_lo, y_lo = min(x_lo, origin[0] - 0.5), min(y_lo, origin[1] - 0.5)
    x_hi, y_hi = max(x_hi, origin[0] + w + 0.5), max(y_hi, origin[1] + l_m + 0.5)
    c_lo = math.floor((x_lo - origin[0]) / ps)
    c_hi = math.ceil((x_hi - origin[0]) / ps)
    r_lo = math.floor((y_lo - origin[1]) / ps)
    r_hi = math.ceil((y_hi - origin[1]) / ps)
    return GridSpec(origin[0] + c_lo * ps, origin[1] + r_hi * ps, ps, c_hi - c_lo, r_hi - r_lo,
                    config.epsg)


def area_window(grid: GridSpec, config: SimConfig, origin: tuple[float, float]
                ) -> tuple[slice, slice, GridSpec]:
    """Rows/columns of the truth grid that cover the survey area, and that area's grid."""
    ps = grid.pixel_size
    c0 = int(round((origin[0] - grid.x0) / ps))
    r0 = int(round((grid.y0 - (origin[1] + config.area_length_m)) / ps))
    nw = int(round(config.area_width_m / ps))
    nh = int(round(config.area_length_m / ps))
    sub = GridSpec(grid.x0 + c0 * ps, grid.y0 - r0 * ps, ps, nw, nh, grid.epsg)
    return slice(r0, r0 + nh), slice(c0, c0 + nw), sub


@dataclass
class Twin:
    """Everything about a simulated survey that does not depend on when frames are taken.

    Times are UTC epoch seconds, positions metres in the survey CRS (``epsg``), angles
    degrees, temperatures kelvin. See :func:`build_twin`.
    """

    config: SimConfig
    seed: int
    drift: bool
    objects: list[SceneObject]
    origin: tuple[float, float]
    camera: object
    camera_entry: dict
    ifov_rad: float
    platform: dict
    start_s: float
    end_s: float
    mission: dict
    motion: LiftMotion
    forcing: Forcing
    grid: GridSpec
    fields: SceneFields
    area_rows: slice
    area_cols: slice
    area_grid: GridSpec
    tables: list[BandTable]
    frame_rays: list[FrameRays]
    emissivity: list[np.ndarray]
    detectors: list[Detector]
    t_min: np.ndarray
    forcing_min: dict
    bb1_k: np.ndarray
    bb2_k: np.ndarray
    pressure_hpa: np.ndarray
    ground: Ground

    @property
    def n_bands(self) -> int:
        """Spectral bands of the camera."""
        return len(self.tables)

    # -- frames -----------------------------------------------------------------------------

    def band_surface(self, temp_k: np.ndarray, band: int, time_s: float
                     ) -> tuple[np.ndarray, float]:
        """Surface-leaving radiance (H, W) float32 of the truth grid in ``band`` for the
        surface temperature ``temp_k`` (K), and the sky's band radiance, W m-2 sr-1, with the
        sky of ``time_s``."""
        tb = self.tables[band]
        fs = forcing_at(self.forcing, np.array([time_s]))
        sky = float(sky_band_radiance(fs["sky_lw_wm2"][0], fs["air_temp_k"][0], tb))
        l_surf = surface_leaving_radiance(temp_k, self.emissivity[band], sky, tb)
        return l_surf.astype(np.float32), sky

    def pose(self, pan_deg: float, tilt_deg: float, time_s: float) -> CameraPose:
        """True camera pose at ``time_s`` for the pan/tilt angles (degrees)."""
        return pose_from_ptu(self.motion.antenna_m(time_s)[0], pan_deg, tilt_deg,
                             self.platform, self.motion.attitude_rpy_deg(time_s)[0])

    def atmosphere(self, time_s: float) -> Atmosphere:
        """Air between ground and camera at ``time_s`` (the weather station's minute grid)."""
        return Atmosphere(float(np.interp(time_s, self.t_min, self.forcing_min["air_temp_k"])),
                          float(np.interp(time_s, self.t_min, self.forcing_min["rh_pct"])),
                          float(np.interp(time_s, self.t_min, self.pressure_hpa)))

    def scene_counts(self, band: int, pan_deg: float, tilt_deg: float, time_s: float,
                     rgrids: RadianceGrid | Sequence[tuple[RadianceGrid, float]],
                     rng: np.random.Generator | None) -> tuple[np.ndarray, CameraPose]:
        """Raw counts (H, W) uint16 of one band's frame at the pan/tilt angles and time; and
        the true pose.

        ``rgrids`` is the band's radiance grid of that time, or (grid, weight) pairs whose
        weighted sum of surface radiance is seen (grids of the neighbouring times).
        """
        pose = self.pose(pan_deg, tilt_deg, time_s)
        pairs = [(rgrids, 1.0)] if isinstance(rgrids, RadianceGrid) else list(rgrids)
        l_s, rng_m = surface_radiance_frame(self.frame_rays[band], pose, pairs[0][0],
                                            self.ifov_rad)
        if len(pairs) > 1:
            l_s = l_s * np.float32(pairs[0][1])
            for grid, weight in pairs[1:]:
                l_s += np.float32(weight) * surface_radiance_frame(
                    self.frame_rays[band], pose, grid, self.ifov_rad)[0]
        radiance = at_camera_radiance(l_s, rng_m, self.atmosphere(time_s), self.tables[band])
        return self.detectors[band].counts(radiance, time_s, rng), pose

    def blackbody_k(self, blackbody: int, time_s: float) -> float:
        """True temperature of blackbody 1 (heated) or 2 (ambient) at ``time_s``, K."""
        return float(np.interp(time_s, self.t_min, self.bb1_k if blackbody == 1 else self.bb2_k))

    def blackbody_counts(self, band: int, blackbody: int, time_s: float,
                         rng: np.random.Generator | None) -> np.ndarray:
        """Raw counts (H, W) uint16 of a frame filled by a blackbody."""
        h, w = self.config.height, self.config.width
        rad = float(self.tables[band].radiance(self.blackbody_k(blackbody, time_s)))
        return self.detectors[band].counts(np.full((h, w), rad, np.float32), time_s, rng)

    # -- logs -------------------------------------------------------------------------------

    def gnss_log(self) -> GnssLog:
        """The receiver's epochs from a minute before the start to the end."""
        c = self.config
        epochs = gnss_epochs(self.motion, self.start_s - 60.0, self.end_s, c.gnss_interval_s,
                             stream(self.seed, "gnss"))
        lon, lat = crs_to_lonlat(epochs.position_m[:, 0], epochs.position_m[:, 1], c.epsg)
        return GnssLog(time_s=epochs.time_s, lat_deg=np.asarray(lat, float),
                       lon_deg=np.asarray(lon, float),
                       alt_m=epochs.position_m[:, 2] + c.ground_altitude_m,
                       fix_quality=epochs.quality.astype(np.int8),
                       n_sats=epochs.n_sats.astype(np.int16), hdop=epochs.hdop.astype(float))

    def weather_log(self) -> WeatherLog:
        """The weather station's 1-minute records."""
        fm = self.forcing_min
        return instruments.weather_log(self.t_min, fm["air_temp_k"], fm["rh_pct"],
                                       self.pressure_hpa, fm["wind_ms"], fm["solar_wm2"],
                                       fm["sky_lw_wm2"], stream(self.seed, "weather"),
                                       fm["rain_mm_h"])

    def soil_log(self) -> SoilLog:
        """The thermocouples every 10 minutes."""
        t_soil = np.arange(self.start_s, self.end_s + 1.0, 600.0)
        depths = np.asarray(instruments.SOIL_DEPTHS_M)
        soil_k = soil_profile_k(self.forcing, t_soil, depths, self.ground)
        return instruments.soil_log(t_soil, depths, soil_k, stream(self.seed, "soil"))

    def blackbody_log(self) -> BlackbodyLog:
        """The blackbody sensors every minute."""
        return instruments.blackbody_log(self.t_min, self.bb1_k, self.bb2_k,
                                         stream(self.seed, "blackbody"))

    def markers(self) -> Markers:
        """The surveyed marker plates (WGS84)."""
        markers = [o for o in self.objects if o.kind == "marker"]
        lon, lat = crs_to_lonlat(np.array([o.x_m + self.origin[0] for o in markers]),
                                 np.array([o.y_m + self.origin[1] for o in markers]),
                                 self.config.epsg)
        return Markers(id=tuple(o.id for o in markers),
                       lat_deg=np.atleast_1d(np.asarray(lat, float)),
                       lon_deg=np.atleast_1d(np.asarray(lon, float)),
                       description=tuple(f"{o.variant} plate 0.3 m" for o in markers))

    def manifest(self, survey_id: str, description: str) -> dict:
        """``survey.json`` content for a survey of this twin (start and end: the twin's)."""
        c = self.config
        return {
            "format": "clearfast-survey", "format_version": 1, "survey_id": survey_id,
            "description": description,
            "site": {"name": c.site_name, "latitude_deg": c.latitude_deg,
                     "longitude_deg": c.longitude_deg, "ground_altitude_m": c.ground_altitude_m}
            | ({"vegetation_cover": round(c.vegetation_cover, 1)} if c.vegetation_cover > 0
               else {}),
            "crs": {"epsg": c.epsg},
            "time": {"start_utc": format_utc(self.start_s, "seconds"),
                     "end_utc": format_utc(self.end_s, "seconds")},
            "camera": self.camera_entry, "platform": self.platform,
            "files": dict(DEFAULT_FILES),
        }


def build_twin(config: SimConfig, seed: int = 0, drift: bool = False,
               objects: list[SceneObject] | None = None, draw_clutter: bool = False) -> Twin:
    """Set up the twin of ``config`` (see the module docstring).

    Parameters
    ----------
    config : SimConfig
        Preset with scenario overrides.
    seed : int
        Random seed.
    drift : bool
        The trial's sinking, tilting lift (paper §6).
    objects : list of SceneObject, optional
        The scene's objects (local metres); default: drawn from the seed.
    draw_clutter : bool
        With ``objects``, also draw the preset's clutter around them.
    """
    objs = scene_objects(config, seed, objects, draw_clutter)
    origin = site_origin(config)
    camera, cam_entry, ifov = make_camera(config)
    w_px, h_px = config.resolution
    lift_xy = (origin[0] + config.area_width_m / 2, origin[1] - config.lift_offset_m)
    a2c = np.asarray(config.antenna_to_camera_m, float)
    antenna0 = np.array([lift_xy[0], lift_xy[1], config.lift_height_m]) - a2c
    platform = {"kind": "boom_lift", "antenna_to_camera_m": [float(v) for v in a2c],
                "pan_zero_azimuth_deg": 0.0, "tilt_zero_deg": 0.0}
    start_s = parse_utc(config.start_utc)
    end_s = start_s + config.duration_s
    mission = plan_for(config, origin, lift_xy, config.duration_s / config.n_scans)
    motion = lift_motion(config, antenna0, start_s, drift, stream(seed, "lift"))
    forcing = site_forcing(config, start_s, stream(seed, "gusts"))
    ground = ground_of(config.soil_type, config.soil_moisture, config.vegetation_cover)
    ends = [start_s, end_s]
    nominal = [pose_from_ptu(motion.antenna_m(t)[0], p["pan_deg"], p["tilt_deg"], platform,
                             motion.attitude_rpy_deg(t)[0])
               for p in mission["positions"] for t in ends]
    grid = truth_grid(config, origin, camera, nominal)
    fields = build_scene(grid, objs, origin, stream(seed, "scene"))
    rows_a, cols_a, area_grid = area_window(grid, config, origin)
    tables = [BandTable(b.lambda_min_um, b.lambda_max_um) for b in config.bands]
    frame_rays = [FrameRays(camera, b.shift_px) for b in config.bands]
    emis = [emissivity_map(fields, b.lambda_min_um, b.lambda_max_um, ground.vegetation_cover)
            for b in config.bands]
    det_rng = stream(seed, "detector")
    detectors = [make_detector(tb, (h_px, w_px), config.bit_depth, config.netd_k, start_s,
                               det_rng) for tb in tables]
    t_min = np.arange(start_s, end_s + 1.0, 60.0)
    fm = forcing_at(forcing, t_min)
    bb1_k, bb2_k = instruments.blackbody_truth_k(t_min, fm["air_temp_k"])
    pressure = instruments.station_pressure_hpa(t_min, config.ground_altitude_m)
    return Twin(config, int(seed), bool(drift), objs, origin, camera, cam_entry, ifov, platform,
                start_s, end_s, mission, motion, forcing, grid, fields, rows_a, cols_a,
                area_grid, tables, frame_rays, emis, detectors, t_min, fm, bb1_k, bb2_k,
                pressure, ground)
