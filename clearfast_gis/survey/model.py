"""The survey folder as an object: manifest, bands, frames table and raw frame access."""

from __future__ import annotations

import functools
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey.manifest import read_mission, read_survey_json, resolve_inside
from clearfast_gis.survey.tables import (
    BlackbodyFramesTable,
    FramesTable,
    read_blackbody_frames_table,
    read_frames_table,
)
from clearfast_gis.survey.tiff import read_tiff_stack
from clearfast_gis.timeutil import parse_utc

MANIFEST_NAME = "survey.json"


@dataclass(frozen=True)
class Band:
    """A spectral band of the camera: name and wavelength limits in micrometres."""

    name: str
    lambda_min_um: float
    lambda_max_um: float


class Survey:
    """A survey folder whose ``survey.json`` has been validated.

    Use :func:`read_survey` to open one. Tables and logs are read lazily on first use.

    Attributes
    ----------
    root : Path
        The survey folder.
    manifest : dict
        The validated ``survey.json`` content.
    bands : list of Band
        Spectral bands, in band-index order.
    """

    def __init__(self, root: Path, manifest: dict) -> None:
        self.root = Path(root)
        self.manifest = manifest
        self.bands = [Band(b["name"], float(b["lambda_min_um"]), float(b["lambda_max_um"]))
                      for b in manifest["camera"]["bands"]]

    def __repr__(self) -> str:
        return f"Survey({str(self.root)!r}, id={self.manifest['survey_id']!r})"

    # -- files ----------------------------------------------------------------------------
    def path(self, key: str) -> Path:
        """Absolute path of ``files.<key>`` (checked to stay inside the folder)."""
        files = self.manifest["files"]
        if key not in files:
            raise InvalidInput("missing", MANIFEST_NAME, f"files.{key}")
        return resolve_inside(self.root, files[key], MANIFEST_NAME, f"files.{key}")

    def label(self, key: str) -> str:
        """The name of ``files.<key>`` as written in the manifest (for messages)."""
        return self.manifest["files"].get(key, key)

    def file_path(self, rel: str, label: str, field: str) -> Path:
        """Absolute path of a file named inside a table (checked to stay inside the folder)."""
        return resolve_inside(self.root, rel, label, field)

    # -- metadata -------------------------------------------------------------------------
    @property
    def start_s(self) -> float:
        """``time.start_utc`` as UTC epoch seconds."""
        return parse_utc(self.manifest["time"]["start_utc"])

    @property
    def end_s(self) -> float:
        """``time.end_utc`` as UTC epoch seconds."""
        return parse_utc(self.manifest["time"]["end_utc"])

    @property
    def resolution(self) -> tuple[int, int]:
        """Frame size (W, H) in pixels."""
        w, h = self.manifest["camera"]["resolution"]
        return int(w), int(h)

    @functools.cached_property
    def camera(self):
        """The geometry camera model (``clearfast_gis.geometry.camera_from_manifest``)."""
        from clearfast_gis.geometry import camera_from_manifest

        return camera_from_manifest(self.manifest["camera"])

    @functools.cached_property
    def radiometry(self):
        """The camera's own calibration (``camera.radiometry``, a
        :class:`~clearfast_gis.radiometry.camera.CameraRadiometry`), or None for detector counts
        calibrated by the blackbodies."""
        from clearfast_gis.radiometry.camera import CameraRadiometry

        doc = self.manifest["camera"].get("radiometry")
        return None if doc is None else CameraRadiometry.from_manifest(doc, MANIFEST_NAME)

    @functools.cached_property
    def station_profile(self):
        """The station profile ``files.station_profile`` names (a
        :class:`~clearfast_gis.survey.station_profiles.StationProfile`), or None."""
        from clearfast_gis.survey.stations import survey_station_profile

        return survey_station_profile(self.root, self.manifest)

    def use_tables(self, frames: FramesTable | None = None,
                   blackbody_frames: BlackbodyFramesTable | None = None) -> None:
        """Take the frame tables as :func:`~clearfast_gis.survey.validate.validate_survey`
        parsed them (its ``report.logs``) instead of parsing the files again; None leaves a
        table to be read when first asked for."""
        for name, table in (("frames", frames), ("blackbody_frames", blackbody_frames)):
            if table is not None:
                self.__dict__[name] = table

    def use_station_profile(self, profile) -> None:
        """Read the weather and soil logs with ``profile`` (a profile given on the command
        line) instead of the one ``survey.json`` names."""
        self.__dict__["station_profile"] = profile

    @functools.cached_property
    def mission(self) -> dict:
        """The validated ``mission.json``."""
        return read_mission(self.path("mission"), self.label("mission"))

    @functools.cached_property
    def frames(self) -> FramesTable:
        """The frames table (``frames.csv``)."""
        return read_frames_table(self.path("frames"), self.label("frames"))

    @functools.cached_property
    def blackbody_frames(self) -> BlackbodyFramesTable:
        """The blackbody frames table (``blackbody/frames.csv``)."""
        return read_blackbody_frames_table(self.path("blackbody_frames"),
                                           self.label("blackbody_frames"))

    @property
    def scans(self) -> np.ndarray:
        """Sorted scan numbers present in the frames table, int64."""
        return np.unique(self.frames.scan)

    @property
    def positions(self) -> np.ndarray:
        """Sorted position indices present in the frames table, int64."""
        return np.unique(self.frames.position)

    def band_index(self, band: int | str) -> int:
        """Band index from an index or a band name."""
        if isinstance(band, str):
            for i, b in enumerate(self.bands):
                if b.name == band:
                    return i
            raise InvalidInput(f"no band named {band!r}", MANIFEST_NAME, "camera.bands")
        b = int(band)
        if not 0 <= b < len(self.bands):
            raise InvalidInput(f"band index {b} out of range ({len(self.bands)} bands)",
                               MANIFEST_NAME, "camera.bands")
        return b

    # -- pixels ---------------------------------------------------------------------------
    def scan_rows(self, scan: int, band: int | str) -> np.ndarray:
        """Row indices of the frames of ``scan`` and ``band``, ordered by position."""
        fr = self.frames
        b = self.band_index(band)
        idx = np.flatnonzero((fr.scan == int(scan)) & (fr.band == b))
        return idx[np.argsort(fr.position[idx], kind="stable")]

    def scan_positions(self, scan: int, band: int | str) -> np.ndarray:
        """Position indices of the frames :meth:`read_scan` returns, in the same order."""
        return self.frames.position[self.scan_rows(scan, band)]

    def _read_rows(self, rows: np.ndarray, label: str) -> np.ndarray:
        fr = self.frames
        if rows.size == 0:
            w, h = self.resolution
            return np.empty((0, h, w), dtype=np.uint16)
        files = fr.file[rows]
        if np.all(files == files[0]):
            path = self.file_path(files[0], label, "file")
            return read_tiff_stack(path, fr.page[rows], files[0])
        out = None
        for k, r in enumerate(rows):
            page = read_tiff_stack(self.file_path(fr.file[r], label, "file"),
                                   fr.page[r:r + 1], fr.file[r])[0]
            if out is None:
                out = np.empty((rows.size, *page.shape), dtype=page.dtype)
            out[k] = page
        return out

    def read_scan(self, scan: int, band: int | str) -> np.ndarray:
        """Raw counts of all frames of ``scan`` in ``band``, ordered by position.

        Returns
        -------
        uint16 (P, H, W)
            Memory-mapped (read-only) when the TIFF is uncompressed and the pages are in
            position order; P = len(:meth:`scan_positions`).
        """
        rows = self.scan_rows(scan, band)
        if rows.size == 0:
            raise InvalidInput(f"no frames for scan {scan} band {band}", self.label("frames"))
        return self._read_rows(rows, self.label("frames"))

    def read_frame(self, scan: int, position: int, band: int | str) -> np.ndarray:
        """Raw counts of one frame, uint16 (H, W)."""
        fr = self.frames
        b = self.band_index(band)
        rows = np.flatnonzero((fr.scan == int(scan)) & (fr.position == int(position)) &
                              (fr.band == b))
        if rows.size == 0:
            raise InvalidInput(f"no frame for scan {scan} position {position} band {band}",
                               self.label("frames"))
        return np.asarray(self._read_rows(rows[:1], self.label("frames"))[0])


