"""Load a CLEARFAST products folder into a QGIS project (needs only QGIS, not the toolkit).

Mosaics go into one group with a shared thermal colour ramp and a fixed temporal range per scan
(the QGIS Temporal Controller then plays the diurnal cycle); the GeoPackage layers load with the
default styles stored in the GeoPackage; the map zooms to the survey footprint.
"""

from __future__ import annotations

import glob
import json
import os
from dataclasses import dataclass, field
from datetime import datetime, timezone

from qgis.core import (
    QgsColorRampShader,
    QgsCoordinateTransform,
    QgsDateTimeRange,
    QgsEditorWidgetSetup,
    QgsGradientColorRamp,
    QgsGradientStop,
    QgsInterval,
    QgsProject,
    QgsRasterLayer,
    QgsRasterLayerTemporalProperties,
    QgsRasterShader,
    QgsRectangle,
    QgsSingleBandPseudoColorRenderer,
    QgsVectorLayer,
)
from qgis.PyQt.QtCore import QDateTime, Qt
from qgis.PyQt.QtGui import QColor

SCAN_TIME_TAG = "CLEARFAST_SCAN_TIME_UTC"

VECTOR_LAYERS = (
    ("suspects", "Suspects"),
    ("candidates", "Candidates (set aside)"),
    ("anomalies", "Anomaly outlines"),
    ("markers", "Markers"),
    ("footprint", "Footprint"),
)
"""GeoPackage layer name and title, top to bottom in the layer tree."""

OPTIONAL_LAYERS = frozenset({"candidates"})
"""Layers that older products do not have."""

HIDDEN_LAYERS = frozenset({"candidates"})
"""Layers added switched off (one click away in the layer tree)."""

THERMAL_RAMP = (
    (0.0, (0, 0, 0)),
    (0.2, (36, 0, 128)),
    (0.45, (190, 0, 140)),
    (0.7, (255, 110, 0)),
    (0.88, (255, 220, 0)),
    (1.0, (255, 255, 255)),
)
"""Thermal colour ramp (position 0-1, RGB); the same stops as the toolkit's mosaic.qml."""

SUSPECT_FIGURE_FIELD = "figure"


class ProductsError(Exception):
    """The folder is not a readable CLEARFAST products folder."""


@dataclass
class LoadedProducts:
    """What :func:`load_products` added to the project."""

    folder: str
    survey_id: str
    group: object
    mosaics: list = field(default_factory=list)
    vectors: dict = field(default_factory=dict)
    scan_times: list = field(default_factory=list)
    min_c: float = float("nan")
    max_c: float = float("nan")
    extent: QgsRectangle | None = None


def _read_manifest(folder: str) -> dict:
    path = os.path.join(folder, "products.json")
    try:
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
    except FileNotFoundError:
        raise ProductsError(f"{folder}: not a CLEARFAST products folder (no products.json)") \
            from None
    except (OSError, ValueError) as exc:
        raise ProductsError(f"{path}: cannot read ({exc})") from None
    if not isinstance(doc, dict) or doc.get("format") != "clearfast-products":
        raise ProductsError(f"{path}: format: expected \"clearfast-products\"")
    return doc


def parse_utc(text: str) -> QDateTime:
    """ISO 8601 UTC text (``...Z``) to a UTC QDateTime."""
    s = text.strip().replace("Z", "+00:00")
    dt = datetime.fromisoformat(s)
    if dt.tzinfo is None:
        dt = dt.replace(tzinfo=timezone.utc)  # noqa: UP017 (QGIS 3.22 may run Python 3.9)
    ms = round(dt.timestamp() * 1000)
    return QDateTime.fromMSecsSinceEpoch(ms, Qt.UTC)


def scan_time_of(path: str, manifest: dict) -> QDateTime | None:
    """Scan time of a mosaic: its ``CLEARFAST_SCAN_TIME_UTC`` tag, else ``products.json``."""
    try:
        from osgeo import gdal

        ds = gdal.Open(path)
        text = ds.GetMetadataItem(SCAN_TIME_TAG) if ds is not None else None
        ds = None
    except ImportError:
        text = None
    if not text:
        rel = os.path.relpath(path, os.path.dirname(os.path.dirname(path))).replace(os.sep, "/")
        for scan in manifest.get("scans", []):
            if scan.get("file") == rel:
                text = scan.get("time_utc")
    return parse_utc(text) if text else None


