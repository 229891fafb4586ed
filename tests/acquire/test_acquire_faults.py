"""Unplugged devices, garbage and hung units, through real pseudo-terminals and the drivers."""

from __future__ import annotations

import os
import threading
import time

import pytest

from clearfast_gis.acquire import GnssLogger, PanTiltUnit, PortSpec, SimulatedPtu, open_port
from clearfast_gis.acquire.ptu import PtuTimeout
from clearfast_gis.acquire.ptydevice import PtyDevice
from clearfast_gis.survey import gga_sentence, read_nmea, zda_sentence
from clearfast_gis.timeutil import parse_utc

T0 = parse_utc("2026-11-15T10:00:00Z")
RES_DEG = 185.1428 / 3600.0


class Talker:
    """An engine that sends what it is told to (and records what it receives)."""

    def __init__(self) -> None:
        self.out = bytearray()
        self.received = bytearray()
        self.lock = threading.Lock()

    def say(self, data: bytes) -> None:
        with self.lock:
            self.out += data

    def feed(self, data: bytes) -> None:
        self.received += data

    def pending_output(self) -> bytes:
        with self.lock:
            data, self.out = bytes(self.out), bytearray()
        return data


def _until(predicate, timeout_s: float = 5.0) -> None:
    deadline = time.monotonic() + timeout_s
    while not predicate():
        assert time.monotonic() < deadline, "condition not reached"
        time.sleep(0.005)


def _epoch(k: int) -> bytes:
    return (gga_sentence(T0 + k, 35.17, 33.36, 170.0, 4, 14, 0.7) + "\r\n"
            + zda_sentence(T0 + k) + "\r\n").encode()


def test_unplugged_receiver_is_reconnected_through_its_link(tmp_path):
    talker = Talker()
    events: list[tuple[str, str, str]] = []
    link = tmp_path / "by-id" / "gnss"
    with PtyDevice(talker, link=link, name="gnss") as dev:
        spec = PortSpec(str(link), 115200)
        logger = GnssLogger(open_port(spec), tmp_path / "gnss.nmea", reopen=lambda: open_port(spec),
                            retry_s=0.02, on_event=lambda *e: events.append(e))
        stop = threading.Event()
        th = logger.start(stop)
        try:
            talker.say(_epoch(0) + _epoch(1))
            _until(lambda: logger.n_lines_in == 4)
            talker.say(b"$GPGGA,100002.000,3510")  # cut in the middle of a line
            time.sleep(0.05)
            dev.unplug()
            assert not link.exists()
            _until(lambda: not logger.connected)
            time.sleep(0.1)  # a few failed attempts while the link is missing
            dev.replug()
            _until(lambda: logger.connected)
            talker.say(_epoch(3))
            _until(lambda: logger.n_lines_in == 6)
        finally:
            stop.set()
            th.join(5.0)
    assert logger.error is None and logger.n_disconnects == 1
    assert [e[1] for e in events[1:]] == ["disconnected", "reconnected"]
    assert "read failed" in events[1][2] and events[2][2] == str(link)
    # the torn line is not in the log; the epochs before and after are, byte for byte
    assert (tmp_path / "gnss.nmea").read_bytes() == _epoch(0) + _epoch(1) + _epoch(3)
    assert read_nmea(tmp_path / "gnss.nmea").time_s.tolist() == [T0, T0 + 1, T0 + 3]
    assert logger.time_s == T0 + 3


def test_garbage_bytes_are_logged_raw_and_counted(tmp_path):
    talker = Talker()
    with PtyDevice(talker, name="gnss") as dev:
        logger = GnssLogger(open_port(PortSpec(dev.path, 9600)), tmp_path / "gnss.nmea")
        stop = threading.Event()
        th = logger.start(stop)
        try:
            noise = bytes(range(0, 256, 3)).replace(b"\n", b"")
            talker.say(_epoch(0))
            dev.inject(noise + b"\r\n")
            talker.say(_epoch(1).replace(b",4,14,", b",4,15,", 1))  # checksum now wrong
            talker.say(_epoch(2))
            _until(lambda: logger.n_lines_in == 7)
        finally:
            stop.set()
            th.join(5.0)
    assert logger.n_unparseable == 1 and logger.n_bad_checksum == 1
    assert logger.fix.time_s == T0 + 2 and logger.fix.n_sats == 14
    log = read_nmea(tmp_path / "gnss.nmea")
    assert log.n_unparseable == 1 and log.n_bad_checksum == 1 and len(log) == 2


def test_ptu_move_survives_an_unplugged_cable(tmp_path):
    sim = SimulatedPtu()
    link = tmp_path / "ptu"
    events: list[tuple[str, str, str]] = []
    with PtyDevice(sim, link=link, name="ptu") as dev:
        spec = PortSpec(str(link), 9600)
        ptu = PanTiltUnit(open_port(spec), timeout_s=0.5, reopen=lambda: open_port(spec),
                          reconnect_s=10.0, retry_s=0.05, on_event=lambda *e: events.append(e))
        ptu.initialize()
        assert ptu.move_to(10.0, -20.0) == pytest.approx((194 * RES_DEG, -389 * RES_DEG))
        dev.unplug()
        threading.Timer(0.3, dev.replug).start()
        t0 = time.monotonic()
        pan, tilt = ptu.move_to(-30.0, -45.0)
        assert 0.25 < time.monotonic() - t0 < 5.0
        assert (pan, tilt) == pytest.approx((-583 * RES_DEG, -875 * RES_DEG))
        assert sim.position_steps() == (-583.0, -875.0)
        assert ptu.n_reconnects == 1
        assert [e[1] for e in events] == ["disconnected", "reconnected"]
        # set up again after the reconnection: echo off, terse, immediate mode
        assert sim.received[-8:-5] == ["ED", "FT", "I"] and not sim.echo and sim.terse
        ptu.port.close()


def test_hung_ptu_times_out_after_trying_to_reconnect(tmp_path):
    sim = SimulatedPtu()
    with PtyDevice(sim, link=tmp_path / "ptu", name="ptu") as dev:
        spec = PortSpec(dev.path, 9600)
        ptu = PanTiltUnit(open_port(spec), timeout_s=0.2, reopen=lambda: open_port(spec),
                          reconnect_s=0.5, retry_s=0.05)
        ptu.initialize()
        dev.mute = True
        t0 = time.monotonic()
        with pytest.raises(PtuTimeout, match="no reply to 'PP"):
            ptu.move_to(5.0, 5.0)
        assert 0.5 <= time.monotonic() - t0 < 5.0
        assert dev.dropped_bytes > 0
        ptu.port.close()


def test_nobody_reading_loses_output_but_never_blocks_the_device():
    talker = Talker()
    with PtyDevice(talker, name="idle") as dev:
        for _ in range(50):
            talker.say(b"x" * 4000 + b"\r\n")
        _until(lambda: not talker.out)  # the serving thread is not stuck on a full queue
        assert dev.dropped_bytes > 0
        fd = os.open(dev.path, os.O_RDWR | os.O_NOCTTY)
        os.close(fd)
