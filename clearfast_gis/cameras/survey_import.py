"""Build a survey folder from a radiometric camera's files, a pose table and the field logs.

``clearfast import`` (and the folder layout with ``import.json``, ``docs/import.md``): every
camera frame is matched to exactly one row of the pose table by file name and frame number
(never by position in a list), its time and pan/tilt angles come from that row or, where the
row leaves them empty, from the file's own tags; all frames must share one radiometry (FLIR
Planck constants, or one linear scale). The frames are stored as the survey's uint16 stacks
(FLIR raw signal and TLinear counts as read; float temperatures as 0.01 K counts) with
``camera.radiometry`` in ``survey.json``, so the chain needs no blackbodies. The logs are
parsed (to refuse bad ones with their line) and copied byte for byte. The folder is built under
a temporary name, validated with :func:`clearfast_gis.survey.validate_survey`, and only then
renamed: nothing half-written is ever visible.
"""

from __future__ import annotations

import math
import os
import shutil
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass, field
from datetime import UTC
from pathlib import Path

import numpy as np

from clearfast_gis.cameras import RadiometricFrame, exiftool, read_frames
from clearfast_gis.cameras.csv_tables import csv_records, table_time, table_value
from clearfast_gis.errors import InvalidInput
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.radiometry.camera import CameraRadiometry
from clearfast_gis.timeutil import format_utc

TEMPERATURE_COUNT_K = 0.01
"""Kelvin per stored count for float temperature frames (0-655 K in uint16)."""
DEFAULT_LWIR_BAND_UM = (7.5, 13.5)
"""Band of a broadband LWIR camera whose files do not state it, micrometres."""
TAG_BATCH = 200
"""Files per exiftool run."""
POSE_COLUMNS = ("file", "frame", "scan", "position", "time_utc", "pan_deg", "tilt_deg")
"""Columns of the pose table; ``file``, ``scan`` and ``position`` are required."""


@dataclass
class ImportSpec:
    """What ``clearfast import`` needs.

    Attributes
    ----------
    frames : list of Path
        Camera files (folders are expanded to their files, sorted by name).
    poses, gnss, weather, soil, mission : Path
        Pose table, NMEA log, TOA5 weather table, thermocouple log, ``mission.json``.
    markers : Path or None
        ``markers.csv``.
    blackbody, blackbody_log : Path or None
        Blackbody table (``file,frame,event,blackbody,time_utc``, the camera files beside it)
        and blackbody temperature log (``time_utc,bb1_c,bb2_c``); both or neither
        (:mod:`clearfast_gis.cameras.blackbody_import`).
    station_profile : Path or None
        The weather station's / soil logger's profile (their own column names and units,
        ``docs/acquire.md``); copied into the survey as ``station_profile.json``.
    antenna_to_camera_m : (3,) floats
        Camera centre minus GNSS antenna, east/north/up of the pan/tilt base, metres.
    pan_zero_azimuth_deg, tilt_zero_deg : float
        Mount calibration (``docs/contracts.md``).
    lens : {"pinhole", "equiangular"}
        Camera geometry model.
    fov_deg : float or None
        Horizontal field of view; default the file's FLIR ``FieldOfView``, else the mission's
        ``camera.aperture_deg``.
    band_um : (float, float) or None
        Band limits; default the file's FLIR XMP centre wavelength +- FWHM/2, else
        :data:`DEFAULT_LWIR_BAND_UM`.
    unit, scale_k, offset_k
        For TIFFs without the tags stating them.
    utc_offset_h : float or None
        Time zone of camera clocks that state none (hours east of UTC).
    survey_id, site_name : str or None
    ground_altitude_m : float or None
        Default: median GNSS altitude + camera up offset - mission platform height.
    netd_k : float or None
    """

    frames: list[Path]
    poses: Path
    gnss: Path
    weather: Path
    soil: Path
    mission: Path
    antenna_to_camera_m: tuple[float, float, float]
    markers: Path | None = None
    blackbody: Path | None = None
    blackbody_log: Path | None = None
    station_profile: Path | None = None
    pan_zero_azimuth_deg: float = 0.0
    tilt_zero_deg: float = 0.0
    lens: str = "pinhole"
    fov_deg: float | None = None
    band_um: tuple[float, float] | None = None
    unit: str | None = None
    scale_k: float | None = None
    offset_k: float | None = None
    utc_offset_h: float | None = None
    survey_id: str | None = None
    site_name: str | None = None
    ground_altitude_m: float | None = None
    netd_k: float | None = None
    notes: list[str] = field(default_factory=list)


