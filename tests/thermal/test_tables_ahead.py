"""Site tables built ahead on a helper thread: each once, in the order asked, errors raised
where the table is needed."""

from __future__ import annotations

import threading

import pytest

from clearfast_gis.thermal.tables_ahead import TablesAhead


def test_each_table_built_once_in_the_order_asked():
    built: list = []
    threads: set = set()

    def build(key):
        built.append(key)
        threads.add(threading.current_thread().name)
        return ("table", key)

    with TablesAhead(build) as tables:
        assert tables.ahead(("ap", 1)) is True
        assert tables.ahead(("at", 1)) is True
        assert tables.ahead(("ap", 1)) is False  # asked for already
        assert tables.get(("at", 1)) == ("table", ("at", 1))
        assert tables.get(("ap", 0)) == ("table", ("ap", 0))  # not asked ahead: built now
        assert tables.get(("ap", 1)) == ("table", ("ap", 1))
    assert built == [("ap", 1), ("at", 1), ("ap", 0)]
    assert threads == {t for t in threads if t.startswith("clearfast-tables")}
    assert threading.current_thread().name not in threads


def test_a_failed_build_raises_where_the_table_is_needed():
    def build(key):
        if key == "bad":
            raise ValueError("no table for bad")
        return key

    with TablesAhead(build) as tables:
        tables.ahead("bad")
        assert tables.get("good") == "good"
        with pytest.raises(ValueError, match="no table for bad"):
            tables.get("bad")


def test_builds_not_started_are_dropped_on_leaving():
    started = threading.Event()
    gate = threading.Event()
    built: list = []

    def build(key):
        started.set()
        gate.wait(5.0)
        built.append(key)
        return key

    with TablesAhead(build) as tables:
        for k in range(5):
            tables.ahead(k)
        assert started.wait(5.0)  # the helper thread is in the first build
        threading.Timer(0.2, gate.set).start()
    # leaving waited for the running build and dropped the four queued behind it
    assert built == [0]
