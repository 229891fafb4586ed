"""The digital twin's frames as a radiometric camera writes them (``simulate --camera-format``).

A radiometric camera calibrates its own detector: the twin's detector model (gain and offset
drifting in time, :mod:`clearfast_gis.simulate.detector`) is inverted exactly at each frame's
time, giving the at-camera band radiance the camera measured (with the detector's noise), and
that as the at-sensor blackbody temperature is written in the camera's format:

- ``tlinear``: 16-bit TIFF, 0.01 K per count, offset 0 K (a FLIR Boson/Tau in TLinear
  high-resolution mode), with GDAL scale and unit tags;
- ``celsius-tiff``: float32 TIFF of degrees C with the GDAL unit tag ``degC``;
- ``flir-rjpeg``: FLIR radiometric JPEG (:mod:`clearfast_gis.cameras.flir_write`), raw signal
  from :data:`TWIN_FLIR_PLANCK` and the capture time in the FFF record (the pose table leaves
  the time empty, so the import takes it from the files), with field object parameters
  (:data:`TWIN_FLIR_PARAMS`) that the chain must not use.

The survey folder then becomes a camera import folder (``docs/import.md``): the camera files
in ``camera/``, ``poses.csv`` (file, frame, scan, position, time, pan, tilt), the field logs,
``mission.json``, ``markers.csv``, ``import.json`` and ``truth/``; the detector counts, the
blackbody frames and ``survey.json`` are removed (``clearfast import`` rebuilds the survey).
"""

from __future__ import annotations

import csv
import io
import json
import shutil
from pathlib import Path

import numpy as np

from clearfast_gis.atomic import write_text
from clearfast_gis.cameras.tiff import write_tiff
from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry.atmosphere import (
    FLIR_A1_PER_SQRT_M,
    FLIR_A2_PER_SQRT_M,
    FLIR_B1,
    FLIR_B2,
    FLIR_X,
)
from clearfast_gis.radiometry.flir import FlirObjectParams, FlirPlanck
from clearfast_gis.timeutil import format_utc
from clearfast_gis.units import ZERO_CELSIUS_K

CAMERA_FORMATS = ("flir-rjpeg", "tlinear", "celsius-tiff")
"""Formats the twin writes."""
TLINEAR_K_PER_COUNT = 0.01
"""FLIR TLinear high resolution, kelvin per count."""
TWIN_FLIR_PLANCK = FlirPlanck(r1=17096.453125, r2=0.0480847954750061, b=1428.0, f=1.0,
                              o=-370.0)
"""The twin's FLIR calibration (a Zenmuse XT core's constants: about 50 counts per K)."""
TWIN_FLIR_PARAMS = FlirObjectParams(
    emissivity=0.95, reflected_c=20.0, atmosphere_c=20.0, distance_m=15.0, rh_pct=50.0,
    window_c=20.0, window_transmission=1.0, x=FLIR_X, alpha1=FLIR_A1_PER_SQRT_M,
    alpha2=FLIR_A2_PER_SQRT_M, beta1=FLIR_B1, beta2=FLIR_B2)
"""Object parameters the twin's FLIR files state (as a camera set up in the field would);
the chain does not use them, ``thermal-frame`` does."""


LWIR_BAND = ("LWIR", 7.5, 13.5)
"""The broadband long-wave band of the simulated radiometric camera (name, um, um)."""


def radiometric_camera_config(config):
    """The scenario with one broadband LWIR band (a radiometric camera has no filter wheel)."""
    from dataclasses import replace

    from clearfast_gis.simulate.config import Band

    return replace(config, bands=(Band(*LWIR_BAND),))