@dataclass(frozen=True)
class PoseRow:
    """One row of the pose table (``line`` for messages)."""

    line: int
    file: str
    frame: int
    scan: int
    position: int
    time_s: float | None
    pan_deg: float | None
    tilt_deg: float | None


def read_pose_table(path: Path) -> list[PoseRow]:
    """The pose table: ``file,frame,scan,position,time_utc,pan_deg,tilt_deg`` (header row;
    ``frame`` default 0; ``time_utc``, ``pan_deg``, ``tilt_deg`` may be empty or absent, then
    they come from the frame's tags). Errors name the file, line and column."""
    rows, seen_frame, seen_pos = [], {}, {}
    for n, rec in csv_records(path, ("file", "scan", "position"), POSE_COLUMNS):

        def get(col: str, kind, required: bool = False, line: int = n, rec: dict = rec):
            return table_value(rec, col, kind, path, line, required)

        def utc(line: int = n, rec: dict = rec) -> float | None:
            return table_time(rec, path, line)

        if not rec.get("file"):
            raise InvalidInput("empty", path, f"line {n}: file")
        row = PoseRow(n, Path(rec["file"]).name, get("frame", int) or 0,
                      get("scan", int, True), get("position", int, True), utc(),
                      get("pan_deg", float), get("tilt_deg", float))
        key = (row.file, row.frame)
        if key in seen_frame:
            raise InvalidInput(f"file {row.file} frame {row.frame} already on line "
                               f"{seen_frame[key]}", path, f"line {n}")
        if (row.scan, row.position) in seen_pos:
            raise InvalidInput(f"scan {row.scan} position {row.position} already on line "
                               f"{seen_pos[(row.scan, row.position)]}", path, f"line {n}")
        seen_frame[key], seen_pos[(row.scan, row.position)] = n, n
        rows.append(row)
    if not rows:
        raise InvalidInput("no poses", path)
    return rows


def expand_frames(sources: Sequence[str | os.PathLike]) -> list[Path]:
    """Camera files from files and folders (a folder's files sorted by name, hidden files
    and ``import.json`` skipped)."""
    out = []
    for s in map(Path, sources):
        if s.is_dir():
            out.extend(p for p in sorted(s.iterdir())
                       if p.is_file() and not p.name.startswith(".") and p.name != "import.json")
        elif s.is_file():
            out.append(s)
        else:
            raise InvalidInput("no such file or folder", s)
    if not out:
        raise InvalidInput("no camera files", ", ".join(map(str, sources)) or "FRAMES")
    names = [p.name for p in out]
    dup = next((n for n in names if names.count(n) > 1), None)
    if dup:
        raise InvalidInput("two camera files share this name; the pose table names files by "
                           "name", dup)
    return out


def radiometry_of(frame: RadiometricFrame) -> CameraRadiometry:
    """The survey radiometry of a frame (what its stored counts mean)."""
    if frame.planck is not None:
        return CameraRadiometry("flir-planck", planck=frame.planck)
    if frame.format == "temperature-tiff":
        return CameraRadiometry("linear", scale_k=TEMPERATURE_COUNT_K, offset_k=0.0)
    return CameraRadiometry("linear", scale_k=frame.linear.scale_k,
                            offset_k=frame.linear.offset_k)


def stored_counts(frame: RadiometricFrame) -> np.ndarray:
    """The frame as the survey's uint16 counts (float temperatures at 0.01 K per count; NaN
    as 0, which has no temperature)."""
    if frame.format != "temperature-tiff":
        return frame.raw
    t_k = frame.object_temperature_c().astype(np.float64) + 273.15
    c = np.where(np.isfinite(t_k), np.rint(t_k / TEMPERATURE_COUNT_K), 0.0)
    return c.astype(np.uint16)


def frame_time_s(frame: RadiometricFrame, spec: ImportSpec) -> float | None:
    """UTC epoch seconds of the frame's own time tag (None without one)."""
    t = frame.time
    if t is None:
        return None
    if t.tzinfo is None:
        if spec.utc_offset_h is None:
            raise InvalidInput("the camera time states no time zone: give time_utc in the pose "
                               "table or --utc-offset HOURS", frame.path, "DateTimeOriginal")
        return (t.replace(tzinfo=UTC).timestamp() - spec.utc_offset_h * 3600.0)
    return t.astimezone(UTC).timestamp()


