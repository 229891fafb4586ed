"""PanTiltUnit driver against the simulated unit over a pty; the reply parser."""

from __future__ import annotations

import time

import pytest
import serial
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.acquire import (
    PanTiltUnit,
    PtuError,
    PtuLimitError,
    PtuProtocolError,
    PtuReply,
    PtuTimeout,
    SimulatedPtu,
    deg_to_steps,
    format_reply,
    parse_reply,
    simulated_ptu_device,
    steps_to_deg,
)
from clearfast_gis.errors import ClearfastError

RES_ARCSEC = 185.1428
RES_DEG = RES_ARCSEC / 3600.0


@pytest.fixture
def unit():
    with simulated_ptu_device(SimulatedPtu(echo=True, terse=False)) as (name, sim):
        port = serial.Serial(name, 9600, timeout=0.05)
        try:
            yield PanTiltUnit(port, timeout_s=1.0, move_timeout_s=5.0), sim
        finally:
            port.close()


def test_degrees_steps_conversion():
    assert deg_to_steps(30.0, RES_DEG) == 583  # 30 / 0.0514286 = 583.33
    assert deg_to_steps(-45.0, RES_DEG) == -875  # -874.99...
    assert steps_to_deg(583, RES_DEG) == pytest.approx(29.98285, abs=1e-5)
    for a in (-159.0, -12.345, 0.0, 0.02, 77.7):
        assert abs(steps_to_deg(deg_to_steps(a, RES_DEG), RES_DEG) - a) <= RES_DEG / 2 + 1e-12
    with pytest.raises(ValueError):
        deg_to_steps(1.0, 0.0)


def test_initialize_queries_resolution_and_moves(unit):
    ptu, sim = unit
    ptu.initialize()  # the unit starts with echo on and verbose replies
    assert ptu.pan_resolution_deg == pytest.approx(RES_DEG, rel=1e-9)
    assert ptu.tilt_resolution_deg == pytest.approx(RES_DEG, rel=1e-9)
    assert not sim.echo and sim.terse
    pan, tilt = ptu.move_to(30.0, -45.0)
    assert sim.received[-5:] == ["PP583", "TP-875", "A", "PP", "TP"]
    assert (pan, tilt) == pytest.approx((583 * RES_DEG, -875 * RES_DEG), abs=1e-12)
    assert sim.position_steps() == (583.0, -875.0)


def test_await_waits_for_the_motion(unit):
    ptu, sim = unit
    sim.pan.speed_steps_s = sim.tilt.speed_steps_s = 2000.0
    ptu.initialize()
    t0 = time.monotonic()
    ptu.move_to(-40.0, 10.0)  # 778 pan steps at 2000 steps/s: about 0.39 s
    assert time.monotonic() - t0 >= 0.35
    assert ptu.position_steps() == (-778, 194)


def test_verbose_echoed_replies_are_understood(unit):
    ptu, sim = unit
    ptu.pan_resolution_deg = ptu.tilt_resolution_deg = RES_DEG  # configured, not queried
    ptu.move_to(5.0, 2.0)
    assert sim.echo and not sim.terse  # never initialised: still echoing, verbose
    assert ptu.position_steps() == (97, 39)
    assert "PR" not in sim.received


def test_limits_are_queried_and_checked_before_sending(unit):
    ptu, sim = unit
    ptu.initialize()
    assert ptu.limits_steps == (-3090, 3090, -2000, 604)  # from verbose PN PX TN TX replies
    lim = ptu.limits_deg()
    assert lim == pytest.approx((-3090 * RES_DEG, 3090 * RES_DEG, -2000 * RES_DEG,
                                 604 * RES_DEG), abs=1e-12)
    n = len(sim.received)
    with pytest.raises(PtuLimitError) as err:
        ptu.move_to(170.0, 0.0)
    assert str(err.value) == (f"{ptu.name}: pan/tilt unit: pan 170.000 deg is outside the "
                              "unit's range -158.914 to 158.914 deg")
    with pytest.raises(PtuLimitError, match="tilt 31.100 deg is outside .* -102.857 to 31.063"):
        ptu.move_to(0.0, 31.1)
    assert len(sim.received) == n  # nothing was sent
    assert ptu.move_to(158.9, 31.05) == pytest.approx((3090 * RES_DEG, 604 * RES_DEG))


def test_error_reply_gives_a_clear_message(unit):
    ptu, _ = unit
    ptu.initialize()
    ptu.limits_steps = None  # a unit that does not tell its limits: it refuses by itself
    with pytest.raises(PtuError) as err:
        ptu.move_to(170.0, 0.0)
    msg = str(err.value)
    assert "refused 'PP3306'" in msg and "Maximum allowable Pan position is 3090" in msg
    assert err.value.path.startswith("/dev/")
    with pytest.raises(PtuError, match="Minimum allowable Tilt position is -2000"):
        ptu.move_to(0.0, -120.0)
    with pytest.raises(PtuError, match="Illegal Command"):
        ptu.command("XYZ")


def test_timeout_names_the_command_and_port(unit):
    ptu, sim = unit
    ptu.initialize()
    sim.mute = True
    ptu.timeout_s = 0.3
    t0 = time.monotonic()
    with pytest.raises(PtuTimeout) as err:
        ptu.position()
    assert 0.25 <= time.monotonic() - t0 < 5.0
    assert str(err.value).endswith("pan/tilt unit: no reply to 'PP' within 0.3 s")
    sim.mute = False
    assert ptu.position_steps() == (0, 0)  # a late reply does not desynchronise the driver


def test_unconfigured_resolution_is_an_error(unit):
    ptu, _ = unit
    with pytest.raises(PtuError, match="resolution unknown"):
        ptu.move_to(1.0, 1.0)


def test_garbage_reply_is_a_protocol_error():
    with pytest.raises(PtuProtocolError, match="unexpected reply"):
        parse_reply("\x00\xffgarbage")


_text = st.text(st.characters(blacklist_categories=("Cc", "Cs")), max_size=40)


@settings(deadline=None)
@given(st.booleans(), _text)
def test_reply_format_parse_round_trip(ok, text):
    reply = PtuReply(ok, text.strip())
    assert parse_reply(format_reply(reply)) == reply


@settings(deadline=None)
@given(st.integers(min_value=-10**7, max_value=10**7),
       st.sampled_from(["", "Current Pan position is ", "Tilt position: "]))
def test_reply_numbers(value, prefix):
    assert parse_reply(f"* {prefix}{value}\r\n").number() == value


@settings(deadline=None)
@given(st.floats(min_value=1e-3, max_value=1e4, allow_nan=False), st.booleans())
def test_resolution_numbers_with_echo(arcsec, terse):
    body = f"{arcsec!r}" if terse else f"Pan resolution is {arcsec!r} seconds arc per position"
    reply = parse_reply(f"PR * {body}\r\n", echo="PR")
    assert reply.ok and reply.number() == pytest.approx(arcsec, rel=1e-12)


@settings(deadline=None)
@given(st.text(max_size=60), st.one_of(st.none(), _text))
def test_parser_never_fails_unexpectedly(line, echo):
    try:
        reply = parse_reply(line, echo=echo)
    except PtuProtocolError as exc:
        assert isinstance(exc, ClearfastError)
        return
    assert reply.text == reply.text.strip()
    assert parse_reply(format_reply(reply)) == reply  # a normal form
    try:
        value = reply.number()
    except PtuProtocolError:
        return
    assert value == value and abs(value) < float("inf")
