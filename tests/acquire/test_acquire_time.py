"""UTC from the receiver: ZDA/RMC sentences, GGA dating, fix changes, the survey clock."""

from __future__ import annotations

import math
import threading

import pynmea2
import pytest
import serial
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.acquire import GnssLogger
from clearfast_gis.acquire.clock import ClockError, GnssClock, HostClock
from clearfast_gis.survey import gga_sentence, parse_nmea, rmc_sentence, zda_sentence
from clearfast_gis.survey.nmea import sentence_time
from clearfast_gis.timeutil import parse_utc

T0 = parse_utc("2026-11-15T23:59:58Z")


def test_zda_sentence_bytes_and_parse():
    # the NMEA standard's example "$GPZDA,201530.00,04,07,2002,00,00*60" with one more "0":
    # 0x60 ^ ord("0") = 0x50
    text = zda_sentence(parse_utc("2002-07-04T20:15:30Z"))
    assert text == "$GPZDA,201530.000,04,07,2002,00,00*50"
    tod, midnight = sentence_time(pynmea2.parse(zda_sentence(T0), check=True))
    assert (tod, midnight) == (86398.0, parse_utc("2026-11-15T00:00:00Z"))


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=946684800.0, max_value=4102444799.0))
def test_rmc_and_zda_times_round_trip_to_the_millisecond(t):
    t = round(t, 3)
    for text in (zda_sentence(t), rmc_sentence(t, 35.0, 33.0)):
        tod, midnight = sentence_time(pynmea2.parse(text, check=True))
        assert abs(tod + midnight - t) < 5e-4
        assert 0.0 <= tod < 86400.0


def test_parse_nmea_dates_gga_by_zda_across_midnight():
    lines = []
    for k in range(5):  # 23:59:58 .. 00:00:02, GGA then ZDA, no RMC
        lines += [gga_sentence(T0 + k, 35.0, 33.0, 100.0, 4, 12, 0.8), zda_sentence(T0 + k)]
    log = parse_nmea("\r\n".join(lines) + "\r\n")
    assert log.time_s.tolist() == [T0 + k for k in range(5)]
    assert log.n_unparseable == 0


def _logger(tmp_path, clock=lambda: T0 - 86400.0 * 3, **kw) -> GnssLogger:
    return GnssLogger(serial.serial_for_url("loop://", timeout=0.05), tmp_path / "gnss.nmea",
                      clock=clock, **kw)


def test_logger_reports_receiver_time_and_fix_changes(tmp_path):
    times: list[tuple[float, float]] = []
    events: list[tuple[str, str, str]] = []
    mono = iter(range(100, 1000))
    g = _logger(tmp_path, on_time=lambda t, m: times.append((t, m)), mono=lambda: next(mono),
                on_event=lambda *e: events.append(e))
    quality = [4, 4, 0, 0, 5, 4]
    for k, q in enumerate(quality):
        t = T0 + k
        lat = math.nan if q == 0 else 35.0
        g.feed((gga_sentence(t, lat, 33.0, 100.0, q, 12, 0.8) + "\r\n" + zda_sentence(t)
                + "\r\n" + rmc_sentence(t, lat, 33.0, valid=q > 0) + "\r\n").encode())
    g.log.close()
    # one ZDA per epoch and one RMC per epoch with a fix (a void RMC never gives the time),
    # each with the arrival of its batch
    valid = [(0, 1) if q > 0 else (0,) for q in quality]
    assert [t for t, _ in times] == [T0 + k for k in range(6) for _ in valid[k]]
    assert [m for _, m in times] == [100 + k for k in range(6) for _ in valid[k]]
    assert g.time_s == T0 + 5
    # GGA at 00:00:01 (k = 3) is dated by the previous ZDA of 23:59:59 + rollover
    assert g.fix.time_s == T0 + 5 and g.fix.fix_name == "RTK fixed"
    assert [e[2].split(" at ")[0] for e in events] == [
        "RTK fixed", "RTK fixed -> no fix", "no fix -> RTK float", "RTK float -> RTK fixed"]
    assert events[1] == ("gnss", "fix", "RTK fixed -> no fix at 00:00:00 UTC")
    assert g.n_fix_changes == 4 and g.status()["time_utc"] == "2026-11-16T00:00:03.000Z"


def test_gga_time_of_day_before_the_last_date_rolls_over(tmp_path):
    g = _logger(tmp_path)
    g.feed((zda_sentence(T0) + "\r\n").encode())  # 23:59:58 on the 15th
    g.feed((gga_sentence(T0 + 3.0, 35.0, 33.0, 1.0, 1, 5, 2.0) + "\r\n").encode())
    assert g.fix.time_s == T0 + 3.0  # 00:00:01 on the 16th
    g.feed((zda_sentence(T0 + 4.0) + "\r\n").encode())
    g.feed((gga_sentence(T0 - 1.0, 35.0, 33.0, 1.0, 1, 5, 2.0) + "\r\n").encode())
    assert g.fix.time_s == T0 - 1.0  # a late 23:59:57 belongs to the 15th
    g.log.close()


