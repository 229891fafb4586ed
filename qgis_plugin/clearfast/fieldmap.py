"""The field map: a one-page QGIS print layout of a products folder, exported to PDF.

A4 landscape: the map of the survey footprint over the best-contrast mosaic with suspects and
markers, a UTM grid (metres, bottom/left) and WGS84 ticks (degrees, top/right), scale bar, north
arrow, legend; beside it a title block (survey id, dates, CRS, method, the indirect-evidence
disclaimer) and the table of mine indications with their coordinates, in priority order. Needs
only QGIS (not the toolkit).
"""

from __future__ import annotations

import json
import math
import os

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsExpression,
    QgsExpressionContext,
    QgsExpressionContextUtils,
    QgsLayoutExporter,
    QgsLayoutFrame,
    QgsLayoutItemLabel,
    QgsLayoutItemLegend,
    QgsLayoutItemManualTable,
    QgsLayoutItemMap,
    QgsLayoutItemMapGrid,
    QgsLayoutItemPage,
    QgsLayoutItemPicture,
    QgsLayoutItemScaleBar,
    QgsLayoutPoint,
    QgsLayoutSize,
    QgsLayoutTableColumn,
    QgsLegendStyle,
    QgsPrintLayout,
    QgsProject,
    QgsRectangle,
    QgsRenderContext,
    QgsScaleBarSettings,
    QgsTableCell,
    QgsTextFormat,
    QgsUnitTypes,
)
from qgis.PyQt.QtGui import QColor, QFont

from .loader import load_products, shared_range, thermal_renderer

MM = QgsUnitTypes.LayoutMillimeters
PAGE_W, PAGE_H = 297.0, 210.0
MAP_X, MAP_Y, MAP_W, MAP_H = 14.0, 22.0, 170.0, 170.0
SIDE_X, SIDE_W = 196.0, 92.0
LEGEND_H = 46.0
"""Height kept for the legend (suspect classes, markers, footprint), mm."""
MAX_TABLE_ROWS = 14
"""Rows of the mine-indication table on the page (the rest are counted below it)."""

CUE_FILTER = "\"class_cue\" IN ('at_mine', 'ap_mine')"
"""Mine indications of a layer without the stored style (its labelling rule says otherwise)."""


def mine_filter(layer) -> str:
    """The filter of mine indications: that of the stored style's labelling rule (mine
    likelihood or class cue, as the mine-action export selects them)."""
    labeling = layer.labeling()
    if labeling is not None and labeling.type() == "rule-based":
        for rule in labeling.rootRule().children():
            if rule.filterExpression():
                return rule.filterExpression()
    return CUE_FILTER

DISCLAIMER = ("Indirect evidence. Each mark is a thermal anomaly from a stand-off thermal-IR "
              "survey: an indication for technical survey, not a confirmed mine. Ground without "
              "marks is not cleared.")
NORTH_ARROW = "/usr/share/qgis/svg/arrows/NorthArrow_02.svg"


def nice_step(span: float, target: int = 5) -> float:
    """A 1-2-5 step that divides ``span`` into about ``target`` parts."""
    raw = span / max(target, 1)
    if not raw > 0:
        return 1.0
    base = 10.0 ** math.floor(math.log10(raw))
    return next(m * base for m in (1.0, 2.0, 5.0, 10.0) if m * base >= raw)


def nice_floor(value: float) -> float:
    """The largest 1-2-5 number not above ``value`` (> 0)."""
    base = 10.0 ** math.floor(math.log10(value))
    return next(m * base for m in (5.0, 2.0, 1.0) if m * base <= value * (1 + 1e-9))


def mine_rows(layer) -> list:
    """Mine indications of a suspects layer in the style's priority order (its attribute
    table sort expression)."""
    from qgis.core import QgsFeatureRequest

    ctx = QgsExpressionContext(QgsExpressionContextUtils.globalProjectLayerScopes(layer))
    order = QgsExpression(layer.attributeTableConfig().sortExpression() or "\"anomaly_id\"")
    keyed = []
    for f in layer.getFeatures(QgsFeatureRequest().setFilterExpression(mine_filter(layer))):
        ctx.setFeature(f)
        key = order.evaluate(ctx)
        keyed.append((key if key is not None else math.inf, str(f["anomaly_id"]), f))
    keyed.sort(key=lambda k: (k[0], k[1]))
    return [f for _, _, f in keyed]


