"""Orchestration: simulate a complete survey folder with its ground truth.

Order of work (all randomness from one seed, split into independent named streams so that a
change in one part does not reshuffle the others):

1. objects (scenario or drawn), site origin, camera, lift, mission (the planner);
2. schedule: per scan a calibration event (10 frames of each blackbody per band), then the
   stop-and-go positions, bands in filter-wheel order;
3. weather (clear-sky forcing), thermal truth at the scan times, soil profile;
4. truth grid and scene fields; per scan: surface temperature, per band radiance grid,
   blackbody frames, scene frames (true pose -> ray trace -> atmosphere -> detector);
5. logs (GNSS NMEA, TOA5, soil, blackbody temperatures, markers), manifest, mission, tables,
   truth.
"""

from __future__ import annotations

import json
import math
import shutil
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.geometry.cameras import EquiangularCamera, PinholeCamera
from clearfast_gis.geometry.gnss import crs_to_lonlat, lonlat_to_crs
from clearfast_gis.geometry.pose import pose_from_ptu
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.radiometry.surface import surface_leaving_radiance
from clearfast_gis.radiometry.table import BandTable
from clearfast_gis.simulate import instruments
from clearfast_gis.simulate.config import SimConfig
from clearfast_gis.simulate.detector import make_detector
from clearfast_gis.simulate.mission import plan_for
from clearfast_gis.simulate.objects import SceneObject, draw_objects
from clearfast_gis.simulate.platform import gnss_epochs, lift_motion
from clearfast_gis.simulate.rays import FrameRays
from clearfast_gis.simulate.render import (
    Atmosphere,
    at_camera_radiance,
    radiance_grid,
    surface_radiance_frame,
)
from clearfast_gis.simulate.scenario import scenario_document
from clearfast_gis.simulate.scene import GridSpec, build_scene
from clearfast_gis.simulate.sky import sky_band_radiance
from clearfast_gis.simulate.surface import (
    emissivity_map,
    forcing_at,
    soil_profile_k,
    surface_temperature_k,
    thermal_truth,
)
from clearfast_gis.simulate.truth import (
    write_bands,
    write_objects,
    write_poses,
    write_temperature_tif,
)
from clearfast_gis.survey.logs import Markers, write_blackbody_log, write_markers, write_soil_log
from clearfast_gis.survey.manifest import write_mission, write_survey_json
from clearfast_gis.survey.nmea import GnssLog, write_nmea
from clearfast_gis.survey.tables import write_blackbody_frames_table, write_frames_table
from clearfast_gis.survey.tiff import write_tiff_stack
from clearfast_gis.survey.toa5 import write_toa5
from clearfast_gis.thermal.forcing import clear_sky_forcing
from clearfast_gis.timeutil import format_utc, parse_utc
from clearfast_gis.units import ZERO_CELSIUS_K

#: independent random streams (numpy SeedSequence entropy [seed, stream])
STREAMS = {"objects": 1, "scene": 2, "detector": 3, "lift": 4, "gnss": 5, "noise": 6,
           "weather": 7, "soil": 8, "blackbody": 9}

#: seconds between a scan's calibration event and its first position
CALIBRATION_S = 30.0
#: seconds between blackbody frames
BB_FRAME_S = 0.5
#: distortion of the simulated pinhole lens (k1, k2, p1, p2, k3)
PINHOLE_DISTORTION = (-0.06, 0.01, 0.0, 0.0, 0.0)


def stream(seed: int, name: str, index: int | None = None) -> np.random.Generator:
    """The random generator of the named stream for ``seed`` (and scan ``index``)."""
    key = [int(seed), STREAMS[name]] + ([] if index is None else [int(index)])
    return np.random.default_rng(key)


@dataclass
class SimulationResult:
    """What :func:`simulate_survey` wrote: the folder, counts and stage timings (s)."""

    root: Path
    n_scans: int
    n_positions: int
    n_bands: int
    n_frames: int
    objects: list[SceneObject]
    timings_s: dict = field(default_factory=dict)


def make_camera(config: SimConfig):
    """The camera model of ``config`` and its survey.json ``camera`` entry."""
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


