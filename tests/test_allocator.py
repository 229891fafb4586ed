"""The chain's programs keep freed memory in the C heap (clearfast_gis.allocator)."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from clearfast_gis import allocator

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="glibc only")

_PROBE = """
import ctypes, sys
import numpy as np
if sys.argv[1] == "keep":
    from clearfast_gis.allocator import keep_freed_memory
    assert keep_freed_memory()

class MallInfo2(ctypes.Structure):  # glibc >= 2.33
    _fields_ = [(name, ctypes.c_size_t) for name in (
        "arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks", "uordblks",
        "fordblks", "keepcost")]

mallinfo2 = ctypes.CDLL(None).mallinfo2
mallinfo2.restype = MallInfo2
a = np.ones(6 << 20)  # 48 MiB, above glibc's largest dynamic mmap threshold (32 MiB)
live = mallinfo2()
del a
freed = mallinfo2()
print(live.hblkhd >> 20, freed.fordblks >> 20)
"""


def _heap(mode: str) -> tuple[int, int]:
    """(MiB in mappings of their own while a 48 MiB array lives, MiB the heap keeps free
    once it is freed) in a fresh interpreter."""
    env = {k: v for k, v in os.environ.items() if k not in allocator._ENV}
    out = subprocess.run([sys.executable, "-c", _PROBE, mode], env=env, check=True,
                         capture_output=True, text=True)
    mapped, kept = out.stdout.split()
    return int(mapped), int(kept)


def test_freed_arrays_stay_in_the_heap_for_reuse():
    # glibc's defaults: the array is a mapping of its own, unmapped when freed (the next one
    # is fresh memory the kernel zeroes and faults in again); with the settings it comes from
    # the heap, which keeps it once freed
    mapped, kept = _heap("default")
    assert mapped >= 48 and kept < 48
    mapped, kept = _heap("keep")
    assert mapped < 48 and kept >= 48


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
