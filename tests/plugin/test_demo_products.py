"""The plugin on products made by the real chain from the simulated demo survey."""

from __future__ import annotations

import json
import shlex
import sqlite3
import sys

import numpy as np
import pytest

from tests.plugin.test_loader import _render, _rgb

pytestmark = pytest.mark.qgis


def test_demo_products_load_with_styles_time_and_counts(project, demo_products, tmp_path):
    from clearfast.loader import load_products

    loaded = load_products(str(demo_products), project)
    manifest = json.loads((demo_products / "products.json").read_text())
    with sqlite3.connect(demo_products / "anomalies.gpkg") as db:
        for name, layer in loaded.vectors.items():
            assert layer.isValid(), name
            assert layer.crs().authid() == "EPSG:32636"
            n = db.execute(f'SELECT COUNT(*) FROM "{name}"').fetchone()[0]
            assert layer.featureCount() == n, name
    suspects = loaded.vectors["suspects"]
    assert suspects.renderer().type() == "RuleRenderer"
    assert {r.label() for r in suspects.renderer().rootRule().children()} >= {
        "AT mine indication", "AP mine indication", "Clutter"}
    # the outlines of the real chain carry the suspects' columns and show them formatted
    from tests.plugin.test_planner_view import shown

    outlines = loaded.vectors["anomalies"]
    feature = next(f for f in outlines.getFeatures() if f["depth_m"] == f["depth_m"]
                   and f["depth_m"] is not None and f["depth_sigma_m"] is not None)
    assert shown(outlines, feature, "depth") == (
        f"{feature['depth_m'] * 100:.1f} ± {feature['depth_sigma_m'] * 100:.1f} cm")
    assert len(loaded.mosaics) == len(manifest["scans"]) == 6
    for layer in loaded.mosaics:
        assert layer.isValid() and layer.crs().authid() == "EPSG:32636"
        assert layer.temporalProperties().isActive()
    image = _render(project, [suspects, loaded.vectors["footprint"], loaded.mosaics[2]],
                    loaded.extent)
    assert image.save(str(tmp_path / "demo.png"), "PNG")
    rgb = _rgb(image).astype(int)
    background = np.all(rgb == 255, axis=2)
    assert background.mean() < 0.7  # the fan-shaped footprint in its bounding box
    assert len({tuple(c) for c in rgb[~background][::53]}) > 20


def test_process_survey_algorithm_runs_the_real_chain(qgis_app, demo_survey, tmp_path,
                                                      monkeypatch):
    """Processing ▸ CLEARFAST ▸ Process survey on the simulated demo, with the real toolkit."""
    import processing
    from qgis.core import QgsProcessingContext, QgsProcessingFeedback

    monkeypatch.setenv("CLEARFAST_COMMAND",
                       shlex.join([sys.executable, "-m", "clearfast_gis.cli.main"]))
    out = tmp_path / "products"
    context = QgsProcessingContext()
    feedback = QgsProcessingFeedback()
    progress = []
    feedback.progressChanged.connect(progress.append)
    results = processing.run("clearfast:processsurvey",
                             {"SURVEY": str(demo_survey), "OUTPUT": str(out)},
                             context=context, feedback=feedback)
    assert results["OUTPUT"] == str(out)
    assert len(results["MOSAICS"]) == 6
    assert (out / "anomalies.gpkg").is_file() and (out / "report.html").is_file()
    assert progress and max(progress) == pytest.approx(100.0)
    layers = {d.name: context.getMapLayer(lid)
              for lid, d in context.layersToLoadOnCompletion().items()}
    assert "Suspects" in layers and layers["Suspects"].featureCount() > 0
