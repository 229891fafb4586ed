"""Build ``clearfast_gis/styles/suspects.qml`` (the planner's default style) in real QGIS.

It also gives the anomaly outlines (``anomalies.qml``, same fields) the same fields and form,
keeping their symbology.

Run with QGIS's Python (Debian ``python3-qgis``), from the repository root::

    QT_QPA_PLATFORM=offscreen python scripts/build_suspects_style.py

The style is made with the QGIS API on the suspects layer of a small products folder
(:func:`clearfast_gis.export.testing.make_demo_products`) and saved as QML, so the file is
exactly what QGIS 3.22 itself writes. What it holds:

- a rule-based renderer: mine indications (AT/AP cue) large red triangles drawn on top, other
  suspects small muted orange circles, clutter grey and switched off (one click in the legend);
  features drawn in priority order (the most urgent last, on top);
- labels for mine indications only, with the short id ``S-NNN``, placed around the point;
  QGIS drops overlapping labels;
- virtual fields with units and sensible precision (depth in cm with its 1-sigma, diffusivity
  in mm²/s with two significant digits, likelihood and confidence in %), aliases in words,
  Range widgets with a fixed precision for the stored numbers, and a tabbed form;
- the attribute table sorted by priority.

The expressions read the ranking fields with ``attribute('name')``, which is NULL when the
layer has no such field: the same style orders by ``priority`` and shows ``p_mine`` when the
products have them, and by class cue and contrast when they do not.
"""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from clearfast_gis.report.html import UNCONSTRAINED_TEXT  # noqa: E402


def _mine_expression() -> str:
    from clearfast_gis.export.mine_action import DEFAULT_MIN_LIKELIHOOD, MINE_CUES

    cues = ", ".join(f"'{c}'" for c in MINE_CUES)
    return (f"coalesce(attribute('p_mine') >= {DEFAULT_MIN_LIKELIHOOD}, "
            f"\"class_cue\" IN ({cues}))")


MINE = _mine_expression()
"""Mine indications, as the mine-action export selects them: a mine likelihood ``p_mine`` from
the export's default threshold when the products have one, else an AT/AP class cue."""
SHORT_ID = ("'S-' || lpad(to_string(to_int(regexp_substr(\"anomaly_id\", '(\\\\d+)$'))), "
            "3, '0')")
CUE_RANK = ("CASE WHEN \"class_cue\" = 'at_mine' THEN 0 WHEN \"class_cue\" = 'ap_mine' THEN 1 "
            "WHEN \"class_cue\" = 'unknown' THEN 2 ELSE 3 END")
ORDER_KEY = (f"coalesce(attribute('priority'), 1000000 * ({CUE_RANK}) "
             "- round(1000 * max(abs(\"contrast_day_k\"), abs(\"contrast_night_k\"))))")
"""Sort key, ascending = most urgent first: ``priority`` when present, else the class cue
(AT, AP, unknown, clutter) and then the larger of the day/night contrasts."""


def _sig2(value: str) -> str:
    """Expression: ``value`` (non-zero) with two significant digits, as text."""
    digits = f"max(0, 1 - floor(log10(abs({value}))))"
    return (f"CASE WHEN {value} = 0 THEN '0' "
            f"ELSE format_number(round({value}, 1 - floor(log10(abs({value})))), {digits}) END")


def _with_sigma(value: str, sigma: str, fmt, unit: str, unconstrained: bool = False) -> str:
    """Expression: ``value ± sigma unit``; with ``unconstrained``, a value whose 1-sigma is
    larger than itself reads as the report's ``UNCONSTRAINED_TEXT``."""
    loose = (f"WHEN {sigma} > {value} THEN '{UNCONSTRAINED_TEXT}' " if unconstrained else "")
    return (f"CASE WHEN {value} IS NULL THEN 'not characterised' " + loose +
            f"WHEN {sigma} IS NULL THEN {fmt(value)} || ' {unit}' "
            f"ELSE {fmt(value)} || ' ± ' || {fmt(sigma)} || ' {unit}' END")


def _cm(value: str) -> str:
    return f"format_number({value}, 1)"


def _percent(value: str, missing: str = "NULL") -> str:
    return (f"CASE WHEN {value} IS NULL THEN {missing} "
            f"ELSE format_number(100 * {value}, 0) || ' %' END")


