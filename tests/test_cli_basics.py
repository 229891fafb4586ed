"""The command line's frame: help, version, one-line errors."""

from __future__ import annotations

import subprocess
import sys

from clearfast_gis.errors import ClearfastError


def run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "clearfast_gis.cli.main", *args],
                          capture_output=True, text=True, timeout=120)


def test_version_and_help():
    r = run("--version")
    assert r.returncode == 0 and "clearfast" in r.stdout
    r = run("--help")
    assert r.returncode == 0 and "Usage" in r.stdout


def test_unknown_command_is_usage_error():
    r = run("no-such-command")
    assert r.returncode == 2
    assert "Traceback" not in r.stderr


def test_error_one_line():
    e = ClearfastError("expected 2 integers", "survey.json", "camera.resolution")
    assert e.one_line() == "survey.json: camera.resolution: expected 2 integers"
    e = ClearfastError("bad\n  thing", "a.tif")
    assert "\n" not in e.one_line()
