"""Fixtures of the hard-input tests: one valid tiny survey, copied and broken per test."""

from __future__ import annotations

import dataclasses
import json
import shutil
from pathlib import Path

import pytest

from clearfast_gis.cli.main import cli
from clearfast_gis.survey.testing import make_minimal_survey

MAX_ANOMALIES = 2
"""Anomalies drawn per run (one report figure each): keeps a processed survey to seconds."""


@pytest.fixture(scope="session")
def pristine(tmp_path_factory) -> Path:
    """A valid survey (2 scans x 3 positions, one band, 16 x 12 pixels), built once."""
    return make_minimal_survey(tmp_path_factory.mktemp("hard") / "s", seed=3)


@pytest.fixture
def survey(pristine, tmp_path) -> Path:
    """A fresh copy of the valid survey that a test may break."""
    dst = tmp_path / "survey"
    shutil.copytree(pristine, dst)
    return dst


@pytest.fixture
def process(monkeypatch, capsys):
    """``clearfast process SURVEY -o PRODUCTS --no-invert`` in this process.

    Returns (exit status, stdout, stderr). ``max_anomalies`` is capped to keep runs short.
    """
    import clearfast_gis.cli.options as cli_options

    original = cli_options.build_options
    monkeypatch.setattr(cli_options, "build_options", lambda params, invert=True:
                        dataclasses.replace(original(params, invert),
                                            max_anomalies=MAX_ANOMALIES))

    def run(survey: Path, products: Path, *extra: str) -> tuple[int, str, str]:
        with pytest.raises(SystemExit) as e:
            cli(["process", str(survey), "-o", str(products), "--no-invert", "--progress",
                 "none", *extra])
        out, err = capsys.readouterr()
        return e.value.code, out, err

    return run


def assert_fatal(result: tuple[int, str, str], expected_start: str) -> None:
    """Exit status 1 and exactly one line on stderr, starting as expected; no traceback."""
    code, out, err = result
    assert code == 1, out + err
    assert "Traceback" not in out + err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("clearfast: error: " + expected_start), lines[0]


def assert_nothing_half_written(products: Path) -> None:
    """No temporary file is left and every product under its final name opens completely."""
    import pyogrio
    import rasterio

    if not products.exists():
        return
    for p in products.rglob("*"):
        name = p.name
        assert not (name.startswith(".") and ".part" in name), p
        if p.suffix == ".tif":
            with rasterio.open(p) as ds:
                ds.read()
        elif p.suffix == ".gpkg":
            for layer, _ in pyogrio.list_layers(p):
                pyogrio.read_dataframe(p, layer=layer)
        elif p.suffix == ".json":
            json.loads(p.read_text())


def products_warnings(products: Path) -> list[str]:
    """The ``warnings`` of ``products.json``."""
    return json.loads((products / "products.json").read_text())["warnings"]