def simulate_survey(out_dir: str | Path, config: SimConfig, seed: int = 0, drift: bool = False,
                    objects: list[SceneObject] | None = None, draw_clutter: bool = False,
                    progress: Progress = NULL_PROGRESS, overwrite: bool = False
                    ) -> SimulationResult:
    """Simulate a survey folder (the format ``clearfast validate`` accepts) plus ``truth/``.

    Parameters
    ----------
    out_dir : path
        Output folder (created; must be empty or absent unless ``overwrite``).
    config : SimConfig
        Preset with scenario overrides.
    seed : int
        Random seed; identical seeds give byte-identical files.
    drift : bool
        Simulate the trial's sinking, tilting lift (paper §6).
    objects : list of SceneObject, optional
        The scene's objects (local metres); default: drawn from the seed.
    draw_clutter : bool
        With ``objects``, also draw the preset's clutter around them.
    progress : Progress
        Progress reporter (one step per scan).
    overwrite : bool
        Replace an existing non-empty folder.

    Returns
    -------
    SimulationResult
    """
    import time as _time

    clock = _time.perf_counter
    timings: dict[str, float] = {}
    t_stage = clock()
    root = Path(out_dir)
    if root.exists() and not root.is_dir():
        raise InvalidInput("output exists and is not a folder", root)
    if root.exists() and any(root.iterdir()):
        if not overwrite:
            raise InvalidInput("output folder exists and is not empty (use --overwrite)", root)
        if not (root / "survey.json").exists() and not (root / "truth").is_dir():
            raise InvalidInput("will not overwrite a folder that is not a simulated survey",
                               root)
        shutil.rmtree(root)
    root.mkdir(parents=True, exist_ok=True)

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
    interval_s = config.duration_s / config.n_scans
    mission = plan_for(config, origin, lift_xy, interval_s)
    positions = mission["positions"]
    n_pos, n_bands = len(positions), len(config.bands)
    scan_len_s = CALIBRATION_S + n_pos * config.position_dwell_s
    if scan_len_s > interval_s:
        raise InvalidInput(f"a scan of {n_pos} positions takes {scan_len_s:.0f} s, longer than "
                           f"the {interval_s:.0f} s between scans", field="n_scans")
    scan_t0 = start_s + config.first_scan_offset_s + interval_s * np.arange(config.n_scans)
    scan_t0 = np.minimum(scan_t0, end_s - scan_len_s - 60.0)
    scan_mid = scan_t0 + CALIBRATION_S + 0.5 * n_pos * config.position_dwell_s
    motion = lift_motion(config, antenna0, start_s, drift, stream(seed, "lift"))
    timings["setup"] = clock() - t_stage

    # weather and thermal truth
    t_stage = clock()
    forcing = clear_sky_forcing(config.latitude_deg, config.longitude_deg, start_s,
                                config.duration_s, 60.0)
    truth_t = thermal_truth(forcing, scan_mid, objs)
    t_soil = np.arange(start_s, end_s + 1.0, 600.0)
    depths = np.asarray(instruments.SOIL_DEPTHS_M)
    soil_k = soil_profile_k(forcing, t_soil, depths)
    timings["thermal"] = clock() - t_stage

    # scene
    t_stage = clock()
    ends = [start_s, end_s]
    nominal = [pose_from_ptu(motion.antenna_m(t)[0], p["pan_deg"], p["tilt_deg"], platform,
                             motion.attitude_rpy_deg(t)[0]) for p in positions for t in ends]
    grid = truth_grid(config, origin, camera, nominal)
    fields_ = build_scene(grid, objs, origin, stream(seed, "scene"))
    rows_a, cols_a, area_grid = area_window(grid, config, origin)
    tables = [BandTable(b.lambda_min_um, b.lambda_max_um) for b in config.bands]
    frame_rays = [FrameRays(camera, b.shift_px) for b in config.bands]
    emis = [emissivity_map(fields_, b.lambda_min_um, b.lambda_max_um) for b in config.bands]
    det_rng = stream(seed, "detector")
    detectors = [make_detector(tb, (h_px, w_px), config.bit_depth, config.netd_k, start_s,
                               det_rng) for tb in tables]
    timings["scene"] = clock() - t_stage

    # blackbody truth on the logger's minute grid
    t_min = np.arange(start_s, end_s + 1.0, 60.0)
    fm = forcing_at(forcing, t_min)
    air_min = fm["air_temp_k"]
    bb1_k, bb2_k = instruments.blackbody_truth_k(t_min, air_min)
    pressure = instruments.station_pressure_hpa(t_min, config.ground_altitude_m)

    frame_rows: dict[str, list] = {k: [] for k in ("scan", "position", "band", "time_s",
                                                   "pan_deg", "tilt_deg", "file", "page")}
    bb_rows: dict[str, list] = {k: [] for k in ("event", "blackbody", "band", "time_s", "file",
                                                "page")}
    pose_rows: list[tuple] = []
    t_render = t_write = 0.0
    progress.start("simulate", config.n_scans)
    (root / "truth" / "apparent_temperature").mkdir(parents=True, exist_ok=True)
    for s in range(config.n_scans):
        t0 = clock()
        noise = stream(seed, "noise", s)  # per scan: independent of the order of work
        temp_k = surface_temperature_k(fields_, truth_t, s)
        fs = forcing_at(forcing, np.array([scan_mid[s]]))
        rgrids = []
        for b, tb in enumerate(tables):
            sky = float(sky_band_radiance(fs["sky_lw_wm2"][0], fs["air_temp_k"][0], tb))
            l_surf = surface_leaving_radiance(temp_k, emis[b], sky, tb).astype(np.float32)
            if b == 0:
                app_c = tb.temperature(l_surf[rows_a, cols_a]) - np.float32(ZERO_CELSIUS_K)
                t_w = clock()
                write_temperature_tif(
                    root / "truth" / "apparent_temperature" / f"scan_{s:03d}.tif", app_c,
                    area_grid, f"apparent temperature {config.bands[0].name} scan {s} "
                    f"{format_utc(scan_mid[s], 'seconds')}")
                t_write += clock() - t_w
            rgrids.append(radiance_grid(l_surf, grid, sky))
        # calibration event: bb1 then bb2, each band per frame (filter wheel)
        bb_stacks = [np.empty((2 * config.blackbody_frames, h_px, w_px), np.uint16)
                     for _ in tables]
        for bb in (1, 2):
            truth_bb = bb1_k if bb == 1 else bb2_k
            for k in range(config.blackbody_frames):
                page = (bb - 1) * config.blackbody_frames + k
                for b, tb in enumerate(tables):
                    t = (scan_t0[s] + (bb - 1) * CALIBRATION_S / 2 + k * BB_FRAME_S
                         + b * config.band_interval_s / 4)
                    rad = float(tb.radiance(np.interp(t, t_min, truth_bb)))
                    bb_stacks[b][page] = detectors[b].counts(
                        np.full((h_px, w_px), rad, np.float32), t, noise)
                    bb_rows["event"].append(s)
                    bb_rows["blackbody"].append(bb)
                    bb_rows["band"].append(b)
                    bb_rows["time_s"].append(t)
                    bb_rows["file"].append(f"blackbody/event_{s:03d}_b{b}.tif")
                    bb_rows["page"].append(page)
        stacks = [np.empty((n_pos, h_px, w_px), np.uint16) for _ in tables]
        for p, pos in enumerate(positions):
            for b, tb in enumerate(tables):
                t = (scan_t0[s] + CALIBRATION_S + p * config.position_dwell_s
                     + b * config.band_interval_s)
                pose = pose_from_ptu(motion.antenna_m(t)[0], pos["pan_deg"], pos["tilt_deg"],
                                     platform, motion.attitude_rpy_deg(t)[0])
                l_s, rng_m = surface_radiance_frame(frame_rays[b], pose, rgrids[b], ifov)
                atm = Atmosphere(float(np.interp(t, t_min, air_min)),
                                 float(np.interp(t, t_min, fm["rh_pct"])),
                                 float(np.interp(t, t_min, pressure)))
                stacks[b][p] = detectors[b].counts(at_camera_radiance(l_s, rng_m, atm, tb),
                                                   t, noise)
                frame_rows["scan"].append(s)
                frame_rows["position"].append(p)
                frame_rows["band"].append(b)
                frame_rows["time_s"].append(t)
                frame_rows["pan_deg"].append(pos["pan_deg"])
                frame_rows["tilt_deg"].append(pos["tilt_deg"])
                frame_rows["file"].append(f"frames/scan_{s:03d}_b{b}.tif")
                frame_rows["page"].append(p)
                pose_rows.append((s, p, b, t, pose))
        t_render += clock() - t0
        t_w = clock()
        for b in range(n_bands):
            write_tiff_stack(root / "frames" / f"scan_{s:03d}_b{b}.tif", stacks[b])
            write_tiff_stack(root / "blackbody" / f"event_{s:03d}_b{b}.tif", bb_stacks[b])
        t_write += clock() - t_w
        t_render -= clock() - t_w
        progress.advance(1, scan=s)
    progress.close()
    timings["render"] = t_render

    # logs, manifest, tables, truth
    t_stage = clock()
    epochs = gnss_epochs(motion, start_s - 60.0, end_s, config.gnss_interval_s,
                         stream(seed, "gnss"))
    lon, lat = crs_to_lonlat(epochs.position_m[:, 0], epochs.position_m[:, 1], config.epsg)
    write_nmea(root / "gnss.nmea", GnssLog(
        time_s=epochs.time_s, lat_deg=np.asarray(lat, float), lon_deg=np.asarray(lon, float),
        alt_m=epochs.position_m[:, 2] + config.ground_altitude_m,
        fix_quality=epochs.quality.astype(np.int8), n_sats=epochs.n_sats.astype(np.int16),
        hdop=epochs.hdop.astype(float)))
    write_toa5(root / "weather.dat", instruments.weather_log(
        t_min, fm["air_temp_k"], fm["rh_pct"], pressure, fm["wind_ms"], fm["solar_wm2"],
        fm["sky_lw_wm2"],
        stream(seed, "weather")), station="clearfast_sim")
    write_soil_log(root / "soil.csv", instruments.soil_log(t_soil, depths, soil_k,
                                                           stream(seed, "soil")))
    write_blackbody_log(root / "blackbody" / "temperatures.csv",
                        instruments.blackbody_log(t_min, bb1_k, bb2_k,
                                                  stream(seed, "blackbody")))
    markers = [o for o in objs if o.kind == "marker"]
    m_lon, m_lat = crs_to_lonlat(np.array([o.x_m + origin[0] for o in markers]),
                                 np.array([o.y_m + origin[1] for o in markers]), config.epsg)
    write_markers(root / "markers.csv", Markers(
        id=tuple(o.id for o in markers), lat_deg=np.atleast_1d(np.asarray(m_lat, float)),
        lon_deg=np.atleast_1d(np.asarray(m_lon, float)),
        description=tuple(f"{o.variant} plate 0.3 m" for o in markers)))
    write_frames_table(root / "frames.csv", {k: np.asarray(v) for k, v in frame_rows.items()})
    write_blackbody_frames_table(root / "blackbody" / "frames.csv",
                                 {k: np.asarray(v) for k, v in bb_rows.items()})
    write_mission(root / "mission.json", mission)
    manifest = {
        "format": "clearfast-survey", "format_version": 1,
        "survey_id": f"{config.name}-seed{seed}{'-drift' if drift else ''}",
        "description": f"simulated survey (preset {config.name})",
        "site": {"name": config.site_name, "latitude_deg": config.latitude_deg,
                 "longitude_deg": config.longitude_deg,
                 "ground_altitude_m": config.ground_altitude_m},
        "crs": {"epsg": config.epsg},
        "time": {"start_utc": format_utc(start_s, "seconds"),
                 "end_utc": format_utc(end_s, "seconds")},
        "camera": cam_entry, "platform": platform,
        "files": {"mission": "mission.json", "frames": "frames.csv",
                  "blackbody_frames": "blackbody/frames.csv",
                  "blackbody_log": "blackbody/temperatures.csv", "gnss": "gnss.nmea",
                  "weather": "weather.dat", "soil": "soil.csv", "markers": "markers.csv"},
    }
    write_survey_json(root / "survey.json", manifest)
    write_objects(root / "truth" / "objects.csv", objs, origin)
    write_poses(root / "truth" / "poses.csv", pose_rows)
    write_bands(root / "truth" / "bands.csv", config.bands)
    scen = scenario_document(config, objs)
    scen["description"] = (f"objects of {manifest['survey_id']}; area origin (south-west "
                           f"corner) E {origin[0]:.1f} N {origin[1]:.1f} EPSG {config.epsg}")
    write_text(root / "truth" / "scenario.json", json.dumps(scen, indent=1) + "\n")
    timings["logs"] = clock() - t_stage
    timings["write"] = t_write
    return SimulationResult(root, config.n_scans, n_pos, n_bands,
                            config.n_scans * n_pos * n_bands, objs, timings)
