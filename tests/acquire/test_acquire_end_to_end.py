"""simulate-devices + acquire through real ptys: faults, a crash and its resumption, then
validate and process; values compared with the digital twin."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys

import numpy as np
import pytest

from clearfast_gis.simulate.scenario import parse_scenario
from clearfast_gis.simulate.twin import build_twin
from clearfast_gis.survey import (
    read_blackbody_frames_table,
    read_blackbody_log,
    read_frames_table,
    read_nmea,
    read_soil_log,
    read_toa5,
    validate_survey,
)
from clearfast_gis.timeutil import parse_utc
from tests.acquire.test_acquire_cli_log import _wait_for

CLI = [sys.executable, "-m", "clearfast_gis.cli.main"]
SCALE = 1500.0
START = "2026-11-15T08:00:00Z"
SCENARIO = {
    "format": "clearfast-scenario", "format_version": 1, "preset": "demo",
    "start_utc": START, "n_scans": 2, "duration_h": 8,
    "area": {"width_m": 3.0, "length_m": 2.0}, "lift": {"height_m": 5.0, "offset_m": 1.5},
    "camera": {"resolution": [64, 48]}, "grid_cell_m": 0.03,
    "objects": [
        {"id": "AT1", "kind": "at_mine", "x_m": 1.0, "y_m": 1.0, "depth_m": 0.01,
         "diameter_m": 0.3},
        {"id": "AP1", "kind": "ap_mine", "x_m": 2.2, "y_m": 0.8, "depth_m": 0.0,
         "diameter_m": 0.1},
        {"id": "M1", "kind": "marker", "x_m": 0.4, "y_m": 1.6, "variant": "hot"},
        {"id": "M2", "kind": "marker", "x_m": 2.6, "y_m": 1.6, "variant": "cold"},
    ],
}
# the simulators start at 08:00, scan 0 is planned at 08:40 and scan 1 at 12:40 (the run killed
# in scan 0 is resumed well before 11:00 even on a busy machine); line noise at 11:00 and
# 11:30, no RTK fix 11:20-11:25, and the receiver is unplugged from 12:30 to 12:50, when scan 1
# begins (the survey clock runs on without it; scene frames after the calibration event stay
# within the 600 s the processing bridges)
PLANNED = "2026-11-15T08:40:00Z"
FAULTS = ["noise:weather@10800", "rtk-loss@12000+300", "noise:soil@12600",
          "unplug:gnss@16200+1200"]


def _env() -> dict:
    return {**os.environ, "PYTHONPATH": os.pathsep.join(
        [os.getcwd(), os.environ.get("PYTHONPATH", "")])}


@pytest.fixture(scope="module")
def acquired(tmp_path_factory):
    """Device simulators of a small twin at 1500x, an acquisition killed in scan 0 and run
    again to the end; yields (sim folder, survey folder, outputs)."""
    base = tmp_path_factory.mktemp("e2e")
    scen = base / "scenario.json"
    scen.write_text(json.dumps(SCENARIO))
    sim_dir, survey = base / "sim", base / "survey"
    profile = base / "station.json"  # the station's own names, stated with their units
    profile.write_text(json.dumps({
        "format": "clearfast-station-profile", "format_version": 1, "name": "twin station",
        "columns": {"air_temp_c": {"column": "AirTC_Avg", "unit": "Deg C"},
                    "pressure_hpa": {"column": "BP_hPa_Avg", "unit": "hPa"}}}))
    sim = subprocess.Popen(
        [*CLI, "simulate-devices", "--ports-file", str(sim_dir / "ports.json"), "--scenario",
         str(scen), "--time-scale", str(SCALE), "--progress", "json",
         *[a for f in FAULTS for a in ("--fault", f)]],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=_env())
    acquire = [*CLI, "acquire", "--ports-file", str(sim_dir / "ports.json"), "-o", str(survey),
               "--progress", "json", "--start", PLANNED, "--station-profile", str(profile)]
    out: dict = {}
    try:
        ready = _wait_for(sim, lambda e: e["event"] == "ready", 60.0)[-1]
        out["ready"] = ready
        first = subprocess.Popen(acquire, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                 text=True, env=_env())
        try:  # killed (no clean-up at all) after 8 exposures of scan 0
            _wait_for(first, lambda e: e.get("event") == "progress" and e["done"] == 8, 60.0)
        finally:
            first.send_signal(signal.SIGKILL)
            first.communicate(timeout=30)
        out["staged_after_kill"] = sorted(
            p.name for p in (survey / "acquisition" / "incoming" / "scan_000").iterdir())
        second = subprocess.run(acquire, capture_output=True, text=True, env=_env(),
                                timeout=180)
        out["second"] = second
        sim.send_signal(signal.SIGTERM)
        sim_out, sim_err = sim.communicate(timeout=30)
        out["sim_end"] = json.loads(sim_out.strip().splitlines()[-1])
    finally:
        if sim.poll() is None:
            sim.kill()
    yield sim_dir, survey, out


@pytest.fixture(scope="module")
def twin():
    """The same twin as the device simulators'."""
    scen = parse_scenario(SCENARIO)
    return build_twin(scen.config, 0, False, list(scen.objects), False)


