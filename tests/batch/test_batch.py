"""``clearfast batch``: local processes and a real Dask cluster on loopback."""

from __future__ import annotations

import json

import pyogrio
import pytest

from clearfast_gis.batch import plan_jobs, summary_table
from clearfast_gis.batch.jobs import SurveyResult, worker_id
from clearfast_gis.cli.main import cli
from clearfast_gis.errors import ClearfastError
from clearfast_gis.export.manifest import read_products_manifest


def run_cli(capsys, *args) -> tuple[int, str, str]:
    with pytest.raises(SystemExit) as e:
        cli([str(a) for a in args])
    out, err = capsys.readouterr()
    return e.value.code, out, err


def test_plan_jobs_names_products_after_survey_folders(tmp_path):
    (tmp_path / "a" / "s1").mkdir(parents=True)
    (tmp_path / "b" / "s1").mkdir(parents=True)
    (tmp_path / "b" / "s2").mkdir(parents=True)
    jobs = plan_jobs([tmp_path / "a" / "s1", tmp_path / "b" / "s2"], tmp_path / "out")
    assert [j.name for j in jobs] == ["s1", "s2"]
    assert jobs[1].products == str((tmp_path / "out" / "s2").resolve())
    with pytest.raises(ClearfastError) as e:
        plan_jobs([tmp_path / "a" / "s1", tmp_path / "b" / "s1"], tmp_path / "out")
    assert e.value.exit_code == 2 and "two surveys named 's1'" in e.value.one_line()


def test_summary_table_layout():
    rows = [SurveyResult("alpha", "ok", 12, 31.25, None, "/o/alpha", "h:1"),
            SurveyResult("charlie", "failed", None, 0.4, "soil.csv: file not found",
                         "/o/charlie", "h:2")]
    assert summary_table(rows).splitlines() == [
        "survey   status  anomalies    time",
        "-------  ------  ---------  ------",
        "alpha    ok             12  31.2 s",
        "charlie  failed          -   0.4 s  soil.csv: file not found",
        "2 survey(s): 1 ok, 1 failed",
    ]


def _check_products(out, names, n_max):
    for name in names:
        manifest = read_products_manifest(out / name)
        assert manifest["survey_id"] == f"test-{'12'[names.index(name)]}"
        assert len(list((out / name / "mosaics").glob("scan_*.tif"))) == 2
        assert manifest["parameters"]["max_anomalies"] == n_max


@pytest.mark.slow  # ~60 s: three surveys processed by subprocesses
def test_local_batch_with_a_failing_survey(tiny_surveys, broken_survey, tmp_path, capsys,
                                           few_anomalies):
    out = tmp_path / "out"
    code, stdout, err = run_cli(capsys, "batch", *tiny_surveys, broken_survey, "-o", out,
                                "--workers", 2, "--no-invert", "--progress", "json")
    assert code == 1, err
    assert "Traceback" not in stdout + err
    lines = [json.loads(s) for s in stdout.splitlines()]
    starts = {ev["survey"] for ev in lines if ev["event"] == "start"}
    finishes = {ev["survey"]: ev for ev in lines if ev["event"] == "finish"}
    assert starts == set(finishes) == {"alpha", "bravo", "charlie"}
    summary = lines[-1]
    assert summary["event"] == "summary" and (summary["ok"], summary["failed"]) == (2, 1)
    assert finishes["charlie"]["status"] == "failed"
    assert finishes["charlie"]["error"].startswith("soil.csv: file not found")
    for name in ("alpha", "bravo"):
        ev = finishes[name]
        # the count is of the suspects layer; a two-scan survey may set every detection
        # aside as a candidate, but something was found and measured
        assert ev["status"] == "ok" and 0 <= ev["anomalies"] <= few_anomalies
        gpkg = out / name / "anomalies.gpkg"
        assert ev["anomalies"] == pyogrio.read_info(gpkg, layer="suspects")["features"]
        assert sum(pyogrio.read_info(gpkg, layer=lyr)["features"]
                   for lyr in ("suspects", "candidates")) > 0
        assert ev["seconds"] > 0
    _check_products(out, ["alpha", "bravo"], few_anomalies)
    assert not (out / "charlie" / "products.json").exists()
    # worker processes (not this one) did the work, at most two of them; which took which
    # survey is up to the pool (on a busy machine one may take all three)
    workers = {finishes[n]["worker"] for n in ("alpha", "bravo", "charlie")}
    assert 1 <= len(workers) <= 2
    assert worker_id() not in workers


@pytest.mark.slow  # ~130 s: a Dask cluster started and three surveys processed
def test_dask_batch_on_a_loopback_cluster(tiny_surveys, tmp_path, capsys, few_anomalies):
    from distributed import LocalCluster

    out = tmp_path / "out"
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None, worker_dashboard_address=None) as cluster:
        assert cluster.scheduler_address.startswith("tcp://127.0.0.1:")
        code, stdout, err = run_cli(capsys, "batch", *tiny_surveys, "-o", out, "--no-invert",
                                    "--scheduler", cluster.scheduler_address,
                                    "--progress", "none")
        workers = {w.worker_address for w in cluster.workers.values()}
    assert code == 0, stdout + err
    table = stdout.splitlines()
    assert table[0].split() == ["survey", "status", "anomalies", "time"]
    assert table[2].split()[:2] == ["alpha", "ok"] and table[3].split()[:2] == ["bravo", "ok"]
    assert table[-1] == "2 survey(s): 2 ok, 0 failed"
    assert len(workers) == 2
    _check_products(out, ["alpha", "bravo"], few_anomalies)


def test_unreachable_scheduler_is_one_line():
    import socket

    from clearfast_gis.batch.cluster import connect

    with socket.socket() as s:  # a free loopback port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    with pytest.raises(ClearfastError) as e:
        connect(f"tcp://127.0.0.1:{port}", timeout_s=1.0)
    line = e.value.one_line()
    assert line.startswith(f"tcp://127.0.0.1:{port}: --scheduler: cannot reach the Dask "
                           "scheduler (")
    assert "\n" not in line and e.value.exit_code == 1
