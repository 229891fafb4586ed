"""The digital twin's frames as a radiometric camera writes them (``simulate --camera-format``).

A radiometric camera calibrates its own detector: the twin's detector model (gain and offset
drifting in time, :mod:`clearfast_gis.simulate.detector`) is inverted exactly at each frame's
time, giving the at-camera band radiance the camera measured (with the detector's noise), and
that as the at-sensor blackbody temperature is written in the camera's format:

- ``tlinear``: 16-bit TIFF, 0.01 K per count, offset 0 K (a FLIR Boson/Tau in TLinear
  high-resolution mode), with GDAL scale and unit tags;
- ``celsius-tiff``: float32 TIFF of degrees C with the GDAL unit tag ``degC``.

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
from clearfast_gis.timeutil import format_utc
from clearfast_gis.units import ZERO_CELSIUS_K

CAMERA_FORMATS = ("tlinear", "celsius-tiff")
"""Formats the twin writes."""
TLINEAR_K_PER_COUNT = 0.01
"""FLIR TLinear high resolution, kelvin per count."""


LWIR_BAND = ("LWIR", 7.5, 13.5)
"""The broadband long-wave band of the simulated radiometric camera (name, um, um)."""


def radiometric_camera_config(config):
    """The scenario with one broadband LWIR band (a radiometric camera has no filter wheel)."""
    from dataclasses import replace

    from clearfast_gis.simulate.config import Band

    return replace(config, bands=(Band(*LWIR_BAND),))


def encode(t_k: np.ndarray, fmt: str) -> tuple[np.ndarray, dict]:
    """One frame's at-sensor temperature (kelvin, (H, W)) in a camera format: the array and
    the :func:`~clearfast_gis.cameras.tiff.write_tiff` keyword arguments."""
    if fmt == "tlinear":
        counts = np.clip(np.rint(np.nan_to_num(t_k, nan=0.0) / TLINEAR_K_PER_COUNT), 0, 65535)
        return counts.astype(np.uint16), {"unit": "K", "scale": TLINEAR_K_PER_COUNT}
    if fmt == "celsius-tiff":
        return (t_k - ZERO_CELSIUS_K).astype(np.float32), {"unit": "degC"}
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
        encode(np.zeros((1, 1)), fmt)  # raises the one-line error
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
    suffix = ".tif"
    for rel in sorted(set(fr.file)):
        rows = np.flatnonzero(fr.file == rel)
        stack = read_tiff_stack(root / rel, fr.page[rows])
        for k, i in enumerate(rows):
            g, o = det.gain_offset(float(fr.time_s[i]))
            radiance = (stack[k].astype(np.float32) - o) / g
            values, kw = encode(table.temperature(radiance).astype(np.float64), fmt)
            name = f"scan_{fr.scan[i]:03d}_pos_{fr.position[i]:03d}{suffix}"
            write_tiff(root / "camera" / name, values, **kw)
            out.writerow([name, 0, int(fr.scan[i]), int(fr.position[i]),
                          format_utc(float(fr.time_s[i])), f"{fr.pan_deg[i]:.6f}",
                          f"{fr.tilt_deg[i]:.6f}"])
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
