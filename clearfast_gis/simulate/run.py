"""Orchestration: simulate a complete survey folder with its ground truth.

Order of work (all randomness from one seed, split into independent named streams so that a
change in one part does not reshuffle the others):

1. the twin (:func:`~clearfast_gis.simulate.twin.build_twin`): objects (scenario or drawn),
   site origin, camera, lift, mission (the planner), forcing, truth grid and scene fields,
   detectors, blackbody truth;
2. schedule: per scan a calibration event (10 frames of each blackbody per band), then the
   stop-and-go positions, bands in filter-wheel order;
3. thermal truth at the scan times;
4. per scan: surface temperature, per band radiance grid, blackbody frames, scene frames
   (true pose -> ray trace -> atmosphere -> detector);
5. logs (GNSS NMEA, TOA5, soil, blackbody temperatures, markers), manifest, mission, tables,
   truth.
"""

from __future__ import annotations

import json
import shutil
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from clearfast_gis.atomic import write_text
from clearfast_gis.errors import InvalidInput
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.simulate.config import SimConfig
from clearfast_gis.simulate.objects import SceneObject
from clearfast_gis.simulate.render import radiance_grid
from clearfast_gis.simulate.scenario import scenario_document
from clearfast_gis.simulate.surface import surface_temperature_k, thermal_truth
from clearfast_gis.simulate.truth import (
    write_bands,
    write_objects,
    write_poses,
    write_temperature_tif,
)
from clearfast_gis.simulate.twin import build_twin, site_origin, stream

__all__ = ["SimulationResult", "simulate_survey", "site_origin"]
from clearfast_gis.survey.logs import write_blackbody_log, write_markers, write_soil_log
from clearfast_gis.survey.manifest import write_mission, write_survey_json
from clearfast_gis.survey.nmea import write_nmea
from clearfast_gis.survey.tables import write_blackbody_frames_table, write_frames_table
from clearfast_gis.survey.tiff import write_tiff_stack
from clearfast_gis.survey.toa5 import write_toa5
from clearfast_gis.timeutil import format_utc
from clearfast_gis.units import ZERO_CELSIUS_K

#: seconds between a scan's calibration event and its first position
CALIBRATION_S = 30.0
#: seconds between blackbody frames
BB_FRAME_S = 0.5


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
    twin: object = field(default=None, repr=False)


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

    twin = build_twin(config, seed, drift, objects, draw_clutter)
    objs, origin, grid = twin.objects, twin.origin, twin.grid
    w_px, h_px = config.resolution
    start_s, end_s = twin.start_s, twin.end_s
    interval_s = config.duration_s / config.n_scans
    mission = twin.mission
    positions = mission["positions"]
    n_pos, n_bands = len(positions), twin.n_bands
    scan_len_s = CALIBRATION_S + n_pos * config.position_dwell_s
    if scan_len_s > interval_s:
        raise InvalidInput(f"a scan of {n_pos} positions takes {scan_len_s:.0f} s, longer than "
                           f"the {interval_s:.0f} s between scans", field="n_scans")
    scan_t0 = start_s + config.first_scan_offset_s + interval_s * np.arange(config.n_scans)
    scan_t0 = np.minimum(scan_t0, end_s - scan_len_s - 60.0)
    scan_mid = scan_t0 + CALIBRATION_S + 0.5 * n_pos * config.position_dwell_s
    timings["setup"] = clock() - t_stage

    # thermal truth at the scan times
    t_stage = clock()
    truth_t = thermal_truth(twin.forcing, scan_mid, objs, twin.ground)
    timings["thermal"] = clock() - t_stage
    rows_a, cols_a, area_grid = twin.area_rows, twin.area_cols, twin.area_grid
    tables = twin.tables

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
        temp_k = surface_temperature_k(twin.fields, truth_t, s)
        rgrids = []
        for b, tb in enumerate(tables):
            l_surf, sky = twin.band_surface(temp_k, b, scan_mid[s])
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
            for k in range(config.blackbody_frames):
                page = (bb - 1) * config.blackbody_frames + k
                for b in range(n_bands):
                    t = (scan_t0[s] + (bb - 1) * CALIBRATION_S / 2 + k * BB_FRAME_S
                         + b * config.band_interval_s / 4)
                    bb_stacks[b][page] = twin.blackbody_counts(b, bb, t, noise)
                    bb_rows["event"].append(s)
                    bb_rows["blackbody"].append(bb)
                    bb_rows["band"].append(b)
                    bb_rows["time_s"].append(t)
                    bb_rows["file"].append(f"blackbody/event_{s:03d}_b{b}.tif")
                    bb_rows["page"].append(page)
        stacks = [np.empty((n_pos, h_px, w_px), np.uint16) for _ in tables]
        for p, pos in enumerate(positions):
            for b in range(n_bands):
                t = (scan_t0[s] + CALIBRATION_S + p * config.position_dwell_s
                     + b * config.band_interval_s)
                stacks[b][p], pose = twin.scene_counts(b, pos["pan_deg"], pos["tilt_deg"], t,
                                                       rgrids[b], noise)
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
    write_nmea(root / "gnss.nmea", twin.gnss_log())
    write_toa5(root / "weather.dat", twin.weather_log(), station="clearfast_sim")
    write_soil_log(root / "soil.csv", twin.soil_log())
    write_blackbody_log(root / "blackbody" / "temperatures.csv", twin.blackbody_log())
    write_markers(root / "markers.csv", twin.markers())
    write_frames_table(root / "frames.csv", {k: np.asarray(v) for k, v in frame_rows.items()})
    write_blackbody_frames_table(root / "blackbody" / "frames.csv",
                                 {k: np.asarray(v) for k, v in bb_rows.items()})
    write_mission(root / "mission.json", mission)
    manifest = twin.manifest(f"{config.name}-seed{seed}{'-drift' if drift else ''}",
                             f"simulated survey (preset {config.name})")
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
                            config.n_scans * n_pos * n_bands, objs, timings, twin)