def best_contrast_mosaic(loaded):
    """The mosaic of the scan where the mine indications' median |contrast| is largest
    (from the suspects' ``contrast_series``); the first mosaic when that is unknown."""
    suspects = loaded.vectors.get("suspects")
    if not loaded.mosaics:
        return None
    if suspects is None or suspects.fields().indexOf("contrast_series") < 0:
        return loaded.mosaics[0]
    per_time: dict[str, list[float]] = {}
    for f in mine_rows(suspects):
        try:
            series = json.loads(f["contrast_series"] or "{}")
        except (TypeError, ValueError):
            continue
        for t, c in zip(series.get("time_utc", []), series.get("contrast_k", [])):  # noqa: B905
            if c is not None:
                per_time.setdefault(t, []).append(abs(float(c)))
    if not per_time:
        return loaded.mosaics[0]
    best = max(sorted(per_time), key=lambda t: sorted(per_time[t])[len(per_time[t]) // 2])
    from .loader import parse_utc

    when = parse_utc(best)
    gaps = [abs(t.secsTo(when)) for t in loaded.scan_times]
    return loaded.mosaics[gaps.index(min(gaps))] if gaps else loaded.mosaics[0]


def _label(layout, html: str, x: float, y: float, w: float, h: float, size: float = 9.0,
           bold: bool = False):
    item = QgsLayoutItemLabel(layout)
    item.setMode(QgsLayoutItemLabel.ModeHtml)
    item.setText(html)
    font = QFont("DejaVu Sans")
    font.setPointSizeF(size)
    font.setBold(bold)
    item.setFont(font)
    item.attemptMove(QgsLayoutPoint(x, y, MM))
    item.attemptResize(QgsLayoutSize(w, h, MM))
    layout.addLayoutItem(item)
    return item


def _text_format(size: float) -> QgsTextFormat:
    fmt = QgsTextFormat()
    fmt.setFont(QFont("DejaVu Sans"))
    fmt.setSize(size)
    return fmt


def _grids(map_item, crs, extent: QgsRectangle) -> None:
    """UTM grid lines with metre labels (bottom, left); WGS84 ticks in DMS (top, right)."""
    G = QgsLayoutItemMapGrid
    utm = G("UTM grid (m)", map_item)
    utm.setCrs(crs)
    step = nice_step(max(extent.width(), extent.height()))
    utm.setIntervalX(step)
    utm.setIntervalY(step)
    utm.setStyle(G.Solid)
    utm.setGridLineColor(QColor(255, 255, 255, 110))
    utm.setGridLineWidth(0.15)
    utm.setAnnotationEnabled(True)
    utm.setAnnotationFormat(G.Decimal)
    utm.setAnnotationPrecision(0)
    utm.setAnnotationTextFormat(_text_format(6.5))
    for side in (G.Left, G.Bottom):
        utm.setAnnotationDisplay(G.ShowAll, side)
        utm.setAnnotationPosition(G.OutsideMapFrame, side)
    utm.setAnnotationDirection(G.Vertical, G.Left)
    for side in (G.Right, G.Top):
        utm.setAnnotationDisplay(G.HideAll, side)
    map_item.grids().addGrid(utm)

    wgs = G("WGS84 ticks", map_item)
    wgs84 = QgsCoordinateReferenceSystem("EPSG:4326")
    wgs.setCrs(wgs84)
    ll = QgsCoordinateTransform(crs, wgs84, QgsProject.instance()).transformBoundingBox(extent)
    step_s = nice_step(max(ll.width(), ll.height()) * 3600.0, 4)
    wgs.setIntervalX(step_s / 3600.0)
    wgs.setIntervalY(step_s / 3600.0)
    wgs.setStyle(G.FrameAnnotationsOnly)
    wgs.setFrameStyle(G.ExteriorTicks)
    wgs.setFrameWidth(2.0)
    wgs.setAnnotationEnabled(True)
    wgs.setAnnotationFormat(G.DegreeMinuteSecond)
    wgs.setAnnotationPrecision(max(0, -math.floor(math.log10(step_s))) if step_s < 1 else 0)
    wgs.setAnnotationTextFormat(_text_format(6.5))
    for side in (G.Left, G.Bottom):
        wgs.setAnnotationDisplay(G.HideAll, side)
        wgs.setFrameSideFlag(getattr(G, f"Frame{'Left' if side == G.Left else 'Bottom'}"),
                             False)
    for side in (G.Right, G.Top):
        wgs.setAnnotationDisplay(G.ShowAll, side)
        wgs.setAnnotationPosition(G.OutsideMapFrame, side)
    wgs.setAnnotationDirection(G.Vertical, G.Right)
    map_item.grids().addGrid(wgs)


def _table(layout, rows, x: float, y: float, w: float, h: float):
    table = QgsLayoutItemManualTable.create(layout)
    layout.addMultiFrame(table)
    heads = ("Id", "Cue", "Easting m", "Northing m", "Lat °", "Lon °", "Depth")
    table.setHeaders([QgsLayoutTableColumn(name) for name in heads])
    table.setIncludeTableHeader(True)
    table.setHeaderTextFormat(_text_format(6.0))
    table.setContentTextFormat(_text_format(6.0))
    table.setCellMargin(0.6)
    cue = {"at_mine": "AT", "ap_mine": "AP"}
    contents = []
    for f in rows:
        depth = f["depth"] if f.fields().indexOf("depth") >= 0 else None
        contents.append([QgsTableCell(str(v)) for v in (
            f["short_id"] if f.fields().indexOf("short_id") >= 0 else f["anomaly_id"],
            cue.get(f["class_cue"], f["class_cue"]), f"{f['x']:.2f}", f"{f['y']:.2f}",
            f"{f['lat']:.7f}", f"{f['lon']:.7f}", depth or "")])
    table.setTableContents(contents)
    frame = QgsLayoutFrame(layout, table)
    frame.attemptMove(QgsLayoutPoint(x, y, MM))
    frame.attemptResize(QgsLayoutSize(w, h, MM))
    table.addFrame(frame)
    return table


def _utc(text: str) -> str:
    return text.replace("T", " ").replace(".000Z", "Z").replace("Z", " UTC") if text else "?"


def build_field_map(folder: str, project: QgsProject):
    """Load a products folder into ``project`` and lay out its field map.

    Returns ``(layout, loaded)``; the layout belongs to the project's layout manager (keep the
    project alive while using it)."""
    loaded = load_products(folder, project)
    with open(os.path.join(loaded.folder, "products.json"), encoding="utf-8") as fh:
        manifest = json.load(fh)
    suspects = loaded.vectors.get("suspects")
    crs = (loaded.vectors.get("footprint") or loaded.mosaics[0]).crs()
    mosaic = best_contrast_mosaic(loaded)
    lo_c = hi_c = math.nan
    if mosaic is not None:
        lo_c, hi_c = shared_range([mosaic])
        mosaic.setRenderer(thermal_renderer(mosaic, lo_c, hi_c))

    layout = QgsPrintLayout(project)
    layout.initializeDefaults()
    layout.setName(f"CLEARFAST field map {loaded.survey_id}")
    layout.pageCollection().page(0).setPageSize("A4", QgsLayoutItemPage.Landscape)

    map_item = QgsLayoutItemMap(layout)
    map_item.attemptMove(QgsLayoutPoint(MAP_X, MAP_Y, MM))
    map_item.attemptResize(QgsLayoutSize(MAP_W, MAP_H, MM))
    map_item.setCrs(crs)
    shown = [loaded.vectors[n] for n in ("suspects", "markers", "footprint")
             if n in loaded.vectors]
    map_item.setLayers(shown + ([mosaic] if mosaic is not None else []))
    map_item.setKeepLayerSet(True)
    extent = QgsRectangle(loaded.extent)
    side = max(extent.width(), extent.height()) * 1.08
    centre = extent.center()
    extent = QgsRectangle(centre.x() - side / 2, centre.y() - side / 2,
                          centre.x() + side / 2, centre.y() + side / 2)
    map_item.setExtent(extent)
    map_item.setFrameEnabled(True)
    layout.addLayoutItem(map_item)
    _grids(map_item, crs, extent)

    bar = QgsLayoutItemScaleBar(layout)
    bar.setStyle("Single Box")
    bar.setLinkedMap(map_item)
    bar.setUnits(QgsUnitTypes.DistanceMeters)
    bar.setUnitLabel("m")
    bar.setSegmentSizeMode(QgsScaleBarSettings.SegmentSizeFixed)
    bar.setUnitsPerSegment(nice_floor(side / 5.0))
    bar.setNumberOfSegments(2)
    bar.setNumberOfSegmentsLeft(0)
    bar.setTextFormat(_text_format(7.0))
    bar.attemptMove(QgsLayoutPoint(MAP_X + 3, MAP_Y + MAP_H - 16, MM))
    layout.addLayoutItem(bar)
    bar.setBackgroundEnabled(True)

    arrow = QgsLayoutItemPicture(layout)
    arrow.setPicturePath(NORTH_ARROW)
    arrow.setLinkedMap(map_item)
    arrow.setNorthMode(QgsLayoutItemPicture.TrueNorth)
    arrow.attemptMove(QgsLayoutPoint(MAP_X + MAP_W - 14, MAP_Y + 3, MM))
    arrow.attemptResize(QgsLayoutSize(10, 14, MM))
    arrow.setBackgroundEnabled(True)
    layout.addLayoutItem(arrow)

    start = manifest.get("time", {}).get("start_utc", "")
    end = manifest.get("time", {}).get("end_utc", "")
    mosaic_name = mosaic.name() if mosaic is not None else "none"
    _label(layout, f"CLEARFAST field map &mdash; survey <b>{loaded.survey_id}</b>",
           MAP_X, 6, MAP_W + 100, 10, 15)
    rows = mine_rows(suspects) if suspects is not None else []
    n_suspects = suspects.featureCount() if suspects is not None else 0
    block = (f"<b>Survey</b> {loaded.survey_id}<br>"
             f"<b>Dates</b> {_utc(start)} &ndash; {_utc(end)}<br>"
             f"<b>CRS</b> {crs.authid()} {crs.description()}; grid in metres, "
             "ticks in WGS84 degrees<br>"
             "<b>Method</b> stand-off thermal IR (CLEARFAST), 24 h of scans; morphological "
             "detection, thermal inversion for depth<br>"
             f"<b>Background</b> {mosaic_name}, the scan with the best contrast of the mine "
             f"indications: apparent temperature {lo_c:.1f} (black) to {hi_c:.1f} &deg;C "
             "(white)<br>"
             f"<b>Suspects</b> {n_suspects}, of which <b>{len(rows)} mine indications</b> "
             "(red, labelled); other suspects muted; clutter not shown<br>"
             f"<i>{DISCLAIMER}</i>")
    _label(layout, block, SIDE_X, MAP_Y, SIDE_W, 52, 7.0)

    legend = QgsLayoutItemLegend(layout)
    legend.setLinkedMap(map_item)
    legend.setTitle("Legend")
    legend.setLegendFilterByMapEnabled(True)
    legend.setAutoUpdateModel(False)
    root = legend.model().rootGroup()
    root.removeAllChildren()
    for layer in shown:
        root.addLayer(layer)
    legend.attemptMove(QgsLayoutPoint(SIDE_X, MAP_Y + 56, MM))
    for part, size in ((QgsLegendStyle.Title, 8), (QgsLegendStyle.Group, 7),
                       (QgsLegendStyle.Subgroup, 7), (QgsLegendStyle.SymbolLabel, 7)):
        legend.setStyleFont(part, QFont("DejaVu Sans", size))
    layout.addLayoutItem(legend)
    legend.setResizeToContents(True)

    table_y = MAP_Y + 56 + LEGEND_H + 7
    _label(layout, f"<b>Mine indications</b> ({len(rows)}, priority order)", SIDE_X,
           table_y - 6, SIDE_W, 5, 8.0)
    _table(layout, rows[:MAX_TABLE_ROWS], SIDE_X, table_y, SIDE_W, PAGE_H - table_y - 12)
    if len(rows) > MAX_TABLE_ROWS:
        _label(layout, f"&hellip; and {len(rows) - MAX_TABLE_ROWS} more: see the suspects "
               "layer", SIDE_X, PAGE_H - 11, SIDE_W, 5, 6.5)
    version = manifest.get("software", {}).get("version", "")
    _label(layout, f"clearfast-gis {version} &middot; products {loaded.folder}", MAP_X,
           PAGE_H - 9, MAP_W, 5, 6.0)
    project.layoutManager().addLayout(layout)
    return layout, loaded


def export_field_map(folder: str, pdf_path: str, project: QgsProject | None = None) -> str:
    """Write the field map of a products folder as a one-page PDF; returns its path.

    The products are loaded into ``project`` (default: a new project of their own, so the
    user's project is left as it is)."""
    project = project if project is not None else QgsProject()
    layout, _ = build_field_map(folder, project)
    settings = QgsLayoutExporter.PdfExportSettings()
    settings.dpi = 200
    settings.rasterizeWholeImage = False
    settings.textRenderFormat = QgsRenderContext.TextFormatAlwaysText  # searchable text
    os.makedirs(os.path.dirname(os.path.abspath(pdf_path)) or ".", exist_ok=True)
    result = QgsLayoutExporter(layout).exportToPdf(pdf_path, settings)
    if result != QgsLayoutExporter.Success:
        raise OSError(f"{pdf_path}: cannot write the field map (QGIS layout error {result})")
    return pdf_path
