"""The station set-up of an acquisition (``setup.json``) and the survey manifest it gives.

``setup.json`` (schema ``setup.schema.json``) holds what the operator knows before the survey
besides the mission: the site, CRS, camera and platform entries of ``survey.json``, where the
two calibration blackbodies are (pan/tilt angles) and how many frames each gets per scan, the
thermocouple depths, the surveyed markers and the settle time::

    {"format": "clearfast-setup", "format_version": 1, "survey_id": "buffer-zone-2026-11-15",
     "site": {"name": "...", "latitude_deg": 35.17, "longitude_deg": 33.36,
              "ground_altitude_m": 160.0},
     "crs": {"epsg": 32636},
     "camera": {"model": "equiangular", "resolution": [160, 128], "aperture_deg": 24.0,
                "bit_depth": 14, "netd_k": 0.05, "bands": [...]},
     "platform": {"kind": "boom_lift", "antenna_to_camera_m": [0.0, 0.0, -0.4],
                  "pan_zero_azimuth_deg": 0.0, "tilt_zero_deg": 0.0},
     "blackbodies": {"heated": {"pan_deg": 150.0, "tilt_deg": 20.0},
                     "ambient": {"pan_deg": -150.0, "tilt_deg": 20.0}, "frames": 10},
     "soil_depths_m": [0.02, 0.05, 0.10, 0.20, 0.50], "markers": "markers.csv",
     "settle_s": 0.5}

The survey parts are checked against ``survey.schema.json`` (errors name ``setup.json`` and
the field, as ``setup.json: camera.resolution: expected 2 integers``).
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from clearfast_gis.acquire.mission import Blackbodies
from clearfast_gis.acquire.soil import DEFAULT_DEPTHS_M
from clearfast_gis.errors import InvalidInput, more_problems
from clearfast_gis.survey._text import read_text
from clearfast_gis.survey.manifest import DEFAULT_FILES, manifest_problems, parse_json
from clearfast_gis.timeutil import format_utc

SETUP_NAME = "setup.json"
#: the parts of setup.json copied into survey.json
SURVEY_KEYS = ("survey_id", "description", "site", "crs", "camera", "platform")


@dataclass(frozen=True)
class StationSetup:
    """A read ``setup.json``.

    Attributes
    ----------
    document : dict
        The file's content.
    blackbodies : Blackbodies
        Blackbody positions (degrees) and frames per blackbody and scan.
    soil_depths_m : tuple of float
        Thermocouple depths, metres, in channel order.
    markers : Path or None
        The markers CSV to copy into the survey.
    settle_s : float
        Wait after each move, seconds.
    label : str
        The file's name in error messages.
    """

    document: dict
    blackbodies: Blackbodies
    soil_depths_m: tuple[float, ...]
    markers: Path | None
    settle_s: float
    label: str = SETUP_NAME

    def manifest(self, survey_id: str, start_s: float, end_s: float) -> dict:
        """``survey.json`` for an acquisition from ``start_s`` to ``end_s`` (UTC epoch s)."""
        doc = {"format": "clearfast-survey", "format_version": 1, "survey_id": survey_id}
        doc.update({k: self.document[k] for k in SURVEY_KEYS if k in self.document})
        doc["time"] = {"start_utc": format_utc(start_s, "seconds"),
                       "end_utc": format_utc(end_s, "seconds")}
        files = dict(DEFAULT_FILES)
        if self.markers is None:
            del files["markers"]
        doc["files"] = files
        return doc


def setup_document(manifest: dict, blackbodies: Blackbodies, settle_s: float = 0.5,
                   soil_depths_m: tuple[float, ...] = DEFAULT_DEPTHS_M,
                   markers: str | None = "markers.csv") -> dict:
    """A ``setup.json`` document from a survey manifest's parts (the device simulators write
    the twin's)."""
    doc = {"format": "clearfast-setup", "format_version": 1}
    doc.update({k: manifest[k] for k in SURVEY_KEYS if k in manifest})
    doc["blackbodies"] = {
        "heated": {"pan_deg": blackbodies.heated[0], "tilt_deg": blackbodies.heated[1]},
        "ambient": {"pan_deg": blackbodies.ambient[0], "tilt_deg": blackbodies.ambient[1]},
        "frames": blackbodies.frames}
    doc["soil_depths_m"] = [float(d) for d in soil_depths_m]
    if markers is not None:
        doc["markers"] = markers
    doc["settle_s"] = float(settle_s)
    return doc


def read_setup(path: str | os.PathLike, label: str | None = None) -> StationSetup:
    """Read and check ``setup.json``.

    Raises
    ------
    InvalidInput
        ``setup.json: <field>: <problem>`` for the first problem found (and how many more).
    """
    path = Path(path)
    label = str(path) if label is None else label
    doc = parse_json(read_text(path, label), label)
    problems = manifest_problems(doc, "setup")
    if not problems:
        probe = StationSetup(doc, Blackbodies((0.0, 0.0), (0.0, 0.0)), (), None, 0.0)
        problems = [(f, m) for f, m in manifest_problems(
            probe.manifest("probe", 0.0, 1.0), "survey")
            if f.split(".")[0] in SURVEY_KEYS or f == "(top level)"]
    if problems:
        field, msg = problems[0]
        more = more_problems(len(problems))
        raise InvalidInput(msg + more, label, field)
    bb = doc["blackbodies"]
    blackbodies = Blackbodies((float(bb["heated"]["pan_deg"]), float(bb["heated"]["tilt_deg"])),
                              (float(bb["ambient"]["pan_deg"]),
                               float(bb["ambient"]["tilt_deg"])), int(bb.get("frames", 10)))
    depths = tuple(float(d) for d in doc.get("soil_depths_m", DEFAULT_DEPTHS_M))
    if len({f"{d:.3f}" for d in depths}) != len(depths):
        raise InvalidInput("two thermocouples at the same depth", label, "soil_depths_m")
    markers = None
    if "markers" in doc:
        markers = path.parent / doc["markers"]
        if not markers.is_file():
            raise InvalidInput(f"{doc['markers']!r} not found beside {path.name}", label,
                               "markers")
    return StationSetup(doc, blackbodies, depths, markers, float(doc.get("settle_s", 0.5)),
                        label)
