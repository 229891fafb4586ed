"""Shared test fixtures.

``demo_survey`` / ``demo_products``: the simulated demo survey (seed 0) and its products, made
once per source version and shared by every test process (pytest-xdist workers take a file
lock, the first one builds, the others reuse).
"""

from __future__ import annotations

import fcntl
import hashlib
import os
import shutil
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

REPO = Path(__file__).resolve().parents[1]
SHARED = REPO.parent / "shared"

# Property tests judge the code, not the machine: a loaded CI host (or a neighbour's job on the
# same cores) must not fail a test through Hypothesis's timing health checks or deadlines.
settings.register_profile("clearfast", deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("clearfast")


def _source_key() -> str:
    h = hashlib.sha256()
    for p in sorted((REPO / "clearfast_gis").rglob("*")):
        if p.suffix in (".py", ".json", ".qml") and "__pycache__" not in p.parts:
            h.update(p.relative_to(REPO).as_posix().encode())
            h.update(p.read_bytes())
    return h.hexdigest()[:16]


def _cache_dir() -> Path:
    root = Path(os.environ.get("CLEARFAST_TEST_CACHE",
                               Path(tempfile.gettempdir()) / "clearfast-test-cache"))
    d = root / _source_key()
    d.mkdir(parents=True, exist_ok=True)
    return d


def _build_once(name: str, build) -> Path:
    d = _cache_dir()
    target = d / name
    with open(d / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            if not (d / f"{name}.done").exists():
                if target.exists():
                    shutil.rmtree(target)
                build(target)
                (d / f"{name}.done").write_text("ok")
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)
    return target


SLOW_FIXTURES = frozenset({"demo_survey", "demo_products", "demo_drift_mosaics", "acquired"})
"""Fixtures that simulate, acquire or process a whole survey (minutes on a cold cache): every
test using one is marked ``slow``, so ``pytest -m "not slow"`` is the quick loop."""


def pytest_collection_modifyitems(config, items) -> None:
    for item in items:
        if SLOW_FIXTURES & set(getattr(item, "fixturenames", ())):
            item.add_marker(pytest.mark.slow)


@pytest.fixture(scope="session")
def repo_root() -> Path:
    return REPO


@pytest.fixture(scope="session")
def demo_survey() -> Path:
    """The simulated demo survey, seed 0 (read-only: copy before changing it)."""
    from clearfast_gis.simulate import preset, simulate_survey

    return _build_once("demo-survey", lambda t: simulate_survey(t, preset("demo"), seed=0))


@pytest.fixture(scope="session")
def demo_products(demo_survey) -> Path:
    """``clearfast process`` of the demo survey with default parameters (read-only)."""
    from clearfast_gis.pipeline import process_survey

    return _build_once("demo-products", lambda t: process_survey(demo_survey, t))


@pytest.fixture(scope="session")
def demo_drift_mosaics() -> tuple[Path, Path]:
    """The demo survey with the trial's drifting lift (seed 1), and its mosaics."""
    from clearfast_gis.pipeline import ProcessOptions, process_survey
    from clearfast_gis.simulate import preset, simulate_survey

    survey = _build_once("demo-drift-survey",
                         lambda t: simulate_survey(t, preset("demo"), seed=1, drift=True))
    products = _build_once("demo-drift-mosaics", lambda t: process_survey(
        survey, t, ProcessOptions(invert=False), until="residuals_and_footprint"))
    return survey, products
