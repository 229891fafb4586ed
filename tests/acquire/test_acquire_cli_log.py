"""``clearfast log``: one-line errors, concurrent loggers over ptys, clean stop on signals."""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import sys
import time

import numpy as np

from clearfast_gis.acquire import SimulatedPtu, pty_pair, simulated_ptu_device
from clearfast_gis.acquire.weather import toa5_header
from clearfast_gis.survey import gga_sentence, read_nmea, read_soil_log, read_toa5, rmc_sentence
from clearfast_gis.timeutil import parse_utc

T0 = parse_utc("2026-11-15T10:00:00Z")
CMD = [sys.executable, "-m", "clearfast_gis.cli.main", "log"]


def test_bad_port_gives_one_line_and_exit_1(tmp_path):
    out = tmp_path / "survey"
    p = subprocess.run([*CMD, "--gnss", str(tmp_path / "ttyNOPE") + ",9600", "-o", str(out)],
                       capture_output=True, text=True, timeout=60)
    assert p.returncode == 1
    assert p.stderr.strip().splitlines() == [
        f"clearfast: error: {tmp_path / 'ttyNOPE'}: cannot open serial port "
        "(No such file or directory)"]
    assert not out.exists()  # nothing is written before every port is open


def test_no_instrument_is_a_usage_error(tmp_path):
    p = subprocess.run([*CMD, "-o", str(tmp_path)], capture_output=True, text=True, timeout=60)
    assert p.returncode == 2 and "choose at least one instrument" in p.stderr


def _wait_for(proc: subprocess.Popen, predicate, timeout_s: float = 20.0) -> list[dict]:
    """Read JSON lines from proc.stdout until predicate(last event) holds."""
    events: list[dict] = []
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        line = proc.stdout.readline()
        if not line:
            break
        events.append(json.loads(line))
        if predicate(events[-1]):
            return events
    err = proc.stderr.read() if proc.poll() is not None and proc.stderr else ""
    raise AssertionError(f"condition not reached; events: {events[-2:]} {err}")


def test_all_instruments_then_sigterm_leaves_complete_files(tmp_path):
    out = tmp_path / "survey"
    gnss_lines = b"".join((gga_sentence(T0 + k, 35.17, 33.36, 170.0, 4, 15, 0.6) + "\r\n" +
                           rmc_sentence(T0 + k, 35.17, 33.36) + "\r\n").encode()
                          for k in range(10))
    weather = toa5_header().encode() + \
        b'"2026-11-15 10:01:00",1,15.5,55,1004.0,1.5,400,310,0\r\n'
    soil = b"T,2026-11-15T10:00:00Z,20.5,19.0,18.2,17.5,16.9\r\n"
    with contextlib.ExitStack() as stack:
        (g_fd, g_name), (w_fd, w_name), (s_fd, s_name) = (
            stack.enter_context(pty_pair()) for _ in range(3))
        p_name, _ = stack.enter_context(simulated_ptu_device(SimulatedPtu()))
        proc = subprocess.Popen(
            [*CMD, "--gnss", g_name, "--weather", w_name + ",19200", "--soil", s_name,
             "--ptu", p_name, "-o", str(out), "--progress", "json", "--status-interval", "0.2"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            _wait_for(proc, lambda e: e["event"] == "start")
            os.write(g_fd, gnss_lines + b"$GPGGA,100000.00,35")  # last line unfinished
            os.write(w_fd, weather)
            os.write(s_fd, soil + b"T,2026-11-15T10:10:00Z,20")
            events = _wait_for(proc, lambda e: e["event"] == "status"
                               and e["instruments"]["gnss"]["lines"] == 20
                               and e["instruments"]["weather"]["records"] == 1
                               and e["instruments"]["soil"]["records"] == 1
                               and e["instruments"]["ptu"]["polls"] > 0)
            proc.send_signal(signal.SIGTERM)
            rest, err = proc.communicate(timeout=30)
        finally:
            if proc.poll() is None:
                proc.kill()
    assert proc.returncode == 0, err
    status = events[-1]["instruments"]
    assert status["gnss"]["fix"]["name"] == "RTK fixed" and status["gnss"]["fix"]["n_sats"] == 15
    assert status["ptu"]["pan_deg"] == 0.0 and status["ptu"]["tilt_deg"] == 0.0
    end = json.loads(rest.strip().splitlines()[-1])
    assert end["event"] == "end"
    assert (out / "gnss.nmea").read_bytes() == gnss_lines
    assert len(read_nmea(out / "gnss.nmea")) == 10
    w = read_toa5(out / "weather.dat")
    assert w.air_temp_c.tolist() == [15.5] and w.time_s.tolist() == [T0 + 60.0]
    s = read_soil_log(out / "soil.csv")
    np.testing.assert_allclose(s.temp_c, [[20.5, 19.0, 18.2, 17.5, 16.9]])
    assert (out / "soil.csv").read_bytes().endswith(b"\n")


def test_duration_and_sigint_stop_cleanly(tmp_path):
    with pty_pair() as (fd, name):
        t0 = time.monotonic()
        p = subprocess.run([*CMD, "--gnss", name, "-o", str(tmp_path), "--duration", "0.5",
                            "--progress", "none"], capture_output=True, text=True, timeout=60)
        assert p.returncode == 0, p.stderr
        assert time.monotonic() - t0 < 30
        assert (tmp_path / "gnss.nmea").read_bytes() == b""

        proc = subprocess.Popen([*CMD, "--gnss", name, "-o", str(tmp_path), "--progress",
                                 "json"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True)
        try:
            _wait_for(proc, lambda e: e["event"] == "start")
            line = (gga_sentence(T0, 35.0, 33.0, 100.0, 5, 9, 1.0) + "\r\n").encode()
            os.write(fd, line)
            _wait_for(proc, lambda e: e["instruments"]["gnss"]["lines"] == 1)
            proc.send_signal(signal.SIGINT)
            proc.communicate(timeout=30)
        finally:
            if proc.poll() is None:
                proc.kill()
    assert proc.returncode == 0
    assert (tmp_path / "gnss.nmea").read_bytes() == line


def test_lost_port_is_reported_in_one_line(tmp_path):
    with pty_pair() as (fd, name):
        proc = subprocess.Popen([*CMD, "--gnss", name, "-o", str(tmp_path), "--progress",
                                 "json", "--status-interval", "0.1"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            _wait_for(proc, lambda e: e["event"] == "start")
            os.write(fd, b"$GPTXT,01,01,02,ANTSTATUS=OK*3B\r\n")
            _wait_for(proc, lambda e: e["instruments"]["gnss"]["lines"] == 1)
            os.close(fd)  # the receiver's cable is pulled
            _, err = proc.communicate(timeout=30)
        finally:
            if proc.poll() is None:
                proc.kill()
    assert proc.returncode == 1
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"clearfast: error: {name}: read failed")
    assert (tmp_path / "gnss.nmea").read_bytes() == b"$GPTXT,01,01,02,ANTSTATUS=OK*3B\r\n"
