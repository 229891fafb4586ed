"""The chain's packages are layered: the domains (mosaics, attitude, detection, export, ...)
never import the orchestration (``clearfast_gis.pipeline``); only the chain's users do."""

from __future__ import annotations

import ast
from pathlib import Path

import clearfast_gis

PACKAGE = Path(clearfast_gis.__file__).parent

USERS_OF_THE_PIPELINE = {"pipeline", "cli", "batch", "evaluation"}
"""Top-level parts of the package allowed to import the pipeline."""


def _imported(path: Path) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
        elif isinstance(node, ast.Import):
            names.update(a.name for a in node.names)
    return names


def test_domains_do_not_import_the_pipeline():
    offenders = []
    for path in sorted(PACKAGE.rglob("*.py")):
        part = path.relative_to(PACKAGE).parts[0].removesuffix(".py")
        if part in USERS_OF_THE_PIPELINE:
            continue
        bad = sorted(n for n in _imported(path)
                     if n == "clearfast_gis.pipeline" or n.startswith("clearfast_gis.pipeline."))
        offenders += [f"{path.relative_to(PACKAGE)}: {n}" for n in bad]
    assert offenders == []


def test_the_check_sees_an_import_of_the_pipeline(tmp_path):
    p = tmp_path / "m.py"
    p.write_text("def f():\n    from clearfast_gis.pipeline.state import StageState\n")
    assert "clearfast_gis.pipeline.state" in _imported(p)
    assert "clearfast_gis.mosaic.scanjob" in _imported(PACKAGE / "pipeline" / "scanjob.py")
