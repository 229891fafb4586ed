"""The chain's programs keep freed memory in the C heap (clearfast_gis.allocator)."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from clearfast_gis import allocator

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="glibc only")

_CHURN = """
import resource, sys
import numpy as np
if sys.argv[1] == "keep":
    from clearfast_gis.allocator import keep_freed_memory
    assert keep_freed_memory()
np.ones(6 << 20).sum()  # 48 MiB
before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
for _ in range(20):
    a = np.ones(6 << 20)  # 48 MiB (above glibc's largest dynamic mmap threshold), freed
    del a
print(resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before)
"""


def _faults(mode: str) -> int:
    env = {k: v for k, v in os.environ.items() if k not in allocator._ENV}
    out = subprocess.run([sys.executable, "-c", _CHURN, mode], env=env, check=True,
                         capture_output=True, text=True)
    return int(out.stdout.strip())


def test_freed_arrays_are_reused_without_page_faults():
    # 20 arrays of 48 MiB: by default each is a fresh mapping, whose pages the kernel zeroes
    # and faults in (12,288 faults, or ~530 with transparent huge pages); a few hundred faults
    # in all once the heap keeps freed memory
    default, kept = _faults("default"), _faults("keep")
    assert default > 20 * 400
    assert kept < default / 5


def test_allocator_settings_in_the_environment_are_left_alone(monkeypatch):
    monkeypatch.setenv("MALLOC_TRIM_THRESHOLD_", "131072")
    assert allocator.keep_freed_memory() is False


def test_the_program_keeps_freed_memory_and_the_function_does_not():
    """``clearfast`` (``main``) sets the heap; ``cli()`` called in a process that embeds the
    toolkit (the tests, a script) leaves that process's allocator as it is."""
    env = {k: v for k, v in os.environ.items() if k not in allocator._ENV}
    code = ("import sys, clearfast_gis.cli.main as m; calls = []\n"
            "m.keep_freed_memory = lambda: calls.append(1)\n"
            "for run in (m.cli, m.main):\n"
            "    sys.argv = ['clearfast', '--version']\n"
            "    try:\n        run()\n    except SystemExit:\n        pass\n"
            "    print('calls', len(calls))")
    out = subprocess.run([sys.executable, "-c", code], env=env, check=True,
                         capture_output=True, text=True)
    assert [ln for ln in out.stdout.splitlines() if ln.startswith("calls")] == ["calls 0",
                                                                                 "calls 1"]
