"""Atomic writes never leave a half-written file under the final name."""

from __future__ import annotations

import os

import pytest

from clearfast_gis.atomic import atomic_path, write_text
from clearfast_gis.errors import OutputError


def test_write_and_replace(tmp_path):
    p = tmp_path / "a" / "x.txt"
    write_text(p, "one")
    write_text(p, "two")
    assert p.read_text() == "two"
    assert sorted(os.listdir(p.parent)) == ["x.txt"]


def test_failure_keeps_previous(tmp_path):
    p = tmp_path / "x.txt"
    write_text(p, "old")
    with pytest.raises(RuntimeError), atomic_path(p) as tmp:
        tmp.write_text("half")
        raise RuntimeError("killed")
    assert p.read_text() == "old"
    assert sorted(os.listdir(tmp_path)) == ["x.txt"]


def test_unwritable_folder(tmp_path):
    blocker = tmp_path / "not-a-folder"
    blocker.write_text("a file where a folder should be")
    with pytest.raises(OutputError, match="not-a-folder"):
        write_text(blocker / "x.txt", "y")
