"""Thermal camera frame capture behind one small interface, and the drop-folder adapter.

A camera is anything with ``capture() -> Exposure`` (one triggered exposure: every band of a
filter-wheel or multi-sensor camera, raw counts) and ``close()``. The mission runner knows
nothing else of it.

:class:`DropFolderCamera` talks to a camera through a folder (the hot folder of the camera
vendor's recording software, or a small bridge beside the camera's SDK; the digital twin's
camera serves one too, :class:`DropFolderServer`). Protocol, in folder ``DIR``:

1. the adapter writes ``DIR/request.json`` (atomically: temporary name, then rename)::

       {"session": "5f1c...", "sequence": 12, "requested_utc": "2026-11-15T06:00:03.250Z"}

2. the camera side exposes and writes ``DIR/frame_000012.tif`` (atomically, e.g. as
   ``.frame_000012.tif.part`` then renamed): one uint16 page per band, (H, W) each, and
   optionally, as the first page's ImageDescription, JSON with the exposure time of each
   band, ``{"time_utc": ["2026-11-15T06:00:03.300Z", "2026-11-15T06:00:03.700Z"]}``;
3. the adapter reads the frame and deletes it.

A radiometric camera writes its own file instead, under the same name with its own suffix:
``frame_000012.jpg`` (FLIR R-JPEG), ``.fff``, or ``.tif`` as a TLinear or temperature TIFF
(recognised by its GDAL unit tag or float samples). It is read by
:func:`clearfast_gis.cameras.read_frames` (one frame, one broadband band); the exposure then
carries the camera's own radiometry and the time the file states (``docs/import.md``).

A frame that does not arrive within the timeout raises :class:`CameraTimeout`; frames left by
an earlier session are deleted when the adapter opens the folder, and a late frame of an
earlier request is never taken for the current one (the sequence number is in its name).

Camera specifications on the command line: ``drop:DIR`` or ``drop:DIR,timeout=S``.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import secrets
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

import numpy as np
import tifffile

from clearfast_gis.errors import ClearfastError
from clearfast_gis.timeutil import format_utc, parse_utc

REQUEST_NAME = "request.json"
_FRAME = re.compile(r"^frame_(\d+)\.(tif|jpg|jpeg|fff)$", re.IGNORECASE)
RADIOMETRIC_SUFFIXES = (".jpg", ".jpeg", ".fff")
"""Drop-frame suffixes of radiometric camera files (a ``.tif`` is one by its tags)."""


class CameraError(ClearfastError):
    """A camera that cannot be reached or returns an unusable frame (the spec is the path)."""


class CameraTimeout(CameraError):
    """No frame within the timeout."""


@dataclass(frozen=True)
class Exposure:
    """One triggered exposure.

    Attributes
    ----------
    counts : uint16 (B, H, W)
        Raw detector counts, one image per band.
    time_s : tuple of float, optional
        UTC epoch seconds of each band's exposure from the camera's clock; None when the
        camera does not say (the runner then uses the trigger time).
    radiometry : CameraRadiometry, optional
        A radiometric camera's own calibration of ``counts``
        (:mod:`clearfast_gis.radiometry.camera`); None for detector counts.
    """

    counts: np.ndarray
    time_s: tuple[float, ...] | None = None
    radiometry: object = None


class Camera(Protocol):
    """What the mission runner needs of a camera."""

    def capture(self) -> Exposure:
        """Trigger one exposure and return it."""
        ...

    def close(self) -> None:
        """Release the camera."""
        ...


def as_exposure(frame: object, source: str = "camera") -> Exposure:
    """An :class:`Exposure` from an exposure or an (H, W) / (B, H, W) uint16 array.

    Raises
    ------
    CameraError
        For anything else.
    """
    if isinstance(frame, Exposure):
        counts, times = np.asarray(frame.counts), frame.time_s
    else:
        counts, times = np.asarray(frame), None
    if counts.dtype != np.uint16 or counts.ndim not in (2, 3):
        raise CameraError(f"camera returned a {counts.shape} {counts.dtype} array, expected "
                          "(H, W) or (B, H, W) uint16", source)
    if counts.ndim == 2:
        counts = counts[None]
    if times is not None and len(times) != counts.shape[0]:
        raise CameraError(f"camera gave {len(times)} exposure times for {counts.shape[0]} "
                          "bands", source)
    return Exposure(counts, None if times is None else tuple(float(t) for t in times),
                    getattr(frame, "radiometry", None))


class CallableCamera:
    """A camera from a plain function returning (H, W) or (B, H, W) uint16 arrays."""

    def __init__(self, grab: Callable[[], object]) -> None:
        self.grab = grab

    def capture(self) -> Exposure:
        """Call the function once."""
        return as_exposure(self.grab())

    def close(self) -> None:
        """Nothing to release."""


def frame_name(sequence: int) -> str:
    """File name of the frame answering request ``sequence``: ``frame_000012.tif``."""
    return f"frame_{int(sequence):06d}.tif"


def write_drop_frame(folder: str | os.PathLike, sequence: int, exposure: Exposure) -> Path:
    """The camera side: write the frame of request ``sequence`` atomically (bands as pages,
    exposure times in the description)."""
    final = Path(folder) / frame_name(sequence)
    tmp = final.with_name(f".{final.name}.part")
    desc = None if exposure.time_s is None else json.dumps(
        {"time_utc": [format_utc(t) for t in exposure.time_s]})
    tifffile.imwrite(tmp, np.asarray(exposure.counts, np.uint16), photometric="minisblack",
                     description=desc, metadata=None)
    os.replace(tmp, final)
    return final


def read_drop_frame(path: str | os.PathLike) -> Exposure:
    """Read a frame written by the camera side (see the module docstring): the toolkit's
    counts TIFF, or a radiometric camera's file.

    Raises
    ------
    CameraError
        For a file that is not a uint16 TIFF or whose description holds bad times, or a
        radiometric file the camera readers refuse.
    """
    if Path(path).suffix.lower() in RADIOMETRIC_SUFFIXES or _is_radiometric_tiff(path):
        return read_radiometric_frame(path)
    try:
        with tifffile.TiffFile(path) as tif:
            if not len(tif.pages):
                raise ValueError("no image in the file")
            counts = tif.asarray()
            desc = tif.pages[0].description
    except Exception as exc:  # tifffile raises many kinds on corrupt input
        msg = " ".join(str(exc).split())[:120] or type(exc).__name__
        raise CameraError(f"unreadable frame ({msg})", path) from None
    times = None
    if desc and desc.lstrip().startswith("{"):
        try:
            doc = json.loads(desc)
            if "time_utc" in doc:
                times = tuple(parse_utc(t) for t in doc["time_utc"])
        except (ValueError, TypeError, AttributeError) as exc:
            raise CameraError(f"bad exposure times in the description ({exc})", path) from None
    return as_exposure(Exposure(counts, times), str(path))


def _is_radiometric_tiff(path: str | os.PathLike) -> bool:
    """A TIFF with float samples or a GDAL unit tag (a TLinear or temperature TIFF)."""
    try:
        with tifffile.TiffFile(path) as tif:
            page = tif.pages[0]
            return page.dtype.kind == "f" or "<Item name=\"UNITTYPE\"" in str(
                page.tags.get("GDAL_METADATA").value if "GDAL_METADATA" in page.tags else "")
    except Exception:  # unreadable: read_drop_frame reports it
        return False


def read_radiometric_frame(path: str | os.PathLike) -> Exposure:
    """A radiometric camera's file as an exposure: the survey's counts of its one frame, the
    camera's radiometry, and the time the file states (UTC; None without a zone)."""
    from datetime import UTC

    from clearfast_gis.cameras import read_frames
    from clearfast_gis.cameras.survey_import import radiometry_of, stored_counts

    try:
        frames = read_frames(path)
    except ClearfastError as exc:
        raise CameraError(exc.message, path) from None
    if len(frames) != 1:
        raise CameraError(f"{len(frames)} frames in one drop file, expected 1", path)
    fr = frames[0]
    t = fr.time
    times = None if t is None or t.tzinfo is None else (t.astimezone(UTC).timestamp(),)
    return Exposure(stored_counts(fr)[None], times, radiometry_of(fr))


