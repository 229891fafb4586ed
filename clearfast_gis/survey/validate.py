"""Complete check of a survey folder: every problem found, one line each, and a summary.

:func:`validate_survey` never stops at the first problem and never raises for bad input; the
processing chain, the QGIS plugin and ``clearfast validate`` share it, and the chain takes the
logs it parsed (:class:`ParsedLogs`).

The module is a little over 500 lines because it is one concept walked in one pass: the
folder's files in dependency order (manifest, mission, frames, blackbody frames, logs), each
check needing what the earlier ones found; the per-file checks that stand alone are the
helpers at its end.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from clearfast_gis.errors import ClearfastError, InvalidInput
from clearfast_gis.survey._text import read_text
from clearfast_gis.survey.logs import parse_blackbody_log, parse_markers, parse_soil_log
from clearfast_gis.survey.manifest import manifest_problems, parse_json, resolve_inside
from clearfast_gis.survey.model import MANIFEST_NAME
from clearfast_gis.survey.nmea import FIX_RTK_FIXED, FIX_RTK_FLOAT, gnss_checksums, parse_nmea
from clearfast_gis.survey.plausibility import check_series
from clearfast_gis.survey.stations import PROFILE_KEY, survey_station_profile
from clearfast_gis.survey.tables import parse_blackbody_frames_table, parse_frames_table
from clearfast_gis.survey.tiff import tiff_info
from clearfast_gis.survey.toa5 import parse_weather_table
from clearfast_gis.timeutil import format_utc, parse_utc

#: fewer blackbody frames than this per blackbody and event is reported (paper §3.3)
MIN_BLACKBODY_FRAMES = 10


@dataclass(frozen=True)
class Problem:
    """One finding: the file (relative to the survey folder), the field, and what is wrong."""

    file: str
    field: str
    message: str

    def line(self) -> str:
        """``file: field: message`` (empty parts left out)."""
        return ": ".join(p for p in (self.file, self.field, self.message) if p)


@dataclass(frozen=True)
class ParsedLogs:
    """The survey's logs and frame tables as validation parsed them, for the chain to use
    (each is parsed once per run). None where a file is absent or could not be parsed (then
    the report holds a problem).

    Attributes
    ----------
    gnss : GnssLog or None
    weather : WeatherLog or None
    soil : SoilLog or None
    markers : Markers or None
    frames : FramesTable or None
    blackbody_frames : BlackbodyFramesTable or None
    """

    gnss: object = None
    weather: object = None
    soil: object = None
    markers: object = None
    frames: object = None
    blackbody_frames: object = None


@dataclass
class ValidationReport:
    """Result of :func:`validate_survey`.

    Attributes
    ----------
    problems : list of Problem
        Findings that make the survey unusable as it is (exit status 1).
    warnings : list of Problem
        Findings worth knowing that processing can live with (RTK float epochs, log gaps).
    summary : dict
        Counts and spans: frames, scans, positions, bands, time span, GNSS fix statistics,
        gaps, missing frames.
    logs : ParsedLogs
        The logs parsed on the way (not part of :meth:`to_dict`).
    """

    problems: list[Problem] = field(default_factory=list)
    warnings: list[Problem] = field(default_factory=list)
    summary: dict = field(default_factory=dict)
    logs: ParsedLogs = field(default_factory=ParsedLogs, repr=False)

    @property
    def valid(self) -> bool:
        """True when there is no problem (warnings allowed)."""
        return not self.problems

    def to_dict(self) -> dict:
        """JSON-ready form (``valid``, ``problems``, ``warnings`` as lines and fields,
        ``summary``)."""
        def rows(items: list[Problem]) -> list[dict]:
            return [{"file": p.file, "field": p.field, "message": p.message, "line": p.line()}
                    for p in items]
        return {"valid": self.valid, "problems": rows(self.problems),
                "warnings": rows(self.warnings), "summary": self.summary}


def _report_gaps(ck, label: str, field: str, time_s, limit_s: float) -> list[dict]:
    """Warn about gaps longer than ``limit_s`` in a log; return them for the summary."""
    gaps = _gaps(time_s, limit_s)
    if gaps:
        a, d = max(gaps, key=lambda g: g[1])
        ck.warn(label, field, f"{len(gaps)} gap(s) longer than {limit_s:g} s, "
                f"longest {d:.0f} s at {format_utc(a, 'seconds')}")
    return [{"start_utc": format_utc(a, "seconds"), "length_s": d} for a, d in gaps]


def _gaps(time_s: np.ndarray, threshold_s: float) -> list[tuple[float, float]]:
    t = np.sort(time_s[np.isfinite(time_s)])
    if t.size < 2:
        return []
    d = np.diff(t)
    idx = np.flatnonzero(d > threshold_s)
    return [(float(t[i]), float(d[i])) for i in idx]


def _ranges(values: list[int]) -> str:
    values = sorted(set(values))
    out, i = [], 0
    while i < len(values):
        j = i
        while j + 1 < len(values) and values[j + 1] == values[j] + 1:
            j += 1
        out.append(str(values[i]) if i == j else f"{values[i]}-{values[j]}")
        i = j + 1
    text = ",".join(out)
    return text if len(text) <= 80 else text[:77] + "..."


class _Checker:
    def __init__(self, root: Path) -> None:
        self.root = root
        self.report = ValidationReport()

    def problem(self, file: str, field: str, message: str) -> None:
        self.report.problems.append(Problem(file, field, " ".join(message.split())))

    def warn(self, file: str, field: str, message: str) -> None:
        self.report.warnings.append(Problem(file, field, " ".join(message.split())))

    @contextlib.contextmanager
    def guard(self, file: str) -> Iterator[None]:
        try:
            yield
        except ClearfastError as exc:
            self.problem(exc.path or file, exc.field or "", exc.message)

    def text(self, rel: str, key: str) -> str | None:
        """Text of ``files.<key>`` or None after recording the problem (the raw GNSS log
        may hold line noise that is not text; see :func:`read_text`)."""
        try:
            path = resolve_inside(self.root, rel, MANIFEST_NAME, f"files.{key}")
        except InvalidInput as exc:
            self.problem(MANIFEST_NAME, exc.field or f"files.{key}", exc.message)
            return None
        try:
            return read_text(path, rel, errors="replace" if key == "gnss" else "strict")
        except InvalidInput as exc:
            self.problem(rel, exc.field or "", exc.message)
            return None


def validate_survey(path: str | os.PathLike, gnss_gap_s: float = 10.0,
                    weather_gap_s: float = 180.0, coverage_margin_s: float = 120.0,
                    station_profile: str | os.PathLike | None = None) -> ValidationReport:
    """Check a survey folder completely and collect every problem.

    Parameters
    ----------
    path : path
        The survey folder.
    gnss_gap_s : float
        GNSS epochs further apart than this are reported as a gap (warning), seconds.
    weather_gap_s : float
        Weather records further apart than this are reported as a gap (warning), seconds.
    coverage_margin_s : float
        How far before the first / after the last frame a log must reach, seconds; a log
        that does not reach the frames' time span within this margin is a problem.
    station_profile : path, optional
        A station profile for the weather and soil logs; default: the one ``survey.json``
        names in ``files.station_profile``, if any.

    Returns
    -------
    ValidationReport
    """
    root = Path(path)
    ck = _Checker(root)
    rep = ck.report
    parsed: dict[str, object] = {}
    if not root.is_dir():
        ck.problem(str(root), "", "survey folder not found" if not root.exists()
                   else "expected a survey folder, got a file")
        return rep
    mtext = ck.text(MANIFEST_NAME, "manifest") if (root / MANIFEST_NAME).exists() else None
    if mtext is None:
        if not (root / MANIFEST_NAME).exists():
            ck.problem(MANIFEST_NAME, "", "file not found (empty or not a survey folder)")
        return rep
    try:
        manifest = parse_json(mtext, MANIFEST_NAME)
    except InvalidInput as exc:
        ck.problem(MANIFEST_NAME, exc.field or "", exc.message)
        return rep
    schema_probs = manifest_problems(manifest, "survey")
    for fld, msg in schema_probs:
        ck.problem(MANIFEST_NAME, fld, msg)
    if not isinstance(manifest, dict):
        return rep
    files = manifest.get("files") if isinstance(manifest.get("files"), dict) else {}
    flagged = {fld for fld, _ in schema_probs}
    files = {k: v for k, v in files.items() if isinstance(v, str) and f"files.{k}" not in flagged}
    cam = manifest.get("camera") if isinstance(manifest.get("camera"), dict) else {}
    bands = cam.get("bands") if isinstance(cam.get("bands"), list) else []
    res = cam.get("resolution")
    shape_hw = (int(res[1]), int(res[0])) if isinstance(res, list) and len(res) == 2 and \
        all(isinstance(x, int) for x in res) else None
    start_s = end_s = None
    with contextlib.suppress(Exception):
        start_s = parse_utc(manifest["time"]["start_utc"])
        end_s = parse_utc(manifest["time"]["end_utc"])
    summary = rep.summary
    summary["survey_id"] = manifest.get("survey_id")
    summary["bands"] = [b.get("name") for b in bands if isinstance(b, dict)]

    # -- mission --------------------------------------------------------------------------
    mission = None
    if "mission" in files and (mt := ck.text(files["mission"], "mission")) is not None:
        with ck.guard(files["mission"]):
            doc = parse_json(mt, files["mission"])
            mp = manifest_problems(doc, "mission")
            for fld, msg in mp:
                ck.problem(files["mission"], fld, msg)
            mission = doc if not mp else None
    if mission is not None and shape_hw is not None and \
            tuple(mission["camera"]["resolution"]) != (shape_hw[1], shape_hw[0]):
        ck.problem(files["mission"], "camera.resolution",
                   f"{mission['camera']['resolution']} differs from survey.json "
                   f"camera.resolution {list(res)}")

    # -- frames ---------------------------------------------------------------------------
    frames = None
    if "frames" in files and (ft := ck.text(files["frames"], "frames")) is not None:
        with ck.guard(files["frames"]):
            frames = parsed["frames"] = parse_frames_table(ft, files["frames"])
    if frames is not None:
        _check_frames(ck, frames, files["frames"], mission, files.get("mission", ""), bands,
                      shape_hw)
        if len(frames):
            summary["time_start_utc"] = format_utc(float(frames.time_s.min()), "seconds")
            summary["time_end_utc"] = format_utc(float(frames.time_s.max()), "seconds")
            if start_s is not None and end_s is not None and (
                    frames.time_s.min() < start_s or frames.time_s.max() > end_s):
                ck.warn(files["frames"], "time_utc", "frames lie outside survey.json time "
                        "start_utc..end_utc")
    t_first = float(frames.time_s.min()) if frames is not None and len(frames) else None
    t_last = float(frames.time_s.max()) if frames is not None and len(frames) else None

    # -- blackbody frames -----------------------------------------------------------------
    if "blackbody_frames" in files and \
            (bt := ck.text(files["blackbody_frames"], "blackbody_frames")) is not None:
        label = files["blackbody_frames"]
        with ck.guard(label):
            bbt = parsed["blackbody_frames"] = parse_blackbody_frames_table(bt, label)
            _check_tiffs(ck, bbt.file, bbt.page, label, shape_hw)
            if len(bbt) == 0:
                ck.problem(label, "", "no blackbody frames")
            if bands and len(bbt) and bbt.band.max() >= len(bands):
                ck.problem(label, "band", f"band index {int(bbt.band.max())} but survey.json "
                           f"has {len(bands)} band(s)")
            for ev in np.unique(bbt.event):
                for b in np.unique(bbt.band[bbt.event == ev]):
                    sel = (bbt.event == ev) & (bbt.band == b)
                    for k in (1, 2):
                        n = int(np.count_nonzero(sel & (bbt.blackbody == k)))
                        if n == 0:
                            ck.problem(label, "blackbody",
                                       f"event {ev} band {b}: no frames of blackbody {k}")
                        elif n < MIN_BLACKBODY_FRAMES:
                            ck.warn(label, "blackbody", f"event {ev} band {b}: only {n} frames "
                                    f"of blackbody {k} (>= {MIN_BLACKBODY_FRAMES} expected)")
            summary["calibration_events"] = int(np.unique(bbt.event).size)

    # -- logs -----------------------------------------------------------------------------
    def coverage(label: str, t: np.ndarray, what: str) -> None:
        t = t[np.isfinite(t)]
        if t_first is None or t.size == 0:
            return
        if t.min() > t_first + coverage_margin_s or t.max() < t_last - coverage_margin_s:
            ck.problem(label, "", f"{what} from {format_utc(float(t.min()), 'seconds')} to "
                       f"{format_utc(float(t.max()), 'seconds')} does not cover the frames "
                       f"({format_utc(t_first, 'seconds')} to {format_utc(t_last, 'seconds')})")

    def order(label: str, t: np.ndarray) -> None:
        if t.size > 1 and np.any(np.diff(t) <= 0):
            k = int(np.flatnonzero(np.diff(t) <= 0)[0])
            ck.problem(label, "", f"times not increasing at record {k + 2} "
                       f"({format_utc(float(t[k + 1]), 'seconds')})")

    if "gnss" in files and (gt := ck.text(files["gnss"], "gnss")) is not None:
        label = files["gnss"]
        with ck.guard(label):
            log = parse_nmea(gt, label, start_s, gnss_checksums(manifest))
            parsed["gnss"] = log
            counts = log.fix_counts()
            n = len(log)
            n_fixed = counts.get(FIX_RTK_FIXED, 0)
            summary["gnss_epochs"] = n
            summary["fix_quality_counts"] = {str(k): v for k, v in sorted(counts.items())}
            summary["rtk_fixed_share"] = n_fixed / n if n else 0.0
            for lines, what in (
                    (log.bad_checksum_lines, "line(s) with a wrong checksum skipped"),
                    (log.no_checksum_lines, "line(s) without a checksum skipped (survey.json "
                     '"gnss": {"checksums": "optional"} accepts them)'),
                    (log.unparseable_lines, "line(s) that are not NMEA sentences skipped"),
                    (log.untimed_gga_lines, "GGA sentence(s) without a time skipped"),
                    (log.implausible_date_lines, "RMC/ZDA date(s) more than 7 days from "
                     "time.start_utc ignored"),
                    (log.prefixed_lines, "line(s) with other bytes before the sentence (read "
                     "from its $)")):
                if lines:
                    ck.warn(label, f"line {lines[0]}", f"{len(lines)} {what}")
            n_usable = int(np.count_nonzero(log.usable))
            not_measured = int(np.count_nonzero(np.isin(log.fix_quality, (6, 7, 8))))
            if not_measured:
                ck.warn(label, "GGA", f"{not_measured} epoch(s) of fix quality 6-8 (dead "
                        "reckoning, manual, simulator) are not position fixes")
            if n_usable == 0:
                ck.problem(label, "GGA", "no epoch has a position fix (fix quality 1-5)")
            elif n_fixed == 0:
                ck.warn(label, "GGA", "no RTK-fixed epoch (fix quality 4): positions are "
                        "metre-level, not centimetre-level")
            elif counts.get(FIX_RTK_FLOAT, 0):
                ck.warn(label, "GGA", f"{counts[FIX_RTK_FLOAT]} RTK float epoch(s)")
            order(label, log.time_s)
            summary["gnss_gaps"] = _report_gaps(ck, label, "time", log.time_s, gnss_gap_s)
            valid = log.usable
            coverage(label, log.time_s[valid], "position fixes")
            if frames is not None and len(frames) and valid.any():
                _check_fix_gaps(ck, label, np.sort(log.time_s[valid]), frames.time_s)

    profile = None
    with ck.guard(files.get(PROFILE_KEY) or str(station_profile)):
        profile = survey_station_profile(root, manifest, station_profile)
    altitude = None
    with contextlib.suppress(Exception):
        altitude = float(manifest["site"]["ground_altitude_m"])
    if "weather" in files and (wt := ck.text(files["weather"], "weather")) is not None:
        label = files["weather"]
        with ck.guard(label):
            table = parse_weather_table(wt, label, profile)
            w = table.weather
            parsed["weather"] = w
            summary["weather_records"] = len(w)
            summary["weather_columns"] = {q: f"{c.column} [{c.unit}]"
                                          for q, c in table.columns.items()}
            if len(w) == 0:
                ck.problem(label, "", "no records")
            order(label, w.time_s)
            summary["weather_gaps"] = _report_gaps(ck, label, "TIMESTAMP", w.time_s,
                                                   weather_gap_s)
            for name in ("air_temp_c", "rh_pct", "pressure_hpa", "wind_ms", "solar_wm2"):
                v = getattr(w, name)
                nn = int(np.count_nonzero(np.isnan(v)))
                if len(w) and nn == len(w):
                    ck.problem(label, name, "all values missing (NAN)")
                elif nn:
                    ck.warn(label, name, f"{nn} missing value(s) (NAN)")
            if "sky_lw_wm2" not in table.columns:
                ck.warn(label, "sky_lw_wm2", "no pyrgeometer column: the sky long-wave is "
                        "estimated from air temperature and humidity (Brutsaert 1975 clear "
                        "sky; under cloud it is underestimated)")
            for f in table.findings(altitude):
                ck.problem(label, f"line {f.line}", f.text())
            coverage(label, w.time_s, "weather records")

    if "soil" in files and (txt := ck.text(files["soil"], "soil")) is not None:
        with ck.guard(files["soil"]):
            soil = parse_soil_log(txt, files["soil"], profile)
            parsed["soil"] = soil
            if soil.time_s.size == 0:
                ck.problem(files["soil"], "", "no records")
            order(files["soil"], soil.time_s)
            coverage(files["soil"], soil.time_s, "soil temperatures")
            first = 5 if txt.lstrip('\ufeff"').startswith("TOA5") else 2  # after the header
            lines = np.arange(soil.time_s.size) + first
            for j, depth in enumerate(soil.depth_m):
                column = soil.columns[j] if soil.columns else f"{depth:g} m"
                for f in check_series("soil_temp_c", column, soil.time_s,
                                      soil.temp_c[:, j], lines, "deg C"):
                    ck.problem(files["soil"], f"line {f.line}", f.text())
    for key, parser, what in (("blackbody_log", parse_blackbody_log, "blackbody temperatures"),):
        if key in files and (txt := ck.text(files[key], key)) is not None:
            with ck.guard(files[key]):
                lg = parser(txt, files[key])
                if lg.time_s.size == 0:
                    ck.problem(files[key], "", "no records")
                order(files[key], lg.time_s)
                coverage(files[key], lg.time_s, what)
                lines = np.arange(lg.time_s.size) + 2  # after the header
                for column in ("bb1_c", "bb2_c"):
                    for f in check_series("blackbody_temp_c", column, lg.time_s,
                                          getattr(lg, column), lines, "deg C"):
                        ck.problem(files[key], f"line {f.line}", f.text())
    if "markers" in files and (mk := ck.text(files["markers"], "markers")) is not None:
        with ck.guard(files["markers"]):
            parsed["markers"] = parse_markers(mk, files["markers"])
            summary["markers"] = len(parsed["markers"])
    rep.logs = ParsedLogs(**parsed)
    return rep


def _check_fix_gaps(ck: _Checker, label: str, fix_time_s: np.ndarray,
                    frame_time_s: np.ndarray) -> None:
    """Frames farther from every position fix than the processing bridges are a problem:
    where the platform was is unknown then."""
    from clearfast_gis.geometry.gnss import STATIC_BRIDGE_S, distance_to_nearest_s

    far = distance_to_nearest_s(fix_time_s, frame_time_s) > STATIC_BRIDGE_S
    if far.any():
        first = float(np.min(frame_time_s[far]))
        ck.problem(label, "GGA", f"{int(np.count_nonzero(far))} frame(s) farther than "
                   f"{STATIC_BRIDGE_S:g} s from any position fix, first at "
                   f"{format_utc(first, 'seconds')}: the platform's position is unknown then")


def _check_tiffs(ck: _Checker, file_col: np.ndarray, page_col: np.ndarray, label: str,
                 shape_hw: tuple[int, int] | None) -> set[str]:
    """Check each referenced TIFF's header once; return the files that are usable."""
    good: set[str] = set()
    for rel in np.unique(file_col):
        rel = str(rel)
        try:
            path = resolve_inside(ck.root, rel, label, "file")
        except InvalidInput as exc:
            ck.problem(label, "file", f"{exc.message}")
            continue
        try:
            info = tiff_info(path, rel)
        except InvalidInput as exc:
            ck.problem(rel, exc.field or "", exc.message)
            continue
        ok = True
        if info.dtype != np.uint16:
            ck.problem(rel, "dtype", f"expected uint16 raw counts, got {info.dtype}")
            ok = False
        if shape_hw is not None and info.shape != shape_hw:
            ck.problem(rel, "size", f"pages are {info.shape[1]}x{info.shape[0]} pixels, "
                       f"survey.json camera.resolution is {shape_hw[1]}x{shape_hw[0]}")
            ok = False
        max_page = int(page_col[file_col == rel].max())
        if max_page >= info.n_pages:
            ck.problem(rel, "pages", f"{label} refers to page {max_page} but the file has "
                       f"{info.n_pages} page(s)")
            ok = False
        if ok:
            good.add(rel)
    return good


