"""A survey restricted to its first scans, for scaling measurements and quick looks.

The frames and logs are hard-linked (same file system) or copied, never rewritten: the
subset reads the same bytes as the whole survey. The frame table keeps the chosen scans; the
blackbody tables keep the calibration events up to the first one after the last kept frame;
the other logs (RTK-DGPS, weather, soil, markers, mission, truth) are kept whole.
"""

from __future__ import annotations

import csv
import os
import shutil
from pathlib import Path

from clearfast_gis.atomic import atomic_path
from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey.manifest import read_survey_json
from clearfast_gis.timeutil import parse_utc


def _link(src: Path, dst: Path) -> None:
    """Hard-link ``src`` to ``dst`` (copy across file systems)."""
    dst.parent.mkdir(parents=True, exist_ok=True)
    if dst.exists():
        dst.unlink()
    try:
        os.link(src, dst)
    except OSError:
        shutil.copy2(src, dst)


def _filter_csv(src: Path, dst: Path, keep) -> list[dict]:
    """Copy the rows of a CSV table for which ``keep(row)`` is true; returns them."""
    with open(src, newline="") as fh:
        reader = csv.DictReader(fh)
        fields = reader.fieldnames or []
        rows = [r for r in reader if keep(r)]
    dst.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(dst) as tmp, open(tmp, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    return rows


def subset_survey(survey: str | os.PathLike, out: str | os.PathLike, n_scans: int) -> Path:
    """Write a survey folder with the first ``n_scans`` scans of ``survey``.

    Parameters
    ----------
    survey : path
        A survey folder (``survey.json``).
    out : path
        The new survey folder (created; files in it are replaced).
    n_scans : int
        Scans kept (the ``n_scans`` lowest scan numbers), >= 1.

    Returns
    -------
    Path
        ``out``.
    """
    src, dst = Path(survey), Path(out)
    manifest = read_survey_json(src / "survey.json")
    files = manifest["files"]
    dst.mkdir(parents=True, exist_ok=True)
    with open(src / files["frames"], newline="") as fh:
        scans = sorted({int(r["scan"]) for r in csv.DictReader(fh)})
    if not 1 <= n_scans <= len(scans):
        raise InvalidInput(f"cannot keep {n_scans} scans of {len(scans)}",
                           src / files["frames"])
    kept = set(scans[:n_scans])
    rows = _filter_csv(src / files["frames"], dst / files["frames"],
                       lambda r: int(r["scan"]) in kept)
    t_last = max(parse_utc(r["time_utc"]) for r in rows)
    with open(src / files["blackbody_frames"], newline="") as fh:
        ev_times: dict[int, float] = {}
        for r in csv.DictReader(fh):
            ev_times.setdefault(int(r["event"]), parse_utc(r["time_utc"]))
    after = [t for t in ev_times.values() if t > t_last]
    t_cut = min(after) + 60.0 if after else float("inf")
    bb_rows = _filter_csv(src / files["blackbody_frames"], dst / files["blackbody_frames"],
                          lambda r: ev_times[int(r["event"])] <= t_cut)
    _filter_csv(src / files["blackbody_log"], dst / files["blackbody_log"],
                lambda r: parse_utc(r["time_utc"]) <= t_cut)
    for rel in sorted({r["file"] for r in rows} | {r["file"] for r in bb_rows}):
        _link(src / rel, dst / rel)
    for key, rel in files.items():
        if key not in ("frames", "blackbody_frames", "blackbody_log"):
            _link(src / rel, dst / rel)
    if (src / "truth").is_dir():
        for p in (src / "truth").rglob("*"):
            if p.is_file():
                _link(p, dst / p.relative_to(src))
    _link(src / "survey.json", dst / "survey.json")
    return dst
