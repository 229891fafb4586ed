"""Opening a products folder in a real QGIS (headless): layers, styles, time, form, rendering."""

from __future__ import annotations

import configparser
import sqlite3
from pathlib import Path

import numpy as np
import pytest

pytestmark = pytest.mark.qgis

PLUGIN = Path(__file__).resolve().parents[2] / "qgis_plugin" / "clearfast"


@pytest.fixture()
def loaded(project, products):
    from clearfast.loader import load_products

    return load_products(str(products.root), project)


def gpkg_count(gpkg: Path, table: str) -> int:
    with sqlite3.connect(gpkg) as con:
        return con.execute(f'SELECT COUNT(*) FROM "{table}"').fetchone()[0]


def test_vector_layers_valid_crs_and_counts(loaded, products):
    gpkg = products.root / "anomalies.gpkg"
    assert set(loaded.vectors) == {"suspects", "anomalies", "markers", "footprint"}
    for name, layer in loaded.vectors.items():
        assert layer.isValid(), name
        assert layer.crs().authid() == "EPSG:32636"
        assert layer.featureCount() == gpkg_count(gpkg, name)
    assert loaded.vectors["suspects"].featureCount() == products.n_suspects == 8
    assert loaded.vectors["markers"].featureCount() == 4


def test_styles_from_geopackage_applied(loaded):
    from qgis.core import QgsWkbTypes

    suspects = loaded.vectors["suspects"]
    renderer = suspects.renderer()
    assert renderer.type() == "RuleRenderer"
    rules = {r.label(): r for r in renderer.rootRule().children()}
    colours = {label: r.symbol().color().name() for label, r in rules.items()}
    assert colours == {"AT mine indication": "#e31a1c", "AP mine indication": "#e31a1c",
                       "Mine indication, other cue": "#e31a1c", "Other suspect": "#ff7f00",
                       "Clutter": "#969696"}
    assert {label: r.active() for label, r in rules.items()} == {
        "AT mine indication": True, "AP mine indication": True,
        "Mine indication, other cue": True, "Other suspect": True, "Clutter": False}
    assert suspects.labelsEnabled()
    assert suspects.labeling().type() == "rule-based"
    assert suspects.geometryType() == QgsWkbTypes.PointGeometry
    outlines = loaded.vectors["anomalies"].renderer()
    assert outlines.type() == "categorizedSymbol" and outlines.classAttribute() == "polarity"
    assert loaded.vectors["markers"].labeling().settings().fieldName == "marker_id"


def form_field_names(layer) -> set[str]:
    """Names of the fields placed anywhere in a layer's drag-and-drop form."""
    names = set()

    def walk(element):
        for child in element.children():
            if hasattr(child, "children"):
                walk(child)
            else:
                names.add(child.name())

    walk(layer.editFormConfig().invisibleRootContainer())
    return names


def test_suspect_form_shows_inversion_and_figure(loaded, products):
    suspects = loaded.vectors["suspects"]
    fields_in_form = form_field_names(suspects)
    assert {"depth_m", "depth_sigma_m", "diffusivity_m2s", "diffusivity_sigma_m2s", "status",
            "class_cue", "figure"} <= fields_in_form
    setup = suspects.editorWidgetSetup(suspects.fields().indexOf("figure"))
    assert setup.type() == "ExternalResource"
    assert setup.config()["DefaultRoot"] == str(products.root)
    assert setup.config()["DocumentViewer"] == 1  # image viewer
    feature = next(f for f in suspects.getFeatures() if f["anomaly_id"] == "A001")
    assert (products.root / feature["figure"]).is_file()
    assert suspects.fields().field("depth_m").alias() == "Burial depth (m)"
    assert feature["depth_m"] == pytest.approx(0.010)


def test_mosaics_group_shared_range_and_temporal(loaded, products):
    from qgis.core import QgsRasterLayerTemporalProperties

    assert len(loaded.mosaics) == 4
    group = loaded.group.findGroup("Mosaics")
    assert group is not None and len(group.findLayers()) == 4
    for layer in loaded.mosaics:
        assert layer.isValid() and layer.crs().authid() == "EPSG:32636"
        renderer = layer.renderer()
        assert renderer.type() == "singlebandpseudocolor"
        assert renderer.classificationMin() == pytest.approx(loaded.min_c)
        assert renderer.classificationMax() == pytest.approx(loaded.max_c)
    # the diurnal range of the synthetic site is about 7-21 C
    assert 5.0 < loaded.min_c < 10.0 and 18.0 < loaded.max_c < 24.0
    begins = []
    for layer, t_s in zip(loaded.mosaics, products.scan_times_s, strict=True):
        props = layer.temporalProperties()
        assert props.isActive()
        assert props.mode() == QgsRasterLayerTemporalProperties.ModeFixedTemporalRange
        rng = props.fixedTemporalRange()
        assert rng.begin().toMSecsSinceEpoch() == int(t_s * 1000)
        begins.append(rng)
    for a, b in zip(begins, begins[1:], strict=False):
        assert a.end() == b.begin()  # consecutive scans tile the day


def test_project_time_and_extent(loaded, project, products):
    rng = project.timeSettings().temporalRange()
    assert rng.begin().toMSecsSinceEpoch() == int(products.scan_times_s[0] * 1000)
    assert rng.begin().secsTo(rng.end()) == 86400
    footprint = loaded.vectors["footprint"].extent()
    assert loaded.extent.contains(footprint)
    assert loaded.extent.width() < 1.2 * footprint.width()