def read_survey(path: str | os.PathLike) -> Survey:
    """Open a survey folder: read and validate ``survey.json``.

    Parameters
    ----------
    path : path
        The survey folder (or its ``survey.json``).

    Raises
    ------
    InvalidInput
        ``survey.json: <json path>: <message>`` for the first schema problem, or when the
        folder or manifest is missing. Run :func:`validate_survey` for all problems.
    """
    p = Path(path)
    if p.is_file() and p.name == MANIFEST_NAME:
        p = p.parent
    if not p.exists():
        raise InvalidInput("survey folder not found", str(p))
    if not p.is_dir():
        raise InvalidInput("expected a survey folder", str(p))
    manifest = read_survey_json(p / MANIFEST_NAME, MANIFEST_NAME)
    return Survey(p, manifest)


@dataclass(frozen=True)
class BlackbodyEvent:
    """Mean blackbody images of one calibration event and band.

    Attributes
    ----------
    event, band : int
        Event number and band index.
    time_s : float
        Mid time of the event (mean of all its frame times), UTC epoch seconds.
    bb1_time_s, bb2_time_s : float
        Mean frame time of each blackbody.
    bb1_mean, bb2_mean : float64 (H, W)
        Mean raw counts of the heated (1) and ambient (2) blackbody frames.
    n_bb1, n_bb2 : int
        Frames averaged.
    """

    event: int
    band: int
    time_s: float
    bb1_time_s: float
    bb2_time_s: float
    bb1_mean: np.ndarray
    bb2_mean: np.ndarray
    n_bb1: int
    n_bb2: int


