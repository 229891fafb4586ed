"""Acceptance of real field files: every NMEA receiver capture and every TOA5 station table in
the given folders is read the way the chain reads it, and compared with an independent reader.

NMEA: each log through :func:`clearfast_gis.survey.read_nmea`; every usable epoch's position
must equal pynmea2's reading of a GGA sentence of the same time and fix quality (1e-9 deg),
times must not repeat, and a refused log must name a cause. TOA5: each table through
:func:`clearfast_gis.survey.stations.read_station_table`; the values of every mapped column
must equal the file's (csv module) after the stated unit conversion; a refused table must list
the missing quantities and the file's columns.

Usage::

    python benchmarks/real_field_files.py [NMEA_DIR ...] [--toa5 DIR ...]

Default folders: ``../shared/data/real-field-files/nmea`` and ``.../toa5``. Prints one line per
file and a summary; exit status 1 if any file disagrees with its reference.
"""

from __future__ import annotations

import argparse
import csv
import sys
from pathlib import Path

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey.nmea import read_nmea
from clearfast_gis.survey.stations import read_station_table
from clearfast_gis.survey.testing import pynmea2_gga_epochs

SHARED = Path(__file__).resolve().parents[2] / "shared" / "data" / "real-field-files"


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
    ok = bad == 0 and repeats == 0
    return (f"{len(log)} epochs ({int(log.usable.sum())} fixes), {bad} disagree with pynmea2, "
            f"{repeats} repeated times, {log.merged_epochs} merged, "
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


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("nmea", nargs="*", type=Path, default=[SHARED / "nmea"])
    ap.add_argument("--toa5", nargs="*", type=Path, default=[SHARED / "toa5"])
    args = ap.parse_args(argv)
    n = n_ok = 0
    for folder, check, pattern in [(d, check_nmea, "*.log") for d in args.nmea] + \
            [(d, check_toa5, "*.dat") for d in args.toa5]:
        for path in sorted(Path(folder).glob(pattern)):
            text, ok = check(path)
            n, n_ok = n + 1, n_ok + ok
            print(f"{'ok ' if ok else 'BAD'} {path.name}: {text}")
    print(f"{n_ok} of {n} real files read in agreement with their reference")
    return 0 if n_ok == n else 1


if __name__ == "__main__":
    sys.exit(main())