@dataclass
class ImportResult:
    """What :func:`import_survey` wrote."""

    root: Path
    n_frames: int
    n_scans: int
    camera: str
    radiometry: CameraRadiometry
    notes: list[str]


def _band(frames: list[RadiometricFrame], spec: ImportSpec) -> tuple[float, float]:
    if spec.band_um is not None:
        return spec.band_um
    tags = frames[0].tags
    centre, fwhm = tags.get("XMP-FLIR:CentralWavelength"), tags.get("XMP-FLIR:WavelengthFWHM")
    try:
        if centre and fwhm and float(fwhm) > 0:
            c, f = float(centre) / 1000.0, float(fwhm) / 1000.0
            return round(c - f / 2, 3), round(c + f / 2, 3)
    except (TypeError, ValueError):
        pass
    spec.notes.append(f"band {DEFAULT_LWIR_BAND_UM[0]}-{DEFAULT_LWIR_BAND_UM[1]} um assumed "
                      "(the files state none; --band-um to set it)")
    return DEFAULT_LWIR_BAND_UM


def _fov(frames: list[RadiometricFrame], spec: ImportSpec, mission: dict) -> float:
    if spec.fov_deg is not None:
        return spec.fov_deg
    fov = frames[0].tags.get("FLIR:FieldOfView")
    try:
        if fov and 0 < float(fov) < 180:
            return float(fov)
    except (TypeError, ValueError):
        pass
    return float(mission["camera"]["aperture_deg"])


def _camera_section(frames, spec: ImportSpec, mission: dict, radiometry: CameraRadiometry
                    ) -> dict:
    h, w = frames[0].shape
    fov = _fov(frames, spec, mission)
    lo, hi = _band(frames, spec)
    cam: dict = {"model": spec.lens, "resolution": [w, h], "bit_depth": 16,
                 "bands": [{"name": "LWIR", "lambda_min_um": lo, "lambda_max_um": hi}]}
    if spec.lens == "equiangular":
        cam["aperture_deg"] = fov
    else:
        f = (w / 2.0) / math.tan(math.radians(fov) / 2.0)
        cam["intrinsics"] = {"fx": f, "fy": f, "cx": (w - 1) / 2.0, "cy": (h - 1) / 2.0,
                             "distortion": [0.0, 0.0, 0.0, 0.0, 0.0]}
    if spec.netd_k is not None:
        cam["netd_k"] = spec.netd_k
    cam["radiometry"] = {**radiometry.to_manifest(), "source_format": frames[0].format,
                         "camera_name": frames[0].camera}
    return cam


def _match(frames: list[RadiometricFrame], poses: list[PoseRow], spec: ImportSpec
           ) -> list[tuple[RadiometricFrame, PoseRow, float, float, float]]:
    """(frame, pose, time_s, pan, tilt) for every frame; every pose used exactly once."""
    by_key = {(r.file, r.frame): r for r in poses}
    used = set()
    out = []
    for fr in frames:
        key = (fr.path.name, fr.index)
        row = by_key.get(key)
        if row is None:
            raise InvalidInput(f"frame {fr.index} has no row in the pose table {spec.poses}",
                               fr.path)
        used.add(key)
        t = row.time_s if row.time_s is not None else frame_time_s(fr, spec)
        pan = row.pan_deg if row.pan_deg is not None else (
            fr.gimbal.yaw_deg if fr.gimbal else None)
        tilt = row.tilt_deg if row.tilt_deg is not None else (
            fr.gimbal.pitch_deg if fr.gimbal else None)
        for name, val in (("time_utc", t), ("pan_deg", pan), ("tilt_deg", tilt)):
            if val is None:
                raise InvalidInput(f"no {name} for {fr.path.name} frame {fr.index}: neither the "
                                   "pose table nor the file's tags give it", spec.poses,
                                   f"line {row.line}: {name}")
        out.append((fr, row, float(t), float(pan), float(tilt)))
    extra = [r for r in poses if (r.file, r.frame) not in used]
    if extra:
        r = extra[0]
        raise InvalidInput(f"file {r.file} frame {r.frame} is not among the camera files "
                           f"({len(extra)} such rows)", spec.poses, f"line {r.line}")
    return out