def test_temporal_filter_selects_one_scan(loaded):
    from qgis.core import QgsDateTimeRange

    first, second = loaded.mosaics[0], loaded.mosaics[1]
    t = loaded.scan_times[1].addSecs(60)
    frame = QgsDateTimeRange(t, t.addSecs(60))
    assert not first.temporalProperties().isVisibleInTemporalRange(frame)
    assert second.temporalProperties().isVisibleInTemporalRange(frame)


def _render(project, layers, extent, size=(300, 450)):
    from qgis.core import QgsMapRendererParallelJob, QgsMapSettings
    from qgis.PyQt.QtCore import QSize
    from qgis.PyQt.QtGui import QColor

    settings = QgsMapSettings()
    settings.setLayers(layers)
    settings.setDestinationCrs(layers[0].crs())
    settings.setExtent(extent)
    settings.setOutputSize(QSize(*size))
    settings.setBackgroundColor(QColor(255, 255, 255))
    job = QgsMapRendererParallelJob(settings)
    job.start()
    job.waitForFinished()
    return job.renderedImage()


def _rgb(image) -> np.ndarray:
    from qgis.PyQt.QtGui import QImage

    image = image.convertToFormat(QImage.Format_RGB888)
    ptr = image.constBits()
    ptr.setsize(image.height() * image.bytesPerLine())
    arr = np.frombuffer(ptr, np.uint8).reshape(image.height(), image.bytesPerLine())
    return arr[:, : image.width() * 3].reshape(image.height(), image.width(), 3).copy()


def test_render_project_to_png(loaded, project, tmp_path):
    layers = [loaded.vectors[n] for n in ("suspects", "anomalies", "markers", "footprint")]
    layers.append(loaded.mosaics[2])  # midday scan
    image = _render(project, layers, loaded.extent)
    png = tmp_path / "products.png"
    assert image.save(str(png), "PNG")
    assert png.stat().st_size > 1000
    rgb = _rgb(image).astype(int)
    background = np.all(rgb == 255, axis=2)
    assert background.mean() < 0.5  # the mosaic covers most of the footprint
    red = (rgb[..., 0] > 200) & (rgb[..., 1] < 60) & (rgb[..., 2] < 60)
    assert red.sum() > 20  # mine indications drawn in red
    colours = {tuple(c) for c in rgb[~background][::97]}
    assert len(colours) > 20  # a thermal ramp, not a flat fill


def test_missing_folder_is_reported(project, tmp_path, qgis_app):
    from clearfast.loader import ProductsError, load_products

    with pytest.raises(ProductsError, match="products.json"):
        load_products(str(tmp_path), project)


def test_ramp_matches_toolkit_style():
    from clearfast.loader import THERMAL_RAMP

    from clearfast_gis.export.styles import mosaic_ramp_stops

    toolkit = mosaic_ramp_stops()
    assert len(toolkit) == len(THERMAL_RAMP)
    for (p1, c1), (p2, c2) in zip(toolkit, THERMAL_RAMP, strict=True):
        assert p1 == pytest.approx(p2) and tuple(c1) == tuple(c2)


def test_metadata_complete():
    meta = configparser.ConfigParser()
    meta.read(PLUGIN / "metadata.txt", encoding="utf-8")
    general = meta["general"]
    for key in ("name", "qgisMinimumVersion", "description", "about", "version", "author",
                "email", "repository", "icon"):
        assert general.get(key), key
    assert general["qgisMinimumVersion"] == "3.22"
    assert general["hasProcessingProvider"] == "yes"
    assert "clearfast toolkit" in general["about"] and "pip install" in general["about"]
    assert (PLUGIN / general["icon"]).is_file()


def test_loader_does_not_import_the_toolkit():
    for name in ("loader.py", "__init__.py", "plugin.py"):
        assert "clearfast_gis" not in (PLUGIN / name).read_text(encoding="utf-8")


class FakeIface:
    """Records what the plugin adds to the QGIS interface."""

    def __init__(self):
        self.menu, self.toolbar = [], []

    def mainWindow(self):
        return None

    def addPluginToMenu(self, menu, action):
        self.menu.append((menu, action))

    def removePluginMenu(self, menu, action):
        self.menu.remove((menu, action))

    def addToolBarIcon(self, action):
        self.toolbar.append(action)

    def removeToolBarIcon(self, action):  # QGIS ignores an action that is not there
        if action in self.toolbar:
            self.toolbar.remove(action)


def test_plugin_gui_unload_removes_everything(session_plugin):
    import clearfast
    from qgis.core import QgsApplication

    registry = QgsApplication.processingRegistry()
    before = len(registry.providers())
    session_plugin.unload()  # one provider per id: make room for the GUI plugin
    assert registry.providerById("clearfast") is None
    iface = FakeIface()
    plugin = clearfast.classFactory(iface)
    try:
        plugin.initGui()
        assert registry.providerById("clearfast") is plugin.provider
        assert len(iface.menu) == 2 and len(iface.toolbar) == 1
        assert {m for m, _ in iface.menu} == {"&CLEARFAST"}
        assert iface.menu[0][1].text().startswith("Open survey products")
        assert iface.menu[1][1].text().startswith("Export field map")
        plugin.unload()
        assert iface.menu == [] and iface.toolbar == []
        assert registry.providerById("clearfast") is None
        assert plugin.provider is None and plugin.actions == []
    finally:
        session_plugin.initProcessing()
    assert len(registry.providers()) == before
    assert {a.name() for a in registry.providerById("clearfast").algorithms()} == {
        "processsurvey", "rerundetection", "exportmineaction", "validatesurvey", "fieldmap"}