def _replace_text(path: Path, text: str) -> None:
    """Write ``text`` under a temporary name and rename it over ``path`` (no fsync: a request
    is a message, not a record)."""
    tmp = path.with_name(f".{path.name}.part")
    try:
        tmp.write_text(text)
        os.replace(tmp, path)
    except OSError as exc:
        raise CameraError(f"cannot write the request ({exc.strerror or exc})", path.parent
                          ) from None


class DropFolderCamera:
    """The file-drop adapter (see the module docstring).

    Parameters
    ----------
    folder : path
        The drop folder (must exist).
    timeout_s : float
        Wall seconds to wait for each frame.
    clock : callable
        UTC clock for the request's ``requested_utc`` (the survey clock).
    poll_s : float
        Wall seconds between looks for the frame.

    Raises
    ------
    CameraError
        When the folder does not exist or cannot be written.
    """

    def __init__(self, folder: str | os.PathLike, timeout_s: float = 10.0,
                 clock: Callable[[], float] = time.time, poll_s: float = 0.001) -> None:
        self.folder = Path(folder)
        self.timeout_s = float(timeout_s)
        self.clock = clock
        self.poll_s = float(poll_s)
        if not self.folder.is_dir():
            raise CameraError("drop folder not found", self.folder)
        self.session = secrets.token_hex(8)
        self.sequence = 0
        self._remove_frames()
        with contextlib.suppress(OSError):
            (self.folder / REQUEST_NAME).unlink()

    def capture(self) -> Exposure:
        """Request a frame and wait for it.

        Raises
        ------
        CameraTimeout
            ``DIR: camera: no frame_000012.tif within 10 s``.
        """
        self.sequence += 1
        name = frame_name(self.sequence)
        _replace_text(self.folder / REQUEST_NAME, json.dumps(
            {"session": self.session, "sequence": self.sequence,
             "requested_utc": format_utc(self.clock())}) + "\n")
        deadline = time.monotonic() + self.timeout_s
        while (path := self._answer(self.sequence)) is None:
            if time.monotonic() > deadline:
                raise CameraTimeout(f"camera: no {name} within {self.timeout_s:g} s",
                                    self.folder)
            time.sleep(self.poll_s)
        try:
            return read_drop_frame(path)
        finally:
            self._remove_frames(up_to=self.sequence)

    def _answer(self, sequence: int) -> Path | None:
        """The frame file answering request ``sequence`` (any accepted suffix), or None."""
        stem = frame_name(sequence)[:-len(".tif")]
        for suffix in (".tif", *RADIOMETRIC_SUFFIXES):
            for cand in (stem + suffix, stem + suffix.upper()):
                if (self.folder / cand).exists():
                    return self.folder / cand
        return None

    def _remove_frames(self, up_to: int | None = None) -> None:
        """Delete the frames of requests up to ``up_to`` (all without it): answered, or
        answered too late."""
        for f in self.folder.iterdir():
            m = _FRAME.match(f.name)
            if m and (up_to is None or int(m.group(1)) <= up_to):
                with contextlib.suppress(OSError):
                    f.unlink()

    def close(self) -> None:
        """Remove the last request."""
        with contextlib.suppress(OSError):
            (self.folder / REQUEST_NAME).unlink()


