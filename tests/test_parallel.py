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


def _squares_and_pids(items: list[int]) -> list[tuple[int, int]]:
    """A chunk's work for the ProcessChunks tests (module level: workers import it)."""
    import os

    return [(x * x, os.getpid()) for x in items]


def _fails_on_seven(items: list[int]) -> list[int]:
    if 7 in items:
        raise ValueError("seven")
    return items


def test_process_chunks_keep_order_and_run_in_other_processes():
    import os

    from clearfast_gis.parallel import ProcessChunks

    with ProcessChunks(_squares_and_pids, range(11), processes=3) as work:
        out = work.result()
    assert [v for v, _ in out] == [x * x for x in range(11)]
    pids = {p for _, p in out}
    assert len(pids) == 3 and os.getpid() not in pids


def test_process_chunks_with_one_process_run_here(monkeypatch):
    import os

    from clearfast_gis.parallel import ProcessChunks

    monkeypatch.setenv("CLEARFAST_THREADS", "1")
    out = ProcessChunks(_squares_and_pids, [2, 3]).result()
    assert out == [(4, os.getpid()), (9, os.getpid())]


def test_a_failed_worker_chunk_is_computed_here_and_its_error_raised():
    from clearfast_gis.parallel import ProcessChunks

    with pytest.raises(ValueError, match="seven"):
        ProcessChunks(_fails_on_seven, range(10), processes=2).result()
    assert ProcessChunks(_fails_on_seven, range(7), processes=2).result() == list(range(7))


def test_process_chunks_without_an_interpreter_to_start_run_here(monkeypatch):
    import os
    import sys

    from clearfast_gis.parallel import ProcessChunks

    monkeypatch.setattr(sys, "executable", "/nonexistent/python")
    out = ProcessChunks(_squares_and_pids, range(4), processes=2).result()
    assert out == [(x * x, os.getpid()) for x in range(4)]