def _check_same_camera(frames: list[RadiometricFrame]) -> CameraRadiometry:
    first = frames[0]
    rad = radiometry_of(first)
    for fr in frames[1:]:
        if fr.shape != first.shape:
            raise InvalidInput(f"frame {fr.index} is {fr.shape[1]}x{fr.shape[0]}, the first "
                               f"camera file {first.path.name} {first.shape[1]}x"
                               f"{first.shape[0]}: one survey, one camera", fr.path)
        if radiometry_of(fr) != rad:
            raise InvalidInput(f"frame {fr.index} has a different radiometry (Planck constants "
                               f"or scale) than {first.path.name}: one survey, one camera "
                               "setting", fr.path)
    return rad


def _site(spec: ImportSpec, mission: dict):
    from clearfast_gis.survey import read_nmea

    gnss = read_nmea(spec.gnss, label=str(spec.gnss))
    ok = gnss.fix_quality > 0
    if not np.any(ok):
        raise InvalidInput("no GNSS fix", spec.gnss)
    i = int(np.flatnonzero(ok)[0])
    lat, lon = float(gnss.lat_deg[i]), float(gnss.lon_deg[i])
    alt = spec.ground_altitude_m
    if alt is None:
        alt = round(float(np.median(gnss.alt_m[ok])) + spec.antenna_to_camera_m[2]
                    - float(mission["platform"]["height_m"]), 2)
        spec.notes.append(f"ground altitude {alt:.2f} m = median GNSS altitude + camera offset "
                          "- mission platform height (--ground-altitude-m to set it)")
    return lat, lon, alt


