"""GnssLogger: raw NMEA lines recorded exactly, checksums counted, latest fix kept."""

from __future__ import annotations

import os
import threading
import time

import numpy as np
import serial

from clearfast_gis.acquire import GnssLogger, pty_pair
from clearfast_gis.survey import gga_sentence, read_nmea, rmc_sentence
from clearfast_gis.timeutil import parse_utc

T0 = parse_utc("2026-11-15T09:58:00Z")


def _stream(n: int = 20) -> tuple[list[bytes], int, int]:
    """GGA+RMC epochs with some corrupted checksums and junk; (lines, n_bad, n_junk)."""
    lines: list[bytes] = []
    n_bad = n_junk = 0
    for k in range(n):
        t = T0 + k
        q = 4 if k % 5 else 5
        gga = gga_sentence(t, 35.17 + 1e-6 * k, 33.36, 170.0 + 0.01 * k, q, 14, 0.7)
        rmc = rmc_sentence(t, 35.17 + 1e-6 * k, 33.36)
        if k % 7 == 3:  # corrupt one character of the body: the checksum no longer matches
            gga = gga.replace("GPGGA,", "GPGGA,1", 1)[:-3] + gga[-3:]
            n_bad += 1
        lines += [(gga + "\r\n").encode(), (rmc + "\r\n").encode()]
        if k == 11:
            lines.append(b"receiver banner: firmware 3.1\r\n")
            n_junk += 1
    return lines, n_bad, n_junk


def _run(logger: GnssLogger, write, lines: list[bytes], chunk: int, tail: bytes = b"") -> None:
    stop = threading.Event()
    th = logger.start(stop)
    data = b"".join(lines) + tail
    for i in range(0, len(data), chunk):
        write(data[i:i + chunk])
    deadline = time.monotonic() + 5.0
    while logger.n_lines_in < len(lines) and time.monotonic() < deadline:
        time.sleep(0.01)
    stop.set()
    th.join(5.0)
    assert not th.is_alive()


def test_loop_url_records_exactly_the_lines_sent(tmp_path):
    lines, n_bad, n_junk = _stream()
    port = serial.serial_for_url("loop://", timeout=0.05)
    path = tmp_path / "gnss.nmea"
    g = GnssLogger(port, path, clock=lambda: T0)
    _run(g, port.write, lines, chunk=37, tail=b"$GPGGA,half a line")
    assert path.read_bytes() == b"".join(lines)  # the unfinished last line is not written
    assert g.n_bad_checksum == n_bad
    assert g.n_unparseable == n_junk
    assert g.n_sentences == len(lines) - n_bad - n_junk
    log = read_nmea(path)  # the survey reader sees the same file the same way
    assert log.n_bad_checksum == n_bad and log.n_unparseable == n_junk
    assert len(log) == 20 - n_bad
    # latest fix: the last epoch (k = 19), RTK fixed, dated by its RMC
    assert g.fix is not None
    assert g.fix.fix_quality == 4 and g.fix.n_sats == 14
    assert abs(g.fix.time_s - (T0 + 19)) < 1e-6
    np.testing.assert_allclose([g.fix.lat_deg, g.fix.lon_deg, g.fix.alt_m],
                               [35.17 + 19e-6, 33.36, 170.19], atol=1e-7)
    status = g.status()
    assert status["fix"]["name"] == "RTK fixed" and status["bad_checksum"] == n_bad


def test_pty_device_and_appending_to_an_existing_log(tmp_path):
    lines, n_bad, _ = _stream(8)
    path = tmp_path / "gnss.nmea"
    first, second = lines[:6], lines[6:]
    with pty_pair() as (master, name):
        port = serial.Serial(name, 115200, timeout=0.05)
        try:
            _run(GnssLogger(port, path), lambda b: os.write(master, b), first, chunk=5)
            g2 = GnssLogger(port, path)
            _run(g2, lambda b: os.write(master, b), second, chunk=64)
        finally:
            port.close()
    assert path.read_bytes() == b"".join(lines)
    assert g2.n_bad_checksum == sum(1 for x in second if b"GPGGA,1" in x)


def test_gga_before_any_rmc_is_dated_by_the_host_clock(tmp_path):
    port = serial.serial_for_url("loop://", timeout=0.05)
    g = GnssLogger(port, tmp_path / "gnss.nmea", clock=lambda: T0 + 30.0)
    g.feed((gga_sentence(T0 + 5.0, 35.0, 33.0, 100.0, 1, 7, 1.2) + "\r\n").encode())
    assert g.fix is not None and abs(g.fix.time_s - (T0 + 5.0)) < 1e-6
    assert g.fix.fix_name == "GPS"
    g.log.close()