VIRTUAL_FIELDS = (
    # name, QVariant type name, expression, alias
    ("short_id", "String", SHORT_ID, "Short id"),
    ("depth", "String", _with_sigma('"depth_m" * 100', '"depth_sigma_m" * 100', _cm, "cm"),
     "Burial depth ± 1σ"),
    ("diffusivity", "String",
     _with_sigma('"diffusivity_m2s" * 1e6', '"diffusivity_sigma_m2s" * 1e6', _sig2, "mm²/s",
                 unconstrained=True),
     "Thermal diffusivity ± 1σ"),
    ("likelihood", "String", _percent("attribute('p_mine')", "'not estimated'"),
     "Mine likelihood"),
    ("cue_confidence_pct", "String",
     _percent("coalesce(attribute('cue_confidence'), attribute('confidence'))"),
     "Class cue confidence"),
)

PRECISION = {
    "x": 2, "y": 2, "lat": 7, "lon": 7, "area_m2": 3, "diameter_m": 2, "circularity": 2,
    "depth_m": 3, "depth_sigma_m": 3, "confidence": 2, "cue_confidence": 2, "p_mine": 2,
    "contrast_day_k": 2, "contrast_night_k": 2, "mine_curve_r": 2,
    "mine_curve_level": 2,
}
"""Decimals shown for stored numbers (their unit is in the alias)."""

ALIASES = {
    "anomaly_id": "Suspect id", "x": "Easting (m, survey UTM)", "y": "Northing (m, survey UTM)",
    "lat": "Latitude (°, WGS84)", "lon": "Longitude (°, WGS84)", "area_m2": "Area (m²)",
    "diameter_m": "Diameter (m)", "circularity": "Circularity (0-1)",
    "depth_m": "Burial depth (m)", "depth_sigma_m": "Depth uncertainty, 1σ (m)",
    "diffusivity_m2s": "Thermal diffusivity (m²/s)",
    "diffusivity_sigma_m2s": "Diffusivity uncertainty, 1σ (m²/s)",
    "status": "Characterisation status", "polarity": "Polarity", "class_cue": "Class cue",
    "confidence": "Class cue confidence (0-1)", "cue_confidence": "Class cue confidence (0-1)",
    "p_mine": "Mine likelihood (0-1)", "priority": "Priority (1 = first)",
    "set_aside_reason": "Set aside because",
    "n_scans": "Scans seen", "contrast_day_k": "Day contrast (K)",
    "contrast_night_k": "Night contrast (K)",
    "mine_curve_r": "Match with a mine's diurnal curve (-1 to 1)",
    "mine_curve_level": "Offset from a mine's diurnal curve (swings)",
    "fix_quality": "GNSS fix quality",
    "found_by": "Found by (scans / stack)",
    "figure": "Contrast curve", "contrast_series": "Contrast series (JSON)",
}

FORM = (
    ("Suspect", (
        ("Identification", ("short_id", "anomaly_id", "priority", "class_cue", "likelihood",
                            "cue_confidence_pct", "status", "found_by", "polarity",
                            "set_aside_reason")),
        ("Burial depth and soil", ("depth", "diffusivity")),
        ("Thermal contrast", ("contrast_day_k", "contrast_night_k", "mine_curve_r",
                              "mine_curve_level", "n_scans")),
        ("Shape", ("diameter_m", "area_m2", "circularity")),
    )),
    ("Contrast curve", (("Contrast curve", ("figure",)),)),
    ("Position", (("Position", ("x", "y", "lat", "lon", "fix_quality")),)),
    ("Stored values", (("Stored values", (
        "depth_m", "depth_sigma_m", "diffusivity_m2s", "diffusivity_sigma_m2s", "p_mine",
        "cue_confidence", "confidence", "contrast_series")),)),
)
"""Form tabs -> group boxes -> fields."""

MAP_TIP = ("<b>[% \"short_id\" %]</b> [% \"class_cue\" %] ([% \"status\" %])<br/>"
           "depth [% \"depth\" %]<br/>diffusivity [% \"diffusivity\" %]")


def _marker(shape: str, rgb: tuple[int, int, int], size_mm: float, opacity: float,
            outline: str = "35,35,35,255"):
    from qgis.core import QgsMarkerSymbol

    symbol = QgsMarkerSymbol.createSimple({
        "name": shape, "color": ",".join(map(str, rgb)) + ",255", "size": str(size_mm),
        "outline_color": outline, "outline_width": "0.3"})
    symbol.setOpacity(opacity)
    return symbol