def write_frame(folder: Path, stem: str, t_k: np.ndarray, fmt: str, time_s: float) -> str:
    """Write one frame's at-sensor temperature (kelvin, (H, W); NaN where unknown) as a camera
    file ``folder/stem.<suffix>``; returns the file name."""
    from datetime import UTC, datetime

    if fmt == "tlinear":
        counts = np.clip(np.rint(np.nan_to_num(t_k, nan=0.0) / TLINEAR_K_PER_COUNT), 0, 65535)
        write_tiff(folder / f"{stem}.tif", counts.astype(np.uint16), "K",
                   scale=TLINEAR_K_PER_COUNT)
        return f"{stem}.tif"
    if fmt == "celsius-tiff":
        write_tiff(folder / f"{stem}.tif", (t_k - ZERO_CELSIUS_K).astype(np.float32), "degC")
        return f"{stem}.tif"
    if fmt == "flir-rjpeg":
        from clearfast_gis.cameras.flir_write import fff_bytes, write_rjpeg

        sig = TWIN_FLIR_PLANCK.signal(np.nan_to_num(t_k, nan=1.0))
        raw = np.clip(np.rint(sig), 0, 65535).astype(np.uint16)
        lo, hi = np.percentile(raw, [1, 99])
        preview = np.clip((raw - lo) / max(hi - lo, 1.0) * 255.0, 0, 255).astype(np.uint8)
        record = fff_bytes(raw, TWIN_FLIR_PLANCK, TWIN_FLIR_PARAMS,
                           datetime.fromtimestamp(time_s, UTC), model="clearfast twin")
        write_rjpeg(folder / f"{stem}.jpg", record, preview)
        return f"{stem}.jpg"
    raise InvalidInput(f"unknown camera format {fmt!r} (one of {', '.join(CAMERA_FORMATS)})",
                       field="camera_format")


def write_camera_folder(root: Path, twin, fmt: str) -> None:
    """Turn the simulated raw-count survey ``root`` into a camera import folder (module notes).

    Parameters
    ----------
    root : Path
        A survey folder just written by :func:`~clearfast_gis.simulate.run.simulate_survey`
        with one band.
    twin : Twin
        Its twin (detectors, band tables).
    fmt : str
        One of :data:`CAMERA_FORMATS`.
    """
    from clearfast_gis.survey import read_survey, read_tiff_stack

    if fmt not in CAMERA_FORMATS:
        raise InvalidInput(f"unknown camera format {fmt!r} (one of "
                           f"{', '.join(CAMERA_FORMATS)})", field="camera_format")
    survey = read_survey(root)
    if len(survey.bands) != 1:
        raise InvalidInput("radiometric cameras have one band; the scenario has "
                           f"{len(survey.bands)}", field="bands")
    fr = survey.frames
    det, table = twin.detectors[0], twin.tables[0]
    (root / "camera").mkdir(exist_ok=True)
    buf = io.StringIO()
    out = csv.writer(buf, lineterminator="\n")
    out.writerow(["file", "frame", "scan", "position", "time_utc", "pan_deg", "tilt_deg"])
    for rel in sorted(set(fr.file)):
        rows = np.flatnonzero(fr.file == rel)
        stack = read_tiff_stack(root / rel, fr.page[rows])
        for k, i in enumerate(rows):
            g, o = det.gain_offset(float(fr.time_s[i]))
            radiance = (stack[k].astype(np.float32) - o) / g
            t_k = table.temperature(radiance).astype(np.float64)
            name = write_frame(root / "camera", f"scan_{fr.scan[i]:03d}_pos_{fr.position[i]:03d}",
                               t_k, fmt, float(fr.time_s[i]))
            # FLIR files carry their own time: the pose table leaves it to them
            when = "" if fmt == "flir-rjpeg" else format_utc(float(fr.time_s[i]))
            out.writerow([name, 0, int(fr.scan[i]), int(fr.position[i]), when,
                          f"{fr.pan_deg[i]:.6f}", f"{fr.tilt_deg[i]:.6f}"])
    write_text(root / "poses.csv", buf.getvalue())
    m = survey.manifest
    cam, band = m["camera"], m["camera"]["bands"][0]
    layout = {"frames": "camera", "poses": "poses.csv", "gnss": m["files"]["gnss"],
              "weather": m["files"]["weather"], "soil": m["files"]["soil"],
              "mission": m["files"]["mission"], "markers": m["files"]["markers"],
              "antenna_to_camera_m": m["platform"]["antenna_to_camera_m"],
              "pan_zero_azimuth_deg": m["platform"]["pan_zero_azimuth_deg"],
              "tilt_zero_deg": m["platform"]["tilt_zero_deg"], "lens": cam["model"],
              "fov_deg": cam["aperture_deg"],
              "band_um": [band["lambda_min_um"], band["lambda_max_um"]],
              "netd_k": cam.get("netd_k"), "survey_id": m["survey_id"],
              "site_name": m["site"]["name"],
              "ground_altitude_m": m["site"]["ground_altitude_m"]}
    write_text(root / "import.json", json.dumps(layout, indent=1) + "\n")
    for rel in ("frames", "blackbody"):
        shutil.rmtree(root / rel)
    for rel in ("frames.csv", "survey.json"):
        (root / rel).unlink()