def _check_frames(ck: _Checker, fr, label: str, mission: dict | None, mission_label: str,
                  bands: list, shape_hw: tuple[int, int] | None) -> None:
    s = ck.report.summary
    s["frames"] = len(fr)
    s["scans"] = int(np.unique(fr.scan).size)
    s["positions"] = int(np.unique(fr.position).size)
    if len(fr) == 0:
        ck.problem(label, "", "no frames (empty survey)")
        return
    if bands and fr.band.max() >= len(bands):
        ck.problem(label, "band", f"band index {int(fr.band.max())} but survey.json has "
                   f"{len(bands)} band(s)")
    key = (fr.scan * 1_000_000 + fr.position) * 1000 + fr.band
    uniq, counts = np.unique(key, return_counts=True)
    if np.any(counts > 1):
        k = int(uniq[counts > 1][0])
        ck.problem(label, "", f"{int(np.count_nonzero(counts > 1))} duplicate frame(s), e.g. "
                   f"scan {k // 1_000_000_000} position {(k // 1000) % 1_000_000} band {k % 1000}")
    pairs = {(str(f), int(p)) for f, p in zip(fr.file, fr.page, strict=True)}
    if len(pairs) != len(fr):
        ck.problem(label, "page", "several frames point to the same file and page")
    good = _check_tiffs(ck, fr.file, fr.page, label, shape_hw)
    bad_rows = int(np.count_nonzero(~np.isin(fr.file.astype(str), list(good))))
    if bad_rows:
        s["unreadable_frames"] = bad_rows
    n_bands = max(len(bands), 1)
    if mission is not None:
        pos = {p["index"]: p for p in mission["positions"]}
        unknown = sorted(set(int(p) for p in np.unique(fr.position)) - set(pos))
        if unknown:
            ck.problem(label, "position", f"position(s) {_ranges(unknown)} are not in "
                       f"{mission_label}")
        if fr.scan.max() >= mission["n_scans"]:
            ck.problem(label, "scan", f"scan {int(fr.scan.max())} but {mission_label} has "
                       f"n_scans {mission['n_scans']}")
        known = np.isin(fr.position, list(pos))
        if np.any(known):
            pan_m = np.array([pos[int(p)]["pan_deg"] for p in fr.position[known]])
            tilt_m = np.array([pos[int(p)]["tilt_deg"] for p in fr.position[known]])
            dpan = np.abs((fr.pan_deg[known] - pan_m + 180.0) % 360.0 - 180.0)
            dtilt = np.abs(fr.tilt_deg[known] - tilt_m)
            worst = float(max(dpan.max(), dtilt.max()))
            if worst > 1.0:
                ck.warn(label, "pan_deg/tilt_deg", f"pointing differs from {mission_label} by up "
                        f"to {worst:.2f} deg")
        expected = mission["n_scans"] * len(pos) * n_bands
    else:
        expected = s["scans"] * s["positions"] * n_bands
    present = int(uniq.size)
    missing = max(expected - present, 0)
    s["frames_expected"] = expected
    s["missing_frames"] = missing
    if missing:
        scans_all = range(mission["n_scans"]) if mission is not None else np.unique(fr.scan)
        incomplete = []
        per_scan = {int(a): int(b) for a, b in zip(*np.unique(fr.scan, return_counts=True),
                                                   strict=True)}
        n_per = (len(mission["positions"]) if mission is not None else s["positions"]) * n_bands
        for sc in scans_all:
            if per_scan.get(int(sc), 0) < n_per:
                incomplete.append(int(sc))
        ck.warn(label, "", f"{missing} of {expected} frame(s) missing (scans "
                f"{_ranges(incomplete)} incomplete)")
