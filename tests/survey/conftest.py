"""Fixtures for the survey package tests."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from clearfast_gis.survey.testing import make_minimal_survey


@pytest.fixture(scope="session")
def pristine_survey(tmp_path_factory) -> Path:
    """One valid survey, built once; copy it before changing it."""
    return make_minimal_survey(tmp_path_factory.mktemp("pristine") / "s", n_bands=2)


@pytest.fixture
def survey_copy(pristine_survey, tmp_path) -> Path:
    """A fresh copy of the valid survey that a test may break."""
    dst = tmp_path / "s"
    shutil.copytree(pristine_survey, dst)
    return dst