def read_blackbody_frames(survey: Survey) -> list[BlackbodyEvent]:
    """Mean blackbody images per calibration event and band, sorted by (event, band).

    Raises
    ------
    InvalidInput
        When an event/band lacks frames of one of the two blackbodies.
    """
    tab = survey.blackbody_frames
    label = survey.label("blackbody_frames")
    out: list[BlackbodyEvent] = []
    keys = sorted({(int(e), int(b)) for e, b in zip(tab.event, tab.band, strict=True)})
    for ev, band in keys:
        sel = (tab.event == ev) & (tab.band == band)
        means, times, counts = [], [], []
        for bb in (1, 2):
            rows = np.flatnonzero(sel & (tab.blackbody == bb))
            if rows.size == 0:
                raise InvalidInput(f"event {ev} band {band}: no frames of blackbody {bb}", label)
            acc = np.zeros(survey.resolution[::-1], dtype=np.float64)
            files = tab.file[rows]
            for f in np.unique(files):
                r = rows[files == f]
                stack = read_tiff_stack(survey.file_path(f, label, "file"), tab.page[r], f)
                if stack.shape[1:] != acc.shape:
                    raise InvalidInput(f"frames are {stack.shape[2]}x{stack.shape[1]}, camera is "
                                       f"{acc.shape[1]}x{acc.shape[0]}", f)
                acc += stack.sum(axis=0, dtype=np.float64)
            means.append(acc / rows.size)
            times.append(float(tab.time_s[rows].mean()))
            counts.append(int(rows.size))
        out.append(BlackbodyEvent(ev, band, float(tab.time_s[sel].mean()), times[0], times[1],
                                  means[0], means[1], counts[0], counts[1]))
    return out
