"""The examples in the docstrings of the main public functions run as written."""

from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = [
    "clearfast_gis.solar",
    "clearfast_gis.detection.voting",
    "clearfast_gis.attitude.adjust",
    "clearfast_gis.attitude.neighbours",
    "clearfast_gis.export.layout",
    "clearfast_gis.pipeline.run",
    "clearfast_gis.progress",
    "clearfast_gis.kernels",
    "clearfast_gis.report.html",
    "clearfast_gis.errors",
]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0, f"{name} has no examples"
    assert result.failed == 0