def test_acquisition_survives_faults_and_a_kill(acquired):
    sim_dir, survey, out = acquired
    second = out["second"]
    assert second.returncode == 0, second.stderr
    summary = json.loads(second.stdout.strip().splitlines()[-1])
    assert summary["event"] == "summary" and not summary["stopped"]
    # 20 blackbody frames then the positions: 8 exposures were kept when the run was killed
    # (a 9th may have been in flight: half-written under a temporary name, or complete)
    kept = [n for n in out["staged_after_kill"] if not n.startswith(".")]
    assert kept[:8] == [f"bb1_{k:03d}.tif" for k in range(8)] and len(kept) in (8, 9)
    assert not list((survey / "acquisition").rglob("*.part"))  # removed when resumed
    assert summary["missed_scans"] == [] and summary["scans"] == [0, 1]
    events = (survey / "acquisition" / "events.csv").read_text().splitlines()
    text = "\n".join(events)
    assert ",gnss,disconnected," in text and ",gnss,reconnected," in text
    assert "RTK fixed -> no fix" in text
    session = json.loads((survey / "acquisition" / "session.json").read_text())
    assert len(session["runs"]) == 2 and not session["runs"][1]["stopped"]
    assert summary["instruments"]["weather"]["bad"] >= 1  # the burst of line noise
    assert summary["instruments"]["soil"]["bad"] + 0 >= 0
    assert any("unplug:gnss@16200+1200 on" in f for f in out["sim_end"]["faults"])


def _switched(out: dict, fault: str) -> tuple[float, float]:
    """Scene seconds after the twin's start when the simulators switched a fault on and off
    (a busy machine may do it a little after the time asked for)."""
    times = {line.rsplit(" ", 1)[1]: float(line.split(" s ", 1)[0])
             for line in out["sim_end"]["faults"] if f" {fault} " in line}
    return times["on"], times["off"]