def thermal_ramp() -> QgsGradientColorRamp:
    """The thermal colour ramp of the mosaics."""
    stops = [QgsGradientStop(p, QColor(*rgb)) for p, rgb in THERMAL_RAMP[1:-1]]
    return QgsGradientColorRamp(QColor(*THERMAL_RAMP[0][1]), QColor(*THERMAL_RAMP[-1][1]),
                                False, stops)


def thermal_renderer(layer: QgsRasterLayer, min_c: float, max_c: float):
    """A single-band pseudocolour renderer of band 1 stretched over [min_c, max_c] deg C."""
    shader_fn = QgsColorRampShader(min_c, max_c, thermal_ramp(),
                                   QgsColorRampShader.Interpolated,
                                   QgsColorRampShader.Continuous)
    shader_fn.setSourceColorRamp(thermal_ramp())
    items = [QgsColorRampShader.ColorRampItem(min_c + p * (max_c - min_c), QColor(*rgb),
                                              f"{min_c + p * (max_c - min_c):.1f} °C")
             for p, rgb in THERMAL_RAMP]
    shader_fn.setColorRampItemList(items)
    shader = QgsRasterShader(min_c, max_c)
    shader.setRasterShaderFunction(shader_fn)
    renderer = QgsSingleBandPseudoColorRenderer(layer.dataProvider(), 1, shader)
    renderer.setClassificationMin(min_c)
    renderer.setClassificationMax(max_c)
    return renderer


def shared_range(layers: list[QgsRasterLayer], lower: float = 0.02,
                 upper: float = 0.98) -> tuple[float, float]:
    """One min/max (deg C) for all mosaics: the widest 2-98 % cumulative cut of band 1."""
    lows, highs = [], []
    for layer in layers:
        lo, hi = layer.dataProvider().cumulativeCut(1, lower, upper)
        if lo == lo and hi == hi:  # not NaN
            lows.append(lo)
            highs.append(hi)
    if not lows:
        return 0.0, 1.0
    lo, hi = min(lows), max(highs)
    return (lo, hi) if hi > lo else (lo, lo + 1.0)


def _vector_layer(gpkg: str, name: str, title: str) -> QgsVectorLayer:
    layer = QgsVectorLayer(f"{gpkg}|layername={name}", title, "ogr")
    if not layer.isValid():
        raise ProductsError(f"{gpkg}: {name}: layer missing or unreadable")
    return layer


def _gpkg_layer_names(gpkg: str) -> set[str]:
    """Names of the vector layers of a GeoPackage."""
    from qgis.core import QgsProviderRegistry

    meta = QgsProviderRegistry.instance().providerMetadata("ogr")
    return {d.name() for d in meta.querySublayers(gpkg)}


def _suspect_form(layer: QgsVectorLayer, folder: str) -> None:
    """Show the contrast-curve figure (path relative to the products folder) in the form."""
    idx = layer.fields().indexOf(SUSPECT_FIGURE_FIELD)
    if idx < 0:
        return
    config = dict(layer.editorWidgetSetup(idx).config())
    config.update({"DocumentViewer": 1, "DocumentViewerHeight": 240,
                   "DocumentViewerWidth": 360, "RelativeStorage": 2, "DefaultRoot": folder,
                   "UseLink": True, "FullUrl": False})
    layer.setEditorWidgetSetup(idx, QgsEditorWidgetSetup("ExternalResource", config))


