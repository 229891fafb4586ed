"""Simulated surveys shared by the simulator's tests (each simulated once per session)."""

from __future__ import annotations

from dataclasses import replace

import pytest

from clearfast_gis.simulate import preset, simulate_survey


@pytest.fixture(scope="session")
def demo_survey(tmp_path_factory):
    """The demo preset, seed 0, as the CLI writes it."""
    root = tmp_path_factory.mktemp("sim") / "demo"
    return simulate_survey(root, preset("demo"), seed=0)


@pytest.fixture(scope="session")
def small_config():
    """A reduced demo: 3 scans, 96x72 frames, a 5 m x 4 m area (for variants)."""
    return replace(preset("demo"), n_scans=3, resolution=(96, 72), area_width_m=5.0,
                   area_length_m=4.0, lift_height_m=6.0, grid_cell_m=0.02,
                   gnss_interval_s=10.0)


@pytest.fixture(scope="session")
def drift_survey(tmp_path_factory, small_config):
    """The reduced demo with the trial's drifting lift, scans spread to the survey's end."""
    cfg = replace(small_config, n_scans=4, first_scan_offset_s=0.0)
    return simulate_survey(tmp_path_factory.mktemp("sim") / "drift", cfg, seed=3, drift=True)
