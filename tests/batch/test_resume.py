"""Resume and atomicity: ``clearfast process`` killed with SIGKILL and started again.

The restarted run must end with products byte-identical to an uninterrupted run (sha256 of
every product file; ``products.json`` without its ``timings_s`` and ``report.html`` without its
stage-timings table, the only parts that record how long the stages took), must not recompute
the scans finished before the kill, and no product may ever be visible half-written under its
final name.
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from clearfast_gis.atomic import is_temporary
from clearfast_gis.cli.main import cli
from clearfast_gis.pipeline.stages import STAGE_NAMES, STAGES
from clearfast_gis.survey.testing import make_minimal_survey
from tests.product_digests import comparable_digests, product_files

from .conftest import CAPPED_CLI, MAX_ANOMALIES

N_SCANS = 5
N_POSITIONS = 3


@pytest.fixture(scope="module")
def kill_survey(tmp_path_factory) -> Path:
    """A survey with enough scans that the mosaic stage lasts a few seconds."""
    return make_minimal_survey(tmp_path_factory.mktemp("resume") / "delta", n_scans=N_SCANS,
                               n_positions=N_POSITIONS, width=32, height=24, seed=7)


def _start(survey: Path, products: Path) -> subprocess.Popen:
    return subprocess.Popen(
        [sys.executable, str(CAPPED_CLI), str(MAX_ANOMALIES), "process", str(survey), "-o",
         str(products), "--no-invert", "--progress", "json"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _units(products: Path) -> set[str]:
    try:
        return set(json.loads((products / ".clearfast" / "state.json").read_text())["units"])
    except (OSError, ValueError, KeyError):
        return set()


def _kill_when(proc: subprocess.Popen, condition, timeout_s: float = 120.0) -> list[dict]:
    """SIGKILL ``proc`` as soon as ``condition(events)`` holds; return the events seen.

    ``events`` are the run's JSON progress lines so far, read by a thread as they come; the
    condition is checked every few milliseconds, so it may also look at the products folder.
    """
    events: list[dict] = []

    def read() -> None:
        for line in proc.stdout:
            with contextlib.suppress(ValueError):
                events.append(json.loads(line))

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    t_end = time.monotonic() + timeout_s
    while not condition(events):
        assert proc.poll() is None, "the run ended before the kill point: " + proc.stderr.read()
        assert time.monotonic() < t_end, "kill point not reached"
        time.sleep(0.002)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    reader.join()
    proc.stdout.close()
    proc.stderr.close()
    return events


def assert_complete(products: Path) -> None:
    """Every product present under its final name opens and reads completely."""
    import pyogrio
    import rasterio
    from PIL import Image

    for rel, p in product_files(products).items():
        if rel.endswith(".tif"):
            with rasterio.open(p) as ds:
                assert ds.read().shape[0] == ds.count, rel
        elif rel.endswith(".gpkg"):
            for name, _ in pyogrio.list_layers(p):
                pyogrio.read_dataframe(p, layer=name)
        elif rel.endswith((".json", ".geojson")):
            json.loads(p.read_text())
        elif rel.endswith(".html"):
            assert p.read_text().rstrip().endswith("</html>"), rel
        elif rel.endswith(".png"):
            with Image.open(p) as im:
                im.load()
        else:
            raise AssertionError(f"unexpected product {rel}")
    for p in (products / ".clearfast").glob("*.npy"):
        np.load(p)


@pytest.mark.slow  # ~35 s: four runs of one survey, three of them killed
def test_sigkill_at_any_stage_then_resume_gives_identical_products(kill_survey, tmp_path,
                                                                   few_anomalies):
    reference = tmp_path / "reference"  # uninterrupted, the same command line in this process
    with pytest.raises(SystemExit) as done:
        cli(["process", str(kill_survey), "-o", str(reference), "--no-invert", "--progress",
             "none"])
    assert done.value.code == 0
    want = comparable_digests(reference)
    assert {"anomalies.gpkg", "products.json", "report.html"} <= set(want)
    assert sum(r.startswith("mosaics/") for r in want) == N_SCANS

    products = tmp_path / "products"
    # 1. killed in the mosaic stage, during the second scan processed (the first, the
    #    reference, is recorded before the second starts; progress lines count frames)
    _kill_when(_start(kill_survey, products), lambda ev: any(
        e.get("stage") == "mosaics" and e.get("done", 0) > N_POSITIONS for e in ev))
    done_1 = {u for u in _units(products) if u.startswith("mosaics/scan_")}
    assert 1 <= len(done_1) < N_SCANS, done_1
    assert_complete(products)
    stamps = {u: os.stat(products / f"{u}.tif").st_mtime_ns for u in done_1}

    # 2. restarted, killed again in the anomaly stage (GeoPackage, figures, report)
    proc = _start(kill_survey, products)
    _kill_when(proc, lambda ev: (products / "anomalies.gpkg").exists()
               or (products / "figures").exists())
    assert not (products / "products.json").exists()
    assert_complete(products)

    # 3. restarted to the end
    run = subprocess.run(
        [sys.executable, str(CAPPED_CLI), str(MAX_ANOMALIES), "process", str(kill_survey),
         "-o", str(products), "--no-invert", "--progress", "json"],
        capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    events = [json.loads(s) for s in run.stdout.splitlines()]
    resumed = {e["scan"] for e in events if e.get("stage") == "mosaics" and e.get("resumed")}
    assert resumed == set(range(N_SCANS)), "all scans were finished before the last restart"
    # the progress speaks of the chain's stages by their one set of names
    # (every line but the command's closing "done" summary)
    chain = events[:-1]
    assert events[-1]["event"] == "done"
    assert [e["stage"] for e in chain if e["event"] == "stage"] == list(STAGE_NAMES)
    assert {e["stage"]: e["label"] for e in chain} == {s.name: s.label for s in STAGES}
    assert comparable_digests(products) == want
    for u, ns in stamps.items():  # the scans finished before the first kill were not redone
        assert os.stat(products / f"{u}.tif").st_mtime_ns == ns
    leftovers = [p for p in products.rglob("*") if is_temporary(p.name)]
    assert leftovers == []

    # 4. a finished run started again recomputes nothing (only products.json's timings change)
    before = {r: p.stat().st_mtime_ns for r, p in product_files(products).items()
              if r != "products.json"}
    again = subprocess.run(
        [sys.executable, str(CAPPED_CLI), str(MAX_ANOMALIES), "process", str(kill_survey),
         "-o", str(products), "--no-invert", "--progress", "none"],
        capture_output=True, text=True, timeout=300)
    assert again.returncode == 0, again.stderr
    assert {r: p.stat().st_mtime_ns for r, p in product_files(products).items()
            if r != "products.json"} == before
    assert comparable_digests(products) == want


def test_a_products_folder_locked_by_another_process_is_refused(tmp_path):
    from clearfast_gis.errors import OutputError
    from clearfast_gis.pipeline.state import RunState

    holder = subprocess.Popen(
        [sys.executable, "-c", "import sys, time; from clearfast_gis.pipeline.state import "
         "RunState; s = RunState(sys.argv[1], 'k'); print('locked', flush=True); "
         "time.sleep(60)", str(tmp_path / "p")], stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "locked"
        with pytest.raises(OutputError) as e:
            RunState(tmp_path / "p", "k")
        assert e.value.one_line() == (f"{tmp_path / 'p'}: another clearfast run is writing to "
                                      "this products folder")
    finally:
        holder.send_signal(signal.SIGKILL)  # the kernel releases the lock of a killed run
        holder.wait()
        holder.stdout.close()
    first = RunState(tmp_path / "p", "k")
    again = RunState(tmp_path / "p", "k")  # the same process may run again (plugin retry)
    again.close()
    first.close()


def test_stale_temporaries_are_removed_on_open(tmp_path):
    from clearfast_gis.pipeline.state import RunState

    (tmp_path / "p" / "mosaics").mkdir(parents=True)
    stale = [tmp_path / "p" / "mosaics" / ".scan_000.k2j4.tif.part",
             tmp_path / "p" / ".anomalies.x1.gpkg.part.gpkg"]
    keep = tmp_path / "p" / "mosaics" / "scan_000.tif"
    for p in [*stale, keep]:
        p.write_bytes(b"x")
    RunState(tmp_path / "p", "k").close()
    assert keep.exists() and not any(p.exists() for p in stale)
