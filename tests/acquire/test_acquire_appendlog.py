"""Line splitting and the append-only log."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.acquire import AppendLog, LineSplitter


@settings(deadline=None)
@given(st.lists(st.binary(max_size=40).filter(lambda b: b"\n" not in b), max_size=20),
       st.lists(st.integers(min_value=1, max_value=17), min_size=1, max_size=10),
       st.binary(max_size=30).filter(lambda b: b"\n" not in b))
def test_splitter_returns_the_lines_whatever_the_chunking(lines, cuts, tail):
    stream = b"".join(x + b"\n" for x in lines) + tail
    sp = LineSplitter()
    got: list[bytes] = []
    i = k = 0
    while i < len(stream):
        n = cuts[k % len(cuts)]
        got += sp.feed(stream[i:i + n])
        i += n
        k += 1
    assert got == [x + b"\n" for x in lines]
    assert sp.pending == tail


def test_splitter_drops_overlong_garbage():
    sp = LineSplitter(max_line_bytes=100)
    assert sp.feed(b"x" * 150) == []
    assert sp.n_overlong == 1
    assert sp.feed(b"ok\r\n") == [b"ok\r\n"]


def test_header_written_once_and_appending_continues(tmp_path):
    p = tmp_path / "sub" / "log.csv"
    with AppendLog(p, b"h1,h2\n") as log:
        assert log.was_empty
        log.append([b"1,2\n", b"3,4\n"])
    with AppendLog(p, b"h1,h2\n") as log:
        assert not log.was_empty
        log.append([b"5,6\n"])
    assert p.read_bytes() == b"h1,h2\n1,2\n3,4\n5,6\n"


def test_a_torn_last_line_is_terminated_before_appending(tmp_path):
    p = tmp_path / "log.nmea"
    p.write_bytes(b"$GPGGA,1\r\n$GPG")  # a write cut by a power loss
    with AppendLog(p) as log:
        log.append([b"$GPRMC,2\r\n"])
    assert p.read_bytes().splitlines() == [b"$GPGGA,1", b"$GPG", b"$GPRMC,2"]


def test_append_refuses_incomplete_lines(tmp_path):
    import pytest

    with AppendLog(tmp_path / "x") as log, pytest.raises(ValueError):
        log.append([b"no line break"])