def test_malformed_time_fields_count_as_unparseable(tmp_path):
    g = _logger(tmp_path)
    body = "GPZDA,256161.00,04,07,2002,00,00"
    from clearfast_gis.survey import nmea_checksum
    g.feed(f"${body}*{nmea_checksum(body)}\r\n".encode())
    assert g.n_unparseable == 1 and g.time_s is None
    g.log.close()


class FakeMono:
    def __init__(self) -> None:
        self.t = 1000.0

    def __call__(self) -> float:
        return self.t


def test_gnss_clock_extrapolates_from_the_least_delayed_sentence():
    mono = FakeMono()
    clock = GnssClock(time_scale=1000.0, mono=mono)
    with pytest.raises(ClockError, match="gnss: no UTC time"):
        clock.now()
    assert not clock.ready and clock.age_s() == math.inf
    clock.observe(T0, 1000.0)
    clock.observe(T0 + 5.0, 1000.007)  # arrived 2 ms late (2 s of scene time)
    mono.t = 1000.010
    assert clock.now() == pytest.approx(T0 + 10.0, abs=1e-6)
    assert clock.age_s() == pytest.approx(0.003)
    mono.t = 1000.0101
    assert clock.now() == pytest.approx(T0 + 10.1, abs=1e-6)
    mono.t = 999.0  # a monotonic clock never does this; the reading still does not go back
    assert clock.now() == pytest.approx(T0 + 10.1, abs=1e-6)
    assert clock.ready and clock.n_observed == 2


def test_clock_waits_scale_to_wall_time():
    clock = GnssClock(time_scale=500.0)
    ev = threading.Event()
    ev.set()
    assert clock.wait(ev, 1e6)  # returns at once when the event is set
    ev.clear()
    import time
    t0 = time.monotonic()
    clock.sleep(25.0)  # 0.05 s of wall time
    assert not clock.wait(ev, 25.0)
    assert 0.09 <= time.monotonic() - t0 < 1.0
    assert abs(HostClock().now() - time.time()) < 1.0
    with pytest.raises(ValueError):
        GnssClock(time_scale=0.0)


def test_void_or_implausible_dates_never_move_the_survey_clock(tmp_path):
    mono = FakeMono()
    clock = GnssClock(mono=mono)
    g = _logger(tmp_path, on_time=clock.observe, mono=mono)
    cold = "$GPRMC,000012.00,V,,,,,,,050180,,,N"  # a cold start's void RMC dated 1980/2080
    g.feed((f"{cold}*{_cs(cold[1:])}\r\n").encode())
    assert not clock.ready and g.time_s is None
    for k in range(4):
        mono.t = 1000.0 + k
        g.feed((zda_sentence(T0 + k) + "\r\n").encode())
    # a valid-looking ZDA of a week-rollover receiver, 1024 weeks off: refused by the logger
    # (more than a year from the host clock); one two days off: refused by the locked clock
    mono.t = 1004.0
    g.feed((zda_sentence(T0 + 4.0 - 1024 * 7 * 86400.0) + "\r\n").encode())
    assert g.n_refused_times == 1 and clock.n_refused == 0
    g.feed((zda_sentence(T0 + 4.0 - 2 * 86400.0) + "\r\n").encode())
    assert g.n_refused_times == 2 and clock.n_refused == 1
    assert clock.now() == pytest.approx(T0 + 4.0, abs=1e-6)
    assert g.time_s == T0 + 3.0
    mono.t = 1005.0
    g.feed((zda_sentence(T0 + 5.0) + "\r\n").encode())
    assert clock.now() == pytest.approx(T0 + 5.0, abs=1e-6) and g.time_s == T0 + 5.0
    g.log.close()


def test_clock_before_lock_follows_the_latest_receiver_time():
    mono = FakeMono()
    clock = GnssClock(mono=mono)
    assert clock.observe(T0 - 40 * 365 * 86400.0, 1000.0)  # one bogus first sentence
    with pytest.raises(ClockError, match="must agree"):
        clock.now()  # one sentence alone gives no time
    assert clock.observe(T0, 1000.5)  # not yet locked: the receiver's new time restarts
    assert not clock.ready
    assert clock.observe(T0 + 1.0, 1001.5)
    mono.t = 1002.5
    assert clock.ready and clock.now() == pytest.approx(T0 + 2.0, abs=1e-6)


def _cs(body: str) -> str:
    from clearfast_gis.survey import nmea_checksum

    return nmea_checksum(body)
