"""Small, valid survey folders for tests (this package's and other packages')."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from clearfast_gis.survey.logs import (
    BlackbodyLog,
    Markers,
    SoilLog,
    write_blackbody_log,
    write_markers,
    write_soil_log,
)
from clearfast_gis.survey.manifest import write_mission, write_survey_json
from clearfast_gis.survey.nmea import GnssLog, write_nmea
from clearfast_gis.survey.tables import write_blackbody_frames_table, write_frames_table
from clearfast_gis.survey.tiff import write_tiff_stack
from clearfast_gis.survey.toa5 import WeatherLog, write_toa5
from clearfast_gis.timeutil import format_utc, parse_utc

DEFAULT_BANDS = ({"name": "LW1", "lambda_min_um": 8.0, "lambda_max_um": 9.2},
                 {"name": "LW2", "lambda_min_um": 10.3, "lambda_max_um": 11.3},
                 {"name": "MW", "lambda_min_um": 3.5, "lambda_max_um": 5.0})


def minimal_manifest(survey_id: str = "test", width: int = 16, height: int = 12,
                     n_bands: int = 1, start_utc: str = "2026-11-15T00:00:00Z",
                     duration_s: float = 3600.0) -> dict:
    """A valid ``survey.json`` dict for an equiangular camera of ``width`` x ``height``."""
    start = parse_utc(start_utc)
    return {
        "format": "clearfast-survey", "format_version": 1, "survey_id": survey_id,
        "site": {"name": "test site", "latitude_deg": 35.17, "longitude_deg": 33.36,
                 "ground_altitude_m": 160.0},
        "crs": {"epsg": 32636},
        "time": {"start_utc": format_utc(start, "seconds"),
                 "end_utc": format_utc(start + duration_s, "seconds")},
        "camera": {"model": "equiangular", "resolution": [width, height], "aperture_deg": 24.0,
                   "bit_depth": 14, "netd_k": 0.05,
                   "bands": [dict(b) for b in DEFAULT_BANDS[:n_bands]]},
        "platform": {"kind": "boom_lift", "antenna_to_camera_m": [0.0, 0.0, -0.4],
                     "pan_zero_azimuth_deg": 0.0, "tilt_zero_deg": 0.0},
        "files": {"mission": "mission.json", "frames": "frames.csv",
                  "blackbody_frames": "blackbody/frames.csv",
                  "blackbody_log": "blackbody/temperatures.csv", "gnss": "gnss.nmea",
                  "weather": "weather.dat", "soil": "soil.csv", "markers": "markers.csv"},
    }


def minimal_mission(n_scans: int, n_positions: int, scan_interval_s: float, width: int,
                    height: int) -> dict:
    """A valid ``mission.json`` dict with ``n_positions`` positions on one tilt row."""
    return {
        "format": "clearfast-mission", "format_version": 1,
        "platform": {"x_m": 0.0, "y_m": 0.0, "height_m": 10.0},
        "area": [-10.0, 5.0, 10.0, 35.0],
        "camera": {"resolution": [width, height], "aperture_deg": 24.0},
        "overlap": 0.2, "n_scans": n_scans, "scan_interval_s": scan_interval_s,
        "duration_h": n_scans * scan_interval_s / 3600.0,
        "images_per_scan": n_positions, "images_total": n_scans * n_positions,
        "ground_resolution_m": {"across_min": 0.02, "across_max": 0.05,
                                "along_min": 0.03, "along_max": 0.1},
        "positions": [{"index": i, "pan_deg": -20.0 + 10.0 * i, "tilt_deg": -45.0}
                      for i in range(n_positions)],
    }


def make_minimal_survey(root: str | os.PathLike, n_scans: int = 2, n_positions: int = 3,
                        n_bands: int = 1, width: int = 16, height: int = 12,
                        scan_interval_s: float = 1500.0, gnss_step_s: float = 10.0,
                        start_utc: str = "2026-11-15T00:00:00Z", seed: int = 0,
                        n_bb_frames: int = 10) -> Path:
    """Write a small, complete and valid survey folder under ``root`` and return its path.

    Frames are random uint16 counts; GNSS is RTK-fixed every ``gnss_step_s`` seconds over the
    whole survey, weather every minute, soil every 10 minutes, one blackbody event per scan.
    """
    rng = np.random.default_rng(seed)
    root = Path(root)
    root.mkdir(parents=True, exist_ok=True)
    start = parse_utc(start_utc)
    duration = n_scans * scan_interval_s
    write_survey_json(root / "survey.json",
                      minimal_manifest("test-" + str(seed), width, height, n_bands, start_utc,
                                       duration))
    mission = minimal_mission(n_scans, n_positions, scan_interval_s, width, height)
    write_mission(root / "mission.json", mission)

    cols: dict[str, list] = {k: [] for k in ("scan", "position", "band", "time_s", "pan_deg",
                                             "tilt_deg", "file", "page")}
    bb: dict[str, list] = {k: [] for k in ("event", "blackbody", "band", "time_s", "file",
                                           "page")}
    for s in range(n_scans):
        t_scan = start + 60.0 + s * scan_interval_s
        for b in range(n_bands):
            rel = f"frames/scan_{s:03d}_b{b}.tif"
            stack = rng.integers(6000, 9000, size=(n_positions, height, width), dtype=np.uint16)
            write_tiff_stack(root / rel, stack)
            for p, pos in enumerate(mission["positions"]):
                cols["scan"].append(s)
                cols["position"].append(pos["index"])
                cols["band"].append(b)
                cols["time_s"].append(t_scan + 2.0 * p + 0.1 * b)
                cols["pan_deg"].append(pos["pan_deg"])
                cols["tilt_deg"].append(pos["tilt_deg"])
                cols["file"].append(rel)
                cols["page"].append(p)
            rel_bb = f"blackbody/event_{s:03d}_b{b}.tif"
            hot = rng.integers(9000, 9100, size=(n_bb_frames, height, width), dtype=np.uint16)
            amb = rng.integers(7000, 7100, size=(n_bb_frames, height, width), dtype=np.uint16)
            write_tiff_stack(root / rel_bb, np.concatenate([hot, amb]))
            for k in range(2 * n_bb_frames):
                bb["event"].append(s)
                bb["blackbody"].append(1 if k < n_bb_frames else 2)
                bb["band"].append(b)
                bb["time_s"].append(t_scan - 50.0 + k)
                bb["file"].append(rel_bb)
                bb["page"].append(k)
    write_frames_table(root / "frames.csv", {k: np.asarray(v) for k, v in cols.items()})
    write_blackbody_frames_table(root / "blackbody/frames.csv",
                                 {k: np.asarray(v) for k, v in bb.items()})

    t_min = start + np.arange(0.0, duration + 1.0, 60.0)
    write_blackbody_log(root / "blackbody/temperatures.csv",
                        BlackbodyLog(t_min, 25.0 + 0.01 * np.arange(t_min.size),
                                     15.0 + 0.01 * np.arange(t_min.size)))
    n = t_min.size
    write_toa5(root / "weather.dat", WeatherLog(
        time_s=t_min, air_temp_c=15.0 + rng.normal(0, 0.1, n), rh_pct=np.full(n, 60.0),
        pressure_hpa=np.full(n, 1005.0), wind_ms=np.full(n, 2.0), solar_wm2=np.zeros(n),
        sky_lw_wm2=np.full(n, 300.0), rain_mm=np.zeros(n)))
    t_soil = start + np.arange(0.0, duration + 1.0, 600.0)
    depths = np.array([0.02, 0.05, 0.1, 0.2, 0.5])
    write_soil_log(root / "soil.csv", SoilLog(
        t_soil, depths, 15.0 + np.exp(-depths / 0.1)[None, :] * np.ones((t_soil.size, 1))))
    t_g = start + np.arange(0.0, duration + 1.0, gnss_step_s)
    m = t_g.size
    write_nmea(root / "gnss.nmea", GnssLog(
        time_s=t_g, lat_deg=np.full(m, 35.17), lon_deg=np.full(m, 33.36),
        alt_m=np.full(m, 170.0), fix_quality=np.full(m, 4, dtype=np.int8),
        n_sats=np.full(m, 14, dtype=np.int16), hdop=np.full(m, 0.7)))
    write_markers(root / "markers.csv", Markers(("M1", "M2"), np.array([35.1701, 35.1702]),
                                                np.array([33.3601, 33.3603]),
                                                ("corner stake", "lane marker, north")))
    return root


def pynmea2_gga_epochs(path: str | os.PathLike) -> dict[float, list[tuple[int, float, float, int]]]:
    """An independent reading of a real receiver log, for comparisons: pynmea2's GGA
    sentences with a time, cut at each line's last ``$`` (lines split at LF or CR), checksums
    checked. Returns time of day (s, 3 decimals) -> [(quality, lat_deg, lon_deg, n_sats)]."""
    import pynmea2

    out: dict[float, list] = {}
    text = Path(path).read_bytes().decode("utf-8", "replace")
    for raw in text.replace("\r", "\n").split("\n"):
        line = raw.strip()
        if "$" not in line:
            continue
        try:
            msg = pynmea2.parse(line[line.rfind("$"):], check=True)
        except (pynmea2.ParseError, pynmea2.ChecksumError, ValueError, AttributeError):
            continue
        if isinstance(msg, pynmea2.GGA) and msg.timestamp is not None:
            ts = msg.timestamp
            tod = round(ts.hour * 3600 + ts.minute * 60 + ts.second + ts.microsecond * 1e-6, 3)
            out.setdefault(tod, []).append((int(msg.gps_qual or 0), msg.latitude,
                                            msg.longitude, int(msg.num_sats or 0)))
    return out
