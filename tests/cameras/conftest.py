"""Real radiometric camera files (``../shared/data/radiometric-samples``) and their manifest."""

from __future__ import annotations

import functools
import json
import shutil

import pytest

from tests.conftest import SHARED

SAMPLES = SHARED / "data" / "radiometric-samples"
MANIFEST = json.loads((SAMPLES / "manifest.json").read_text()) \
    if (SAMPLES / "manifest.json").exists() else {"files": []}


def entries(*categories: str) -> list[dict]:
    """Manifest entries of the given categories, as pytest params named by file."""
    return [pytest.param(e, id=e["local_path"].rsplit("/", 1)[-1])
            for e in MANIFEST["files"] if e["category"] in categories]


def sample(entry: dict):
    """Path of a manifest entry's file (the shared data lies beside the checkout, CI included)."""
    p = SAMPLES / entry["local_path"]
    assert p.exists(), f"real sample missing: {p}"
    return p


def reference_pixels(entry: dict) -> dict:
    """{name: {row, col, temp_C, ...}} of the entry's first (independent) decoder."""
    return next(iter(entry["reference_temps"].values()))["pixels"]


@pytest.fixture(autouse=True)
def _needs_exiftool():
    if shutil.which("exiftool") is None:
        pytest.fail("exiftool is required (Debian libimage-exiftool-perl; scripts/bootstrap.sh)")


@functools.cache
def _read(path: str, scale_k: float | None):
    from clearfast_gis.cameras import read_frames

    return read_frames(path, scale_k=scale_k)


def frame_of(entry: dict, scale_k: float | None = None):
    """The single frame of a sample file, read once per test session (exiftool is slow)."""
    frames = _read(str(sample(entry)), scale_k)
    assert len(frames) == 1
    return frames[0]
