"""Fixtures of the batch and resume tests: tiny surveys built once per session."""

from __future__ import annotations

import dataclasses
import shutil
from pathlib import Path

import pytest

from clearfast_gis.survey.testing import make_minimal_survey

MAX_ANOMALIES = 3
"""Anomalies characterised and drawn per survey in these tests (the report draws one figure per
anomaly; three keep a tiny survey's run to a few seconds)."""

CAPPED_CLI = Path(__file__).with_name("capped_cli.py")
"""The command line with ``max_anomalies`` capped, for subprocess runs."""


@pytest.fixture(scope="session")
def tiny_surveys(tmp_path_factory) -> list[Path]:
    """Two small valid surveys with different folder names."""
    root = tmp_path_factory.mktemp("batch_surveys")
    return [make_minimal_survey(root / "alpha", seed=1),
            make_minimal_survey(root / "bravo", seed=2)]


@pytest.fixture
def broken_survey(tmp_path, tiny_surveys) -> Path:
    """A copy of a tiny survey whose soil log is missing (fails validation)."""
    dst = tmp_path / "charlie"
    shutil.copytree(tiny_surveys[0], dst)
    (dst / "soil.csv").unlink()
    return dst


@pytest.fixture
def few_anomalies(monkeypatch):
    """Cap ``max_anomalies`` of the options the command line builds (keeps runs short)."""
    import clearfast_gis.cli.options as cli_options

    original = cli_options.build_options

    def build(params, invert=True):
        return dataclasses.replace(original(params, invert), max_anomalies=MAX_ANOMALIES)

    monkeypatch.setattr(cli_options, "build_options", build)
    return MAX_ANOMALIES