def renderer():
    """Rule-based renderer: mine indications prominent, others muted, clutter off."""
    from qgis.core import QgsFeatureRequest, QgsRuleBasedRenderer

    from clearfast_gis.export.styles import CLASS_COLOURS_RGB as C

    root = QgsRuleBasedRenderer.Rule(None)
    rules = (
        ("AT mine indication", f"({MINE}) AND \"class_cue\" = 'at_mine'",
         _marker("triangle", C["at_mine"], 5.0, 1.0), True),
        ("AP mine indication", f"({MINE}) AND \"class_cue\" = 'ap_mine'",
         _marker("triangle", C["ap_mine"], 4.0, 1.0), True),
        ("Mine indication, other cue",
         f"({MINE}) AND coalesce(\"class_cue\" NOT IN ('at_mine', 'ap_mine'), true)",
         _marker("circle", C["at_mine"], 3.2, 1.0), True),
        ("Other suspect", f"NOT ({MINE}) AND coalesce(\"class_cue\" <> 'clutter', true)",
         _marker("circle", C["unknown"], 2.4, 0.6, "90,90,90,255"), True),
        ("Clutter", f"NOT ({MINE}) AND \"class_cue\" = 'clutter'",
         _marker("circle", C["clutter"], 2.0, 0.6, "90,90,90,255"), False),
    )
    for label, expr, symbol, active in rules:
        rule = QgsRuleBasedRenderer.Rule(symbol, 0, 0, expr, label)
        rule.setActive(active)
        root.appendChild(rule)
    rend = QgsRuleBasedRenderer(root)
    rend.setOrderByEnabled(True)
    # the most urgent drawn last (on top)
    rend.setOrderBy(QgsFeatureRequest.OrderBy([
        QgsFeatureRequest.OrderByClause(ORDER_KEY, False)]))
    return rend


def labeling():
    """Short ids of mine indications only, around the point, never overlapping."""
    from qgis.core import (
        QgsPalLayerSettings,
        QgsRuleBasedLabeling,
        QgsTextBufferSettings,
        QgsTextFormat,
    )
    from qgis.PyQt.QtGui import QColor, QFont

    fmt = QgsTextFormat()
    font = QFont("DejaVu Sans")
    font.setBold(True)
    fmt.setFont(font)
    fmt.setSize(9)
    fmt.setColor(QColor(120, 0, 0))
    buffer = QgsTextBufferSettings()
    buffer.setEnabled(True)
    buffer.setSize(0.8)
    buffer.setColor(QColor(255, 255, 255))
    fmt.setBuffer(buffer)
    settings = QgsPalLayerSettings()
    settings.setFormat(fmt)
    settings.fieldName = "short_id"
    settings.isExpression = False
    settings.placement = QgsPalLayerSettings.OrderedPositionsAroundPoint
    settings.dist = 1.0
    settings.priority = 9
    settings.displayAll = False
    root = QgsRuleBasedLabeling.Rule(None)
    rule = QgsRuleBasedLabeling.Rule(settings)
    rule.setFilterExpression(MINE)
    rule.setDescription("Mine indications")
    root.appendChild(rule)
    return QgsRuleBasedLabeling(root)


def form(layer) -> None:
    """Tabbed form of :data:`FORM`."""
    from qgis.core import (
        QgsAttributeEditorContainer,
        QgsAttributeEditorField,
        QgsEditFormConfig,
    )

    config = layer.editFormConfig()
    config.clearTabs()
    root = config.invisibleRootContainer()
    for tab_name, groups in FORM:
        tab = QgsAttributeEditorContainer(tab_name, root)
        tab.setIsGroupBox(False)  # a tab (containers default to group boxes)
        for group_name, names in groups:
            group = QgsAttributeEditorContainer(group_name, tab)
            group.setIsGroupBox(True)
            for name in names:
                idx = layer.fields().indexOf(name)
                if idx >= 0:
                    group.addChildElement(QgsAttributeEditorField(name, idx, group))
            tab.addChildElement(group)
        config.addTab(tab)
    config.setLayout(QgsEditFormConfig.TabLayout)
    layer.setEditFormConfig(config)


RANKING_FIELDS = (("p_mine", "Double"), ("priority", "Int"), ("cue_confidence", "Double"),
                  ("set_aside_reason", "String"))