class DropFolderServer:
    """The camera side of a drop folder for any :class:`Camera` (the twin's, a test double):
    answers each new request with a frame, in a thread.

    Attributes
    ----------
    n_frames : int
        Frames written.
    mute : bool
        When True requests are left unanswered (a camera that stopped).
    error : str or None
        The error that ended serving, if any.
    """

    def __init__(self, camera: Camera, folder: str | os.PathLike, poll_s: float = 0.001
                 ) -> None:
        self.camera = camera
        self.folder = Path(folder)
        self.folder.mkdir(parents=True, exist_ok=True)
        self.poll_s = float(poll_s)
        self.n_frames = 0
        self.mute = False
        self.error: str | None = None
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._done: tuple[str, int] | None = None

    def _request(self) -> tuple[str, int] | None:
        try:
            doc = json.loads((self.folder / REQUEST_NAME).read_text())
            return str(doc["session"]), int(doc["sequence"])
        except (OSError, ValueError, KeyError, TypeError):
            return None

    def serve_once(self) -> bool:
        """Answer the current request if it is new; True when a frame was written."""
        req = self._request()
        if req is None or req == self._done or self.mute:
            return False
        self._done = req
        write_drop_frame(self.folder, req[1], self.camera.capture())
        self.n_frames += 1
        return True

    def _serve(self) -> None:
        try:
            while not self._stop.is_set():
                if not self.serve_once():
                    self._stop.wait(self.poll_s)
        except Exception as exc:  # kept for the caller; the thread must not die silently
            self.error = f"{type(exc).__name__}: {exc}"

    def start(self) -> DropFolderServer:
        """Serve in a daemon thread; returns self."""
        self._thread = threading.Thread(target=self._serve, daemon=True,
                                        name="clearfast-sim-camera")
        self._thread.start()
        return self

    def stop(self) -> None:
        """Stop serving."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=5.0)


@dataclass(frozen=True)
class CameraSpec:
    """A camera on the command line: ``drop:DIR[,timeout=S]``."""

    kind: str
    folder: str
    timeout_s: float = 10.0

    def __str__(self) -> str:
        return f"{self.kind}:{self.folder},timeout={self.timeout_s:g}"


def parse_camera_spec(text: str) -> CameraSpec:
    """Parse ``drop:DIR[,timeout=S]``.

    Raises
    ------
    ValueError
        For another kind, an empty folder or a bad timeout.
    """
    kind, sep, rest = text.strip().partition(":")
    if not sep or kind != "drop":
        raise ValueError(f"expected drop:DIR[,timeout=S], got {text!r}")
    folder, _, opts = rest.partition(",timeout=")
    if not folder.strip():
        raise ValueError(f"no drop folder in {text!r}")
    timeout = 10.0
    if opts:
        try:
            timeout = float(opts)
        except ValueError:
            timeout = float("nan")
        if not timeout > 0 or timeout == float("inf"):
            raise ValueError(f"timeout must be a positive number of seconds, got {opts!r}")
    return CameraSpec(kind, folder.strip(), timeout)


def open_camera(spec: CameraSpec, clock: Callable[[], float] = time.time) -> Camera:
    """The camera of ``spec`` (a :class:`DropFolderCamera`)."""
    return DropFolderCamera(spec.folder, spec.timeout_s, clock=clock)