def import_survey(spec: ImportSpec, out: str | os.PathLike, overwrite: bool = False,
                  progress: Progress = NULL_PROGRESS) -> ImportResult:
    """Build the survey folder ``out`` (see the module notes); returns what was written."""
    from clearfast_gis.cameras import blackbody_import as bbi
    from clearfast_gis.survey import (
        read_blackbody_log,
        read_markers,
        read_mission,
        read_soil_log,
        validate_survey,
        write_blackbody_frames_table,
        write_frames_table,
        write_survey_json,
        write_tiff_stack,
    )
    from clearfast_gis.survey.station_profiles import read_station_profile
    from clearfast_gis.survey.stations import PROFILE_KEY, PROFILE_NAME, read_station_table

    out = Path(out)
    if out.exists() and not (overwrite and out.is_dir()):
        raise InvalidInput("already exists (--overwrite to replace it)", out)
    mission = read_mission(spec.mission, str(spec.mission))
    profile = None if spec.station_profile is None else read_station_profile(
        spec.station_profile, str(spec.station_profile))
    read_station_table(spec.weather, profile, str(spec.weather))
    read_soil_log(spec.soil, str(spec.soil), profile)
    if spec.markers is not None:
        read_markers(spec.markers, str(spec.markers))
    poses = read_pose_table(spec.poses)
    bb_rows: list = []
    if (spec.blackbody is None) != (spec.blackbody_log is None):
        raise InvalidInput("blackbody frames need their temperature log and the log its frames "
                           "(give both --blackbody and --blackbody-log)",
                           spec.blackbody or spec.blackbody_log)
    if spec.blackbody is not None:
        read_blackbody_log(spec.blackbody_log, str(spec.blackbody_log))
        bb_rows = bbi.read_blackbody_table(spec.blackbody)
    bb_files = {r.path.resolve() for r in bb_rows}
    files = [p for p in expand_frames(spec.frames) if p.resolve() not in bb_files]
    progress.start("import", len(files))
    frames: list[RadiometricFrame] = []
    all_tags: dict = {}
    for p in files:
        if str(p) not in all_tags:  # exiftool on the next batch of files at once
            k = files.index(p)
            all_tags.update(exiftool.read_tags_many(files[k:k + TAG_BATCH]))
        frames.extend(read_frames(p, unit=spec.unit, scale_k=spec.scale_k,
                                  offset_k=spec.offset_k, tags=all_tags.pop(str(p))))
        progress.advance(1, file=p.name)
    progress.close()
    bb_frames = bbi.read_blackbody_frames(bb_rows, spec.blackbody, dict(
        unit=spec.unit, scale_k=spec.scale_k, offset_k=spec.offset_k)) if bb_rows else []
    rad = _check_same_camera(frames + [f for _r, f in bb_frames])
    matched = _match(frames, poses, spec)
    bb_matched = []
    for row, fr in bb_frames:
        t = row.time_s if row.time_s is not None else frame_time_s(fr, spec)
        if t is None:
            raise InvalidInput(f"no time_utc for {row.path.name} frame {row.frame}: neither "
                               "the table nor the file's tags give it", spec.blackbody,
                               f"line {row.line}: time_utc")
        bb_matched.append((row, fr, float(t)))
    lat, lon, ground = _site(spec, mission)
    camera = _camera_section(frames, spec, mission, rad)
    times = np.array([m[2] for m in matched] + [m[2] for m in bb_matched])
    scans = sorted({m[1].scan for m in matched})
    parent = out.resolve().parent
    parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".part", dir=parent))
    try:
        rows: dict[str, list] = {k: [] for k in ("scan", "position", "band", "time_s",
                                                 "pan_deg", "tilt_deg", "file", "page")}
        for s in scans:
            sel = sorted((m for m in matched if m[1].scan == s), key=lambda m: m[1].position)
            rel = f"frames/scan_{s:03d}_b0.tif"
            write_tiff_stack(tmp / rel, np.stack([stored_counts(m[0]) for m in sel]))
            for page, (_fr, row, t, pan, tilt) in enumerate(sel):
                for k, v in (("scan", s), ("position", row.position), ("band", 0),
                             ("time_s", t), ("pan_deg", pan), ("tilt_deg", tilt),
                             ("file", rel), ("page", page)):
                    rows[k].append(v)
        write_frames_table(tmp / "frames.csv", {k: np.asarray(v) for k, v in rows.items()})
        names = {"mission": "mission.json", "frames": "frames.csv", "gnss": "gnss.nmea",
                 "weather": "weather.dat", "soil": "soil.csv"}
        for key, src in (("mission", spec.mission), ("gnss", spec.gnss),
                         ("weather", spec.weather), ("soil", spec.soil)):
            shutil.copyfile(src, tmp / names[key])
        if bb_matched:
            stacks, bb_table = bbi.blackbody_stacks(bb_matched, stored_counts)
            for rel, stack in stacks.items():
                write_tiff_stack(tmp / rel, stack)
            write_blackbody_frames_table(tmp / bbi.FRAMES_TABLE,
                                         {k: np.asarray(v) for k, v in bb_table.items()})
            shutil.copyfile(spec.blackbody_log, tmp / bbi.LOG_NAME)
            names["blackbody_frames"], names["blackbody_log"] = bbi.FRAMES_TABLE, bbi.LOG_NAME
        if spec.markers is not None:
            shutil.copyfile(spec.markers, tmp / "markers.csv")
            names["markers"] = "markers.csv"
        if spec.station_profile is not None:
            shutil.copyfile(spec.station_profile, tmp / PROFILE_NAME)
            names[PROFILE_KEY] = PROFILE_NAME
        start = math.floor(times.min())
        manifest = {
            "format": "clearfast-survey", "format_version": 1,
            "survey_id": spec.survey_id or out.name,
            "description": f"imported from {len(files)} {frames[0].format} file(s) of "
                           f"{frames[0].camera or 'a radiometric camera'}",
            "site": {"name": spec.site_name or spec.survey_id or out.name,
                     "latitude_deg": lat, "longitude_deg": lon, "ground_altitude_m": ground},
            "time": {"start_utc": format_utc(float(start), "seconds"),
                     "end_utc": format_utc(float(max(math.ceil(times.max()), start + 1)),
                                           "seconds")},
            "camera": camera,
            "platform": {"kind": "boom_lift",
                         "antenna_to_camera_m": [float(v) for v in spec.antenna_to_camera_m],
                         "pan_zero_azimuth_deg": spec.pan_zero_azimuth_deg,
                         "tilt_zero_deg": spec.tilt_zero_deg},
            "files": names,
        }
        write_survey_json(tmp / "survey.json", manifest)
        report = validate_survey(tmp)
        if not report.valid:
            raise InvalidInput(f"the imported survey is not valid: {report.problems[0].line()}",
                               out)
        if out.exists():
            shutil.rmtree(out)
        os.replace(tmp, out)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return ImportResult(out, len(frames), len(scans), frames[0].camera, rad, spec.notes)