"""Fields of the ranked-suspects products that the demo products lack: the style is built on a
layer that has them too, so their aliases, formats and form places are stored as well."""


def style_layer(gpkg: Path, name: str, geometry: str):
    """An empty memory layer with the fields of ``gpkg``'s layer ``name`` and the ranking
    fields, in the survey CRS."""
    from qgis.core import QgsField, QgsVectorLayer
    from qgis.PyQt.QtCore import QVariant

    options = QgsVectorLayer.LayerOptions(loadDefaultStyle=False)
    source = QgsVectorLayer(f"{gpkg}|layername={name}", name, "ogr", options)
    assert source.isValid()
    layer = QgsVectorLayer(f"{geometry}?crs={source.crs().authid()}", name, "memory")
    fields = [f for f in source.fields() if f.name() != "fid"]
    fields += [QgsField(n, getattr(QVariant, kind)) for n, kind in RANKING_FIELDS
               if source.fields().indexOf(n) < 0]
    layer.dataProvider().addAttributes(fields)
    layer.updateFields()
    return layer


def apply_fields(layer) -> None:
    """Virtual fields, aliases, widgets with precision, form, table order, map tip."""
    from qgis.core import QgsEditorWidgetSetup, QgsField
    from qgis.PyQt.QtCore import QVariant

    for name, kind, expr, _ in VIRTUAL_FIELDS:
        layer.addExpressionField(expr, QgsField(name, getattr(QVariant, kind)))
    # aliases first: setting an alias afterwards drops the field's widget set-up
    aliases = dict(ALIASES, **{n: a for n, _, _, a in VIRTUAL_FIELDS})
    for idx, fld in enumerate(layer.fields()):
        if fld.name() in aliases:
            layer.setFieldAlias(idx, aliases[fld.name()])
    for idx, fld in enumerate(layer.fields()):
        name = fld.name()
        if name in PRECISION:
            layer.setEditorWidgetSetup(idx, QgsEditorWidgetSetup("Range", {
                "Precision": PRECISION[name], "Min": -1e9, "Max": 1e9, "Step": 1,
                "Style": "SpinBox", "AllowNull": True}))
        elif name != "figure":
            layer.setEditorWidgetSetup(idx, QgsEditorWidgetSetup("TextEdit", {
                "IsMultiline": False, "UseHtml": False}))
    form(layer)
    table = layer.attributeTableConfig()
    table.setSortExpression(ORDER_KEY)
    table.setSortOrder(0)
    layer.setAttributeTableConfig(table)
    layer.setMapTipTemplate(MAP_TIP)
    layer.setDisplayExpression('"short_id"')


def save(layer, out: Path) -> None:
    from qgis.core import QgsMapLayer

    categories = (QgsMapLayer.Symbology | QgsMapLayer.Labeling | QgsMapLayer.Fields
                  | QgsMapLayer.Forms | QgsMapLayer.MapTips | QgsMapLayer.Rendering
                  | QgsMapLayer.AttributeTable)
    message, ok = layer.saveNamedStyle(str(out), categories)
    assert ok, message


def build(styles_dir: Path) -> None:
    """Write ``suspects.qml`` and ``anomalies.qml`` (the outlines keep their symbology)."""
    from qgis.core import QgsApplication, QgsMapLayer

    from clearfast_gis.export.testing import make_demo_products

    app = QgsApplication([], False)
    app.initQgis()
    with tempfile.TemporaryDirectory() as tmp:
        gpkg = make_demo_products(Path(tmp) / "p").root / "anomalies.gpkg"
        suspects = style_layer(gpkg, "suspects", "Point")
        apply_fields(suspects)
        suspects.setRenderer(renderer())
        suspects.setLabeling(labeling())
        suspects.setLabelsEnabled(True)
        save(suspects, styles_dir / "suspects.qml")
        # the pipeline's outlines carry the suspects' columns (make_demo_products' do not)
        outlines = style_layer(gpkg, "suspects", "MultiPolygon")
        outlines.loadNamedStyle(str(styles_dir / "anomalies.qml"), QgsMapLayer.Symbology)
        apply_fields(outlines)
        save(outlines, styles_dir / "anomalies.qml")
    app.exitQgis()


if __name__ == "__main__":
    from clearfast_gis.export.styles import STYLES_DIR

    build(STYLES_DIR)
    print(STYLES_DIR / "suspects.qml", STYLES_DIR / "anomalies.qml")
