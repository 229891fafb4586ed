"""``clearfast acquire`` / ``simulate-devices``: one-line errors, nothing written on bad input;
the ports file, the set-up file, fault specifications and the twin clock."""

from __future__ import annotations

import json
import subprocess
import sys
import time

import pytest
from click.testing import CliRunner

from clearfast_gis.acquire.mission import Blackbodies
from clearfast_gis.acquire.ports import read_ports_file
from clearfast_gis.acquire.ptydevice import PtyDevice
from clearfast_gis.acquire.simulated import SimulatedPtu
from clearfast_gis.acquire.station import read_setup, setup_document
from clearfast_gis.cli.main import group
from clearfast_gis.errors import InvalidInput
from clearfast_gis.simulate.devices import Fault, TwinClock, parse_fault
from clearfast_gis.survey.testing import minimal_manifest, minimal_mission

BB = Blackbodies((150.0, 20.0), (-150.0, 20.0), 10)


def _station(tmp_path, mission: dict | None = None):
    """mission.json and setup.json of a small camera."""
    m = mission or minimal_mission(1, 3, 600.0, 16, 12)
    (tmp_path / "mission.json").write_text(json.dumps(m))
    doc = setup_document(minimal_manifest("s", 16, 12), BB, markers=None)
    (tmp_path / "setup.json").write_text(json.dumps(doc))
    (tmp_path / "drop").mkdir()
    return tmp_path / "mission.json", tmp_path / "setup.json"


def _acquire(*args: str):
    res = CliRunner().invoke(group, ["acquire", *args], catch_exceptions=True)
    return res


def _cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "clearfast_gis.cli.main", *args],
                          capture_output=True, text=True, timeout=60)


def test_unopenable_port_is_one_line_and_writes_nothing(tmp_path):
    mission, setup = _station(tmp_path)
    out = tmp_path / "survey"
    p = _cli("acquire", "--mission", str(mission), "--setup", str(setup), "--ptu",
             str(tmp_path / "ttyUSB7"), "--camera", f"drop:{tmp_path / 'drop'}", "-o", str(out))
    assert p.returncode == 1
    assert p.stderr.splitlines() == [f"clearfast: error: {tmp_path / 'ttyUSB7'}: cannot open "
                                     "serial port (No such file or directory)"]
    assert not out.exists()


def test_position_outside_the_units_limits_is_refused_before_anything(tmp_path):
    mission = minimal_mission(1, 3, 600.0, 16, 12)
    mission["positions"][2]["pan_deg"] = 170.0
    mission_path, setup = _station(tmp_path, mission)
    out = tmp_path / "survey"
    sim = SimulatedPtu()
    with PtyDevice(sim, name="ptu") as dev:
        p = _cli("acquire", "--mission", str(mission_path), "--setup", str(setup), "--ptu",
                 dev.path, "--camera", f"drop:{tmp_path / 'drop'}", "-o", str(out))
    assert p.returncode == 1, p.stderr
    assert p.stderr.splitlines() == [
        f"clearfast: error: {mission_path}: positions.2: position 2: pan 170.000 deg is "
        f"outside the unit's range -158.914 to 158.914 deg ({dev.path})"]
    assert not out.exists() and not any(c.startswith("PP") and len(c) > 2
                                        for c in sim.received)


@pytest.mark.parametrize("doc, message", [
    ({"format": "clearfast-ports", "gnss": 5}, "ports.json: gnss: expected PORT[,BAUD] as a "
                                               "text"),
    ({"format": "clearfast-ports", "gps": "/dev/x"}, "ports.json: gps: unknown key"),
    ({"format": "clearfast-ports", "time_scale": -2}, "ports.json: time_scale: expected a "
                                                       "positive number"),
    ({"format": "clearfast-ports", "ptu": "/dev/x,fast"}, "ports.json: ptu: baud rate must "
                                                          "be an integer"),
    ([1, 2], "ports.json: format: expected an object"),
])
def test_bad_ports_files(tmp_path, doc, message):
    path = tmp_path / "ports.json"
    path.write_text(json.dumps(doc))
    with pytest.raises(InvalidInput) as err:
        read_ports_file(path)
    assert str(err.value).replace(str(tmp_path) + "/", "").startswith(message)