def test_acquired_folder_validates_and_matches_the_twin(acquired, twin):
    sim_dir, survey, out = acquired
    report = validate_survey(survey)
    assert report.valid, [p.line() for p in report.problems]
    # the survey carries the station profile it was acquired with
    manifest = json.loads((survey / "survey.json").read_text())
    assert manifest["files"]["station_profile"] == "station_profile.json"
    assert json.loads((survey / "station_profile.json").read_text())["name"] == "twin station"
    assert report.summary["weather_columns"]["air_temp_c"] == "AirTC_Avg [Deg C]"
    mission = json.loads((sim_dir / "mission.json").read_text())
    n_pos = len(mission["positions"])
    fr = read_frames_table(survey / "frames.csv")
    assert len(fr) == 2 * n_pos * 2 and report.summary["missing_frames"] == 0
    # read-backs are the planned angles on the unit's 185.1428" steps
    res = 185.1428 / 3600.0
    plan = {p["index"]: (p["pan_deg"], p["tilt_deg"]) for p in mission["positions"]}
    want = np.array([plan[int(p)] for p in fr.position])
    np.testing.assert_allclose(fr.pan_deg, np.round(want[:, 0] / res) * res, atol=2e-6)
    np.testing.assert_allclose(fr.tilt_deg, np.round(want[:, 1] / res) * res, atol=2e-6)
    # exposure times: the twin's clock, band 1 0.4 s after band 0, inside each scan's window
    t0 = parse_utc(PLANNED)
    assert json.loads((survey / "acquisition" / "session.json").read_text())["start_utc"] \
        == "2026-11-15T08:40:00.000Z"
    b0, b1 = fr.take(fr.band == 0), fr.take(fr.band == 1)
    np.testing.assert_allclose(b1.time_s - b0.time_s, 0.4, atol=1e-3)
    for s in (0, 1):
        t = b0.time_s[b0.scan == s]
        assert np.all(np.diff(t) > 0)
        assert t0 + s * 14400.0 <= t.min() and t.max() < t0 + (s + 1) * 14400.0  # its window
    # logs: the twin's records, as the device simulators sent them
    w = read_toa5(survey / "weather.dat")
    truth_w = twin.weather_log()
    k = np.searchsorted(truth_w.time_s, w.time_s)
    np.testing.assert_array_equal(truth_w.time_s[k], w.time_s)
    np.testing.assert_allclose(w.air_temp_c, truth_w.air_temp_c[k], atol=1e-9)
    assert report.summary["weather_gaps"] == []  # the noise burst lost no record
    soil = read_soil_log(survey / "soil.csv")
    truth_s = twin.soil_log()
    k = np.searchsorted(truth_s.time_s, soil.time_s)
    np.testing.assert_allclose(soil.temp_c, np.round(truth_s.temp_c[k], 3), atol=1e-9)
    bbl = read_blackbody_log(survey / "blackbody" / "temperatures.csv")
    truth_b = twin.blackbody_log()
    k = np.searchsorted(truth_b.time_s, bbl.time_s)
    np.testing.assert_allclose(bbl.bb1_c, np.round(truth_b.bb1_c[k], 3), atol=1e-9)
    gnss = read_nmea(survey / "gnss.nmea")
    truth_g = twin.gnss_log()
    ok = gnss.fix_quality == 4
    k = np.searchsorted(truth_g.time_s, gnss.time_s[ok])
    np.testing.assert_allclose(gnss.lat_deg[ok], truth_g.lat_deg[k], atol=1e-9)
    lost = (gnss.time_s >= twin.start_s + 12000) & (gnss.time_s < twin.start_s + 12300)
    assert lost.any() and np.all(gnss.fix_quality[lost] == 0)
    on, off = _switched(out, "unplug:gnss@16200+1200")
    assert 16200 <= on < 16200 + 120 and 17400 <= off < 17400 + 120
    away = (twin.start_s + on, twin.start_s + off)
    # the switch times are the simulators' own record: on a busy machine a sentence already
    # on its way may carry a time a little inside the window (150 s of scene time is 0.1 s)
    assert not np.any((gnss.time_s > away[0] + 150) & (gnss.time_s < away[1] - 150))
    # the survey clock ran on without the receiver: scan 1 began meanwhile (its calibration
    # event is planned at 12:40; a busy machine may delay it by minutes of scene time)
    bb = read_blackbody_frames_table(survey / "blackbody" / "frames.csv")
    t1 = bb.time_s[bb.event == 1]
    assert twin.start_s + 16800 <= t1.min() < away[1]
    assert any(g["length_s"] >= 1190 for g in report.summary["gnss_gaps"])
    # calibration: the heated blackbody gives more counts than the ambient one
    assert len(bb) == 2 * 2 * 10 * 2
    from clearfast_gis.survey import read_tiff_stack
    pages = read_tiff_stack(survey / "blackbody" / "event_000_b0.tif")
    assert pages[:10].mean() > pages[10:].mean() + 200


def test_acquired_folder_goes_through_process(acquired, tmp_path):
    _, survey, _ = acquired
    from clearfast_gis.pipeline import ProcessOptions, process_survey

    process_survey(survey, tmp_path / "products", ProcessOptions(), resume=False)
    mosaics = sorted((tmp_path / "products" / "mosaics").glob("*.tif"))
    assert len(mosaics) == 2
    assert (tmp_path / "products" / "anomalies.gpkg").exists()


def test_rig_sends_soil_lines_from_the_scene_start(twin, tmp_path):
    """Building the rig's engines can take seconds of wall time (the soil profile's first
    compile on a fresh machine: an hour of scene time at 1500x); the scene starts when the
    rig does, and the thermocouple lines due from then on are all sent."""
    import copy
    import time

    import serial

    from clearfast_gis.simulate.devices import DeviceRig

    slow = copy.copy(twin)
    slow.soil_log = lambda: (time.sleep(2.0), twin.soil_log())[1]  # 50 min of scene time
    with DeviceRig(slow, tmp_path, time_scale=SCALE) as rig:
        port = serial.Serial(rig.devices["soil"].path, 9600, timeout=0.05)
        first_t = None
        deadline = time.monotonic() + 10.0
        while first_t is None and time.monotonic() < deadline:
            for line in port.read(4096).decode().splitlines():
                if line.startswith("T,"):
                    first_t = parse_utc(line.split(",")[1])
                    break
        port.close()
    # the first 10-minute record after the start arrives within 0.4 s (wall): well before
    # the 50 minutes building the engine took
    assert first_t is not None and first_t <= twin.start_s + 1800.0
