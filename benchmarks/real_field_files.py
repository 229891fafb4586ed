"""Acceptance of real field files: every NMEA receiver capture and every TOA5 station table in
the given folders is read the way the chain reads it, and compared with an independent reader.

NMEA: each log through :func:`clearfast_gis.survey.read_nmea`; every usable epoch's position
must equal pynmea2's reading of a GGA sentence of the same time and fix quality (1e-9 deg),
times must not repeat, and a refused log must name a cause. TOA5: each table through
:func:`clearfast_gis.survey.stations.read_station_table`; the values of every mapped column
must equal the file's (csv module) after the stated unit conversion; a refused table must list
the missing quantities and the file's columns.

Usage::

    python benchmarks/real_field_files.py [NMEA_DIR ...] [--toa5 DIR ...] [--manifest CSV ...]

Default folders (when no folder and no manifest is given): ``../shared/data/real-field-files/
nmea`` and ``.../toa5`` and the excerpts in ``tests/data/nmea``. A manifest is a CSV file with
a ``file`` column (path relative to the manifest, ``nmea/...`` or ``toa5/...``) and the
source columns ``repository``, ``path``, ``licence``: it lets an acceptance run read real
files that may not be copied into the repository from where they were gathered. A file met
twice (same bytes) is read once. Prints one line per file and a summary; exit status 1 if any
file disagrees with its reference.
"""

from __future__ import annotations

import argparse
import csv
import hashlib
import sys
from pathlib import Path

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey.nmea import read_nmea
from clearfast_gis.survey.stations import read_station_table
from clearfast_gis.survey.testing import pynmea2_gga_epochs

SHARED = Path(__file__).resolve().parents[2] / "shared" / "data" / "real-field-files"
EXCERPTS = Path(__file__).resolve().parents[1] / "tests" / "data" / "nmea"


def check_nmea(path: Path) -> tuple[str, bool]:
    """One line about a capture and whether it agrees with pynmea2."""
    try:
        log = read_nmea(path)
    except InvalidInput as exc:
        return f"refused: {exc.message[:110]}", bool(exc.message)
    ref = pynmea2_gga_epochs(path)
    tods = np.round(np.mod(log.time_s, 86400.0), 3)
    bad = 0
    for k in np.flatnonzero(log.usable):
        cands = [c for c in ref.get(float(tods[k]), []) if c[0] == log.fix_quality[k]]
        if not any(abs(c[1] - log.lat_deg[k]) < 1e-9 and abs(c[2] - log.lon_deg[k]) < 1e-9
                   for c in cands):
            bad += 1
    repeats = int(np.count_nonzero(np.diff(log.time_s) == 0.0))
    back = int(np.count_nonzero(np.diff(log.time_s) < 0.0))  # validate reports these
    ok = bad == 0 and repeats == 0
    return (f"{len(log)} epochs ({int(log.usable.sum())} fixes), {bad} disagree with pynmea2, "
            f"{repeats} repeated times, {back} steps back, {log.merged_epochs} merged, "
            f"{len(log.void_rmc_lines)} void RMC"), ok


def _column(path: Path, name: str) -> np.ndarray:
    with open(path, newline="", encoding="utf-8", errors="replace") as fh:
        rows = list(csv.reader(fh))
    i = [n.strip() for n in rows[1]].index(name)
    return np.array([float(r[i]) if r[i].strip().upper() != "NAN" else np.nan
                     for r in rows[4:]])


def check_toa5(path: Path) -> tuple[str, bool]:
    """One line about a station table and whether its values agree with the file's."""
    try:
        table = read_station_table(path, required=())
    except InvalidInput as exc:
        return f"refused: {exc.message[:110]}", False
    if not table.columns:
        try:
            read_station_table(path)
        except InvalidInput as exc:
            ok = "the file has columns" in exc.message
            return f"no quantity recognised; error lists columns: {ok}", ok
    bad = []
    for q, cm in table.columns.items():
        expect = cm.scale * _column(path, cm.column) + cm.offset
        if not np.allclose(getattr(table.weather, q), expect, equal_nan=True, rtol=1e-12):
            bad.append(q)
    missing = ""
    try:
        read_station_table(path)
    except InvalidInput as exc:
        missing = "; the chain would need: " + exc.message.split(";")[0][8:][:60]
    found = ", ".join(f"{q}={c.column}[{c.unit}]" for q, c in table.columns.items())
    return f"{len(table.weather)} records, {found}{missing}", not bad


def _files(args: argparse.Namespace) -> list[tuple[str, Path]]:
    """(kind, path) of every file to read, each content once, in a stable order."""
    found = [("nmea", p) for d in args.nmea for p in sorted(Path(d).glob("*.log"))]
    found += [("toa5", p) for d in args.toa5 for p in sorted(Path(d).glob("*.dat"))]
    for manifest in args.manifest:
        with open(manifest, newline="", encoding="utf-8") as fh:
            for row in csv.DictReader(fh):
                path = manifest.parent / row["file"]
                found.append(("toa5" if path.suffix == ".dat" else "nmea", path))
    seen: set[str] = set()
    out = []
    for kind, path in found:
        digest = hashlib.sha256(path.read_bytes()).hexdigest()
        if digest not in seen:
            seen.add(digest)
            out.append((kind, path))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("nmea", nargs="*", type=Path)
    ap.add_argument("--toa5", nargs="*", type=Path, default=[])
    ap.add_argument("--manifest", nargs="*", type=Path, default=[])
    args = ap.parse_args(argv)
    if not (args.nmea or args.toa5 or args.manifest):
        args.nmea, args.toa5 = [SHARED / "nmea", EXCERPTS], [SHARED / "toa5"]
    counts = {k: [0, 0, 0] for k in ("nmea", "toa5")}  # files, read, agree
    check = {"nmea": check_nmea, "toa5": check_toa5}
    for kind, path in _files(args):
        text, ok = check[kind](path)
        c = counts[kind]
        c[0], c[1], c[2] = c[0] + 1, c[1] + (not text.startswith(("refused", "no quantity"))), \
            c[2] + ok
        print(f"{'ok ' if ok else 'BAD'} {kind} {path.name}: {text}")
    (n_n, r_n, a_n), (n_t, r_t, a_t) = counts["nmea"], counts["toa5"]
    print(f"NMEA: {n_n} logs, {r_n} read, {n_n - r_n} refused with a named cause; "
          f"{a_n} of {n_n} in agreement with pynmea2 (or refused with a cause)")
    print(f"TOA5: {n_t} tables, {r_t} mapped, {n_t - r_t} without a recognised quantity; "
          f"{a_t} of {n_t} in agreement with the file's own values")
    n, n_ok = n_n + n_t, a_n + a_t
    print(f"{n_ok} of {n} real files read in agreement with their reference")
    return 0 if n_ok == n else 1


if __name__ == "__main__":
    sys.exit(main())