def test_ports_file_paths_and_usage_errors(tmp_path):
    path = tmp_path / "ports.json"
    path.write_text(json.dumps({"format": "clearfast-ports", "format_version": 1,
                                "gnss": "/dev/ttyUSB0", "ptu": "/dev/ttyUSB1,19200",
                                "camera": "drop:/data/cam", "mission": "m/mission.json",
                                "setup": "setup.json", "time_scale": 250}))
    pf = read_ports_file(path)
    assert str(pf.ports["gnss"]) == "/dev/ttyUSB0,115200" and pf.ports["ptu"].baud == 19200
    assert pf.mission == tmp_path / "m" / "mission.json" and pf.time_scale == 250.0
    res = _acquire("-o", str(tmp_path / "s"))
    assert res.exit_code == 2 and "missing --mission, --setup, --ptu, --camera" in res.output
    res = _acquire("--camera", "usb:0", "-o", str(tmp_path / "s"))
    assert res.exit_code == 2 and "expected drop:DIR" in res.output
    res = _acquire("--start", "tomorrow", "-o", str(tmp_path / "s"))
    assert res.exit_code == 2 and "ISO 8601" in res.output
    res = _acquire("--scans", "3-1", "-o", str(tmp_path / "s"))
    assert res.exit_code == 2 and "expected scan numbers such as 0-2,5" in res.output
    from clearfast_gis.cli.acquire import _scans
    assert _scans(None, None, "0-2, 5,1") == [0, 1, 2, 5]
    res = CliRunner().invoke(group, ["simulate-devices", "--ports-file", str(path),
                                     "--fault", "unplug:camera@5+5"])
    assert res.exit_code == 2 and "the camera can only be muted" in res.output


def test_setup_file_errors_name_the_field(tmp_path):
    doc = setup_document(minimal_manifest("s", 16, 12), BB, markers="markers.csv")
    path = tmp_path / "setup.json"
    path.write_text(json.dumps(doc))
    with pytest.raises(InvalidInput, match="setup.json: markers: 'markers.csv' not found"):
        read_setup(path)
    del doc["markers"]
    doc["camera"]["resolution"] = [16]
    path.write_text(json.dumps(doc))
    with pytest.raises(InvalidInput, match="setup.json: camera.resolution: expected 2 "
                                           "integers"):
        read_setup(path)
    doc["camera"]["resolution"] = [16, 12]
    doc["blackbodies"]["frames"] = 0
    path.write_text(json.dumps(doc))
    with pytest.raises(InvalidInput, match="setup.json: blackbodies.frames: expected a number "
                                           "of frames per blackbody"):
        read_setup(path)
    doc["blackbodies"]["frames"] = 12
    path.write_text(json.dumps(doc))
    setup = read_setup(path)
    assert setup.blackbodies == Blackbodies((150.0, 20.0), (-150.0, 20.0), 12)
    manifest = setup.manifest("x", 0.0, 3600.0)
    assert manifest["time"] == {"start_utc": "1970-01-01T00:00:00Z",
                                "end_utc": "1970-01-01T01:00:00Z"}
    assert "markers" not in manifest["files"] and manifest["camera"] == doc["camera"]


def test_a_second_mission_in_the_same_folder_is_refused(tmp_path):
    from clearfast_gis.acquire.session import _check_folder

    (tmp_path / "s" / "acquisition").mkdir(parents=True)
    (tmp_path / "s" / "acquisition" / "session.json").write_text(json.dumps(
        {"format": "clearfast-acquisition", "mission_sha256": "abc"}))
    with pytest.raises(InvalidInput, match="holds the acquisition of another mission"):
        _check_folder(tmp_path / "s", "def")
    assert _check_folder(tmp_path / "s", "abc")["mission_sha256"] == "abc"
    (tmp_path / "t").mkdir()
    (tmp_path / "t" / "notes.txt").write_text("x")
    with pytest.raises(InvalidInput, match="not an acquisition folder"):
        _check_folder(tmp_path / "t", "abc")
    assert _check_folder(tmp_path / "new", "abc") is None


def test_fault_specifications():
    assert parse_fault("unplug:gnss@3600+60") == Fault("unplug", "gnss", 3600.0, 60.0)
    assert parse_fault("noise:weather@100") == Fault("noise", "weather", 100.0, 0.0)
    assert parse_fault("rtk-loss@5400+300") == Fault("rtk-loss", "gnss", 5400.0, 300.0)
    assert str(parse_fault("mute:camera@7200+30")) == "mute:camera@7200+30"
    for bad in ("unplug:gnss@10", "noise:camera@5", "explode:ptu@1+1", "rtk-loss@5"):
        with pytest.raises(ValueError):
            parse_fault(bad)


def test_twin_clock_runs_scaled_and_holds_still():
    mono = [100.0]
    clock = TwinClock(1000.0, time_scale=500.0, mono=lambda: mono[0])
    mono[0] = 100.5
    assert clock.now() == 1250.0
    with clock.paused() as t:
        assert t == 1250.0
        mono[0] = 101.0
        with clock.paused():
            mono[0] = 102.0
        assert clock.now() == 1250.0  # still held by the outer block
    mono[0] = 102.5
    assert clock.now() == 1500.0  # 0.5 s after the hold ended
    clock.restart()
    assert clock.now() == 1000.0
    t0 = time.monotonic()
    assert abs(TwinClock(0.0, 2.0).now()) < 2.0 * (time.monotonic() - t0) + 0.01