def _temporal_ranges(times: list[QDateTime]) -> list[QgsDateTimeRange]:
    """[t_k, t_k+1) for each scan; the last lasts the median scan interval (or one hour)."""
    secs = [t.toMSecsSinceEpoch() / 1000.0 for t in times]
    gaps = sorted(secs[k + 1] - secs[k] for k in range(len(secs) - 1) if secs[k + 1] > secs[k])
    step = gaps[len(gaps) // 2] if gaps else 3600.0
    ranges = []
    for k, t in enumerate(times):
        end = times[k + 1] if k + 1 < len(times) and secs[k + 1] > secs[k] \
            else t.addMSecs(int(step * 1000))
        ranges.append(QgsDateTimeRange(t, end, True, False))
    return ranges


def load_products(folder: str, project: QgsProject | None = None, canvas=None) -> LoadedProducts:
    """Load a products folder into ``project`` (default: the current project).

    Parameters
    ----------
    folder : str
        Products folder (``products.json``, ``mosaics/scan_NNN.tif``, ``anomalies.gpkg``).
    project : QgsProject, optional
        Target project.
    canvas : QgsMapCanvas, optional
        Map canvas to zoom to the footprint and whose temporal controller gets the survey's
        time span.

    Returns
    -------
    LoadedProducts
    """
    project = project or QgsProject.instance()
    folder = os.path.abspath(folder)
    manifest = _read_manifest(folder)
    survey_id = str(manifest.get("survey_id", os.path.basename(folder)))
    gpkg = os.path.join(folder, "anomalies.gpkg")
    vectors = {}
    if os.path.isfile(gpkg):
        present = _gpkg_layer_names(gpkg)
        for name, title in VECTOR_LAYERS:
            if name in OPTIONAL_LAYERS and name not in present:
                continue
            vectors[name] = _vector_layer(gpkg, name, title)
        for name in ("suspects", "candidates"):
            if name in vectors:
                _suspect_form(vectors[name], folder)
    mosaic_paths = sorted(glob.glob(os.path.join(folder, "mosaics", "scan_*.tif")))
    if not vectors and not mosaic_paths:
        raise ProductsError(f"{folder}: no mosaics and no anomalies.gpkg")

    mosaics, times = [], []
    for path in mosaic_paths:
        when = scan_time_of(path, manifest)
        label = os.path.splitext(os.path.basename(path))[0].replace("_", " ").capitalize()
        if when is not None:
            label += " " + when.toString("yyyy-MM-dd HH:mm") + " UTC"
        layer = QgsRasterLayer(path, label, "gdal")
        if not layer.isValid():
            raise ProductsError(f"{path}: not a readable raster")
        mosaics.append(layer)
        times.append(when)
    lo, hi = shared_range(mosaics) if mosaics else (float("nan"), float("nan"))
    for layer in mosaics:
        layer.setRenderer(thermal_renderer(layer, lo, hi))
    timed = [(mosaics[k], times[k]) for k in range(len(mosaics)) if times[k] is not None]
    ranges = _temporal_ranges([t for _, t in timed]) if timed else []
    for (layer, _), rng in zip(timed, ranges):  # noqa: B905 (Python 3.9 in QGIS 3.22)
        props = layer.temporalProperties()
        props.setMode(QgsRasterLayerTemporalProperties.ModeFixedTemporalRange)
        props.setFixedTemporalRange(rng)
        props.setIsActive(True)

    root = project.layerTreeRoot()
    group = root.insertGroup(0, f"CLEARFAST {survey_id}")
    for name, _ in VECTOR_LAYERS:
        if name in vectors:
            project.addMapLayer(vectors[name], False)
            node = group.addLayer(vectors[name])
            node.setItemVisibilityChecked(name not in HIDDEN_LAYERS)
    if mosaics:
        mosaic_group = group.addGroup("Mosaics")
        for layer in mosaics:
            project.addMapLayer(layer, False)
            mosaic_group.addLayer(layer)
        # all stay visible: with the Temporal Controller on, each shows in its own time range;
        # with it off, scan 000 (top of the group) covers the others

    crs = (vectors.get("footprint") or mosaics[0]).crs()
    if not project.crs().isValid():
        project.setCrs(crs)
    if ranges:
        whole = QgsDateTimeRange(ranges[0].begin(), ranges[-1].end(), True, False)
        project.timeSettings().setTemporalRange(whole)
        step_s = ranges[0].begin().secsTo(ranges[0].end())
        if hasattr(project.timeSettings(), "setTimeStep"):
            from qgis.core import QgsUnitTypes

            project.timeSettings().setTimeStepUnit(QgsUnitTypes.TemporalSeconds)
            project.timeSettings().setTimeStep(float(step_s))
        if canvas is not None and hasattr(canvas, "temporalController"):
            controller = canvas.temporalController()
            controller.setTemporalExtents(whole)
            controller.setFrameDuration(QgsInterval(step_s))

    extent_layer = vectors.get("footprint") or mosaics[0]
    extent = QgsRectangle(extent_layer.extent())
    extent.scale(1.05)
    if canvas is not None:
        destination = canvas.mapSettings().destinationCrs()
        transform = QgsCoordinateTransform(extent_layer.crs(), destination, project)
        canvas.setExtent(transform.transformBoundingBox(extent))
        canvas.refresh()
    return LoadedProducts(folder, survey_id, group, mosaics, vectors,
                          [t for _, t in timed], lo, hi, extent)
