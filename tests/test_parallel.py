"""Thread helpers: order, exceptions, the thread cap."""

from __future__ import annotations

import threading
import time

import pytest

from clearfast_gis.parallel import n_threads, thread_imap, thread_map


def test_thread_map_keeps_order_and_uses_threads():
    seen = set()

    def slow_square(x):
        seen.add(threading.get_ident())
        time.sleep(0.01 * (5 - x % 5))
        return x * x

    assert thread_map(slow_square, range(20), threads=3) == [x * x for x in range(20)]
    assert len(seen) > 1


def test_thread_imap_is_ordered_lazy_and_bounded():
    started = []

    def f(x):
        started.append(x)
        return -x

    gen = thread_imap(f, range(100), threads=2, ahead=2)
    assert next(gen) == 0
    time.sleep(0.05)
    assert len(started) <= 2 * 2 + 1  # no more than the window ran ahead
    assert list(gen) == [-x for x in range(1, 100)]


def test_exceptions_propagate():
    def boom(x):
        if x == 3:
            raise ValueError("bad item 3")
        return x

    with pytest.raises(ValueError, match="bad item 3"):
        thread_map(boom, range(6), threads=2)
    with pytest.raises(ValueError, match="bad item 3"):
        list(thread_imap(boom, range(6), threads=2))


def test_thread_cap_from_environment(monkeypatch):
    monkeypatch.setenv("CLEARFAST_THREADS", "1")
    assert n_threads() == 1
    assert thread_map(lambda x: threading.get_ident(), range(4)) == [threading.get_ident()] * 4
    monkeypatch.setenv("CLEARFAST_THREADS", "junk")
    assert 1 <= n_threads() <= 4


def test_an_error_drops_the_calls_not_started():
    started = []

    def f(x):
        started.append(x)
        if x == 0:
            raise RuntimeError("stop")
        time.sleep(0.05)
        return x

    with pytest.raises(RuntimeError, match="stop"):
        thread_map(f, range(200), threads=2)
    assert len(started) < 20  # not the 200
