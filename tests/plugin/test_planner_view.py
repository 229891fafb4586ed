"""The planner's view in a real QGIS (headless): readable values, labels, order, hidden layers.

Everything is read through the styles stored in the GeoPackage, as any QGIS opening the file
sees them (not set by the plugin).
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

pytestmark = pytest.mark.qgis

MINES = {"A001", "A002", "A003", "A004"}  # at_mine / ap_mine in make_demo_products


def _open(gpkg: Path, layer: str = "suspects"):
    from qgis.core import QgsVectorLayer

    lyr = QgsVectorLayer(f"{gpkg}|layername={layer}", layer, "ogr")
    assert lyr.isValid()
    return lyr


def shown(layer, feature, name: str) -> str:
    """The value as QGIS shows it in forms, identify results and the attribute table."""
    from qgis.core import QgsApplication

    idx = layer.fields().indexOf(name)
    assert idx >= 0, name
    setup = layer.editorWidgetSetup(idx)
    formatter = QgsApplication.fieldFormatterRegistry().fieldFormatter(setup.type())
    return formatter.representValue(layer, idx, setup.config(), None, feature[name])


def _by_id(layer) -> dict:
    return {f["anomaly_id"]: f for f in layer.getFeatures()}


@pytest.fixture(scope="module")
def ranked_products(products, tmp_path_factory):
    """The products with the ranking fields (p_mine, priority, cue_confidence) and a
    ``candidates`` layer, as the ranked-suspects products have them."""
    import pyogrio

    from clearfast_gis.export import default_styles, write_geopackage

    root = tmp_path_factory.mktemp("ranked") / "products"
    shutil.copytree(products.root, root)
    gpkg = root / "anomalies.gpkg"
    layers = {name: pyogrio.read_dataframe(gpkg, layer=name)
              for name in ("suspects", "anomalies", "markers", "footprint")}
    suspects = layers["suspects"].rename(columns={"confidence": "cue_confidence"})
    # priority deliberately against the cue order: A008 first, A001 last
    ids = sorted(suspects["anomaly_id"], reverse=True)
    suspects["priority"] = [ids.index(a) + 1 for a in suspects["anomaly_id"]]
    suspects["p_mine"] = [1.0 - 0.1 * (p - 1) for p in suspects["priority"]]
    # a diffusivity the curve did not constrain: 1-sigma larger than the value (table's end)
    loose = suspects["anomaly_id"] == "A004"
    suspects.loc[loose, ["diffusivity_m2s", "diffusivity_sigma_m2s"]] = [3.2e-5, 1.2e-3]
    clutter = suspects["class_cue"] == "clutter"
    layers["candidates"] = suspects[clutter].assign(set_aside_reason="one scan only")
    layers["suspects"] = suspects[~clutter]
    write_geopackage(gpkg, layers, default_styles(layers))
    return root


def test_values_with_units_and_precision(products, qgis_app):
    layer = _open(products.root / "anomalies.gpkg")
    rows = _by_id(layer)
    a1 = rows["A001"]
    depth_cm, sigma_cm = a1["depth_m"] * 100, a1["depth_sigma_m"] * 100
    assert shown(layer, a1, "depth") == f"{depth_cm:.1f} ± {sigma_cm:.1f} cm" == "1.0 ± 0.5 cm"
    # two significant digits, in mm²/s (1e-7 m²/s = 0.10 mm²/s)
    assert shown(layer, a1, "diffusivity") == "0.10 ± 0.020 mm²/s"
    assert shown(layer, rows["A008"], "diffusivity") == "0.40 ± 0.080 mm²/s"
    assert shown(layer, rows["A007"], "depth") == "not characterised"
    for name in ("contrast_day_k", "contrast_night_k"):
        assert shown(layer, a1, name) == f"{a1[name]:.2f}"
    assert shown(layer, a1, "cue_confidence_pct") == f"{100 * a1['cue_confidence']:.0f} %"
    assert shown(layer, a1, "depth_m") == f"{a1['depth_m']:.3f}"
    assert shown(layer, a1, "short_id") == "S-001"
    assert layer.attributeDisplayName(layer.fields().indexOf("contrast_day_k")) \
        == "Day contrast (K)"
    assert layer.attributeDisplayName(layer.fields().indexOf("depth")) == "Burial depth ± 1σ"
    assert shown(layer, a1, "likelihood") == "not estimated"  # no p_mine in these products


def test_likelihood_in_percent_with_ranking_fields(ranked_products, qgis_app):
    layer = _open(ranked_products / "anomalies.gpkg")
    rows = _by_id(layer)
    assert shown(layer, rows["A008"], "likelihood") == "100 %"
    assert shown(layer, rows["A001"], "likelihood") == "30 %"
    assert shown(layer, rows["A001"], "cue_confidence_pct") \
        == f"{100 * rows['A001']['cue_confidence']:.0f} %"


def test_unconstrained_diffusivity_is_not_printed_as_a_number(ranked_products, qgis_app):
    """As report.html shows it: the form's text is the report's, not '32 ± 1.2e+03'."""
    from clearfast_gis.report.html import UNCONSTRAINED_TEXT, diffusivity_text

    layer = _open(ranked_products / "anomalies.gpkg")
    rows = _by_id(layer)
    a4 = rows["A004"]
    assert shown(layer, a4, "diffusivity") == UNCONSTRAINED_TEXT \
        == diffusivity_text(a4["diffusivity_m2s"], a4["diffusivity_sigma_m2s"])
    assert shown(layer, rows["A008"], "diffusivity") == "0.40 ± 0.080 mm²/s"


def _sorted_ids(layer) -> list[str]:
    from qgis.core import QgsExpression, QgsExpressionContext, QgsExpressionContextUtils

    expr = QgsExpression(layer.attributeTableConfig().sortExpression())
    ctx = QgsExpressionContext(QgsExpressionContextUtils.globalProjectLayerScopes(layer))
    keys = []
    for f in layer.getFeatures():
        ctx.setFeature(f)
        keys.append((expr.evaluate(ctx), f["anomaly_id"]))
    assert not expr.hasEvalError(), expr.evalErrorString()
    assert layer.attributeTableConfig().sortOrder() == 0  # ascending
    return [a for _, a in sorted(keys)]


def test_table_ordered_by_cue_and_contrast_without_priority(products, qgis_app):
    order = _sorted_ids(_open(products.root / "anomalies.gpkg"))
    # AT mines (larger contrast first), AP mines, unknown, clutter
    assert order == ["A001", "A002", "A003", "A004", "A008", "A007", "A005", "A006"]


def test_table_ordered_by_priority_when_present(ranked_products, qgis_app):
    order = _sorted_ids(_open(ranked_products / "anomalies.gpkg"))
    assert order == ["A008", "A007", "A004", "A003", "A002", "A001"]


def _labels(layer, extent):
    from qgis.core import QgsMapRendererSequentialJob, QgsMapSettings
    from qgis.PyQt.QtCore import QSize

    settings = QgsMapSettings()
    settings.setLayers([layer])
    settings.setDestinationCrs(layer.crs())
    settings.setExtent(extent)
    settings.setOutputSize(QSize(800, 1000))
    job = QgsMapRendererSequentialJob(settings)
    job.start()
    job.waitForFinished()
    return sorted(lab.labelText for lab in job.takeLabelingResults().allLabels())


def test_labels_only_for_mine_indications_with_short_ids(project, products):
    from clearfast.loader import load_products

    loaded = load_products(str(products.root), project)
    suspects = loaded.vectors["suspects"]
    assert _labels(suspects, loaded.extent) == ["S-001", "S-002", "S-003", "S-004"]
    # clutter is not drawn until switched on
    rules = {r.label(): r for r in suspects.renderer().rootRule().children()}
    assert not rules["Clutter"].active()


def test_candidates_hidden_but_loaded(project, ranked_products):
    from clearfast.loader import load_products

    loaded = load_products(str(ranked_products), project)
    assert loaded.vectors["candidates"].featureCount() == 2
    root = project.layerTreeRoot()
    assert not root.findLayer(loaded.vectors["candidates"].id()).isVisible()
    assert root.findLayer(loaded.vectors["suspects"].id()).isVisible()
    assert loaded.vectors["candidates"].renderer().type() == "RuleRenderer"


def test_outlines_share_the_formats(products, qgis_app):
    layer = _open(products.root / "anomalies.gpkg", "anomalies")
    a1 = _by_id(layer)["A001"]  # these outlines have only id, polarity and area
    assert shown(layer, a1, "area_m2") == f"{a1['area_m2']:.3f}"
    assert layer.attributeDisplayName(layer.fields().indexOf("area_m2")) == "Area (m²)"
    assert layer.renderer().type() == "categorizedSymbol"  # warm/cool by day, as before
    assert not layer.labelsEnabled()


def test_form_has_the_ranking_fields_when_present(ranked_products, qgis_app):
    from tests.plugin.test_loader import form_field_names

    layer = _open(ranked_products / "anomalies.gpkg")
    assert {"priority", "likelihood", "p_mine", "cue_confidence", "depth"} <= form_field_names(
        layer)
    assert layer.attributeDisplayName(layer.fields().indexOf("priority")) \
        == "Priority (1 = first)"


def test_mine_indications_by_likelihood_when_present(project, ranked_products):
    from clearfast.fieldmap import mine_rows
    from clearfast.loader import load_products

    # p_mine: A008 1.0, A007 0.9, A004 0.6, A003 0.5, A002 0.4, A001 0.3 (export default 0.5)
    loaded = load_products(str(ranked_products), project)
    suspects = loaded.vectors["suspects"]
    assert _labels(suspects, loaded.extent) == ["S-003", "S-004", "S-007", "S-008"]
    assert [f["anomaly_id"] for f in mine_rows(suspects)] == ["A008", "A007", "A004", "A003"]
