"""Screenshots of the plugin for docs/plugin.md, made in a real (headless) QGIS.

Run with QGIS's Python, from the repository root::

    QT_QPA_PLATFORM=offscreen python scripts/plugin_screenshots.py [PRODUCTS] [-o docs/img]

PRODUCTS defaults to a small products folder made by the toolkit's writers
(:func:`clearfast_gis.export.testing.make_demo_products`). Writes ``plugin_map.png`` (the loaded
products over the midday mosaic, with the stored styles), ``plugin_form.png`` (the form of the
first mine indication) and ``plugin_fieldmap.png`` (the field-map page).
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
sys.path.insert(0, str(REPO / "qgis_plugin"))


def save_small(image, path: Path) -> None:
    """Save a QImage as an 8-bit palette PNG (small files for the docs)."""
    from qgis.PyQt.QtCore import Qt
    from qgis.PyQt.QtGui import QImage

    flags = Qt.ThresholdDither | Qt.AvoidDither
    image.convertToFormat(QImage.Format_Indexed8, flags).save(str(path), "PNG")


def render_map(loaded, path: Path, width_px: int = 480) -> None:
    from clearfast.fieldmap import best_contrast_mosaic
    from clearfast.loader import shared_range, thermal_renderer
    from qgis.core import QgsMapRendererCustomPainterJob, QgsMapSettings
    from qgis.PyQt.QtCore import QSize
    from qgis.PyQt.QtGui import QColor, QImage, QPainter

    mosaic = best_contrast_mosaic(loaded)
    mosaic.setRenderer(thermal_renderer(mosaic, *shared_range([mosaic])))
    layers = [loaded.vectors[n] for n in ("suspects", "markers", "footprint")] + [mosaic]
    extent = loaded.extent
    height_px = round(width_px * extent.height() / extent.width())
    settings = QgsMapSettings()
    settings.setLayers(layers)
    settings.setDestinationCrs(layers[0].crs())
    settings.setExtent(extent)
    settings.setOutputSize(QSize(width_px, height_px))
    settings.setBackgroundColor(QColor(255, 255, 255))
    image = QImage(settings.outputSize(), QImage.Format_RGB32)
    image.fill(QColor(255, 255, 255))
    painter = QPainter(image)
    job = QgsMapRendererCustomPainterJob(settings, painter)
    job.start()
    job.waitForFinished()
    painter.end()
    save_small(image, path)


def grab_form(layer, path: Path) -> None:
    from clearfast.fieldmap import mine_rows
    from qgis.gui import QgsAttributeEditorContext, QgsAttributeForm, QgsGui

    QgsGui.editorWidgetRegistry().initEditors()
    feature = mine_rows(layer)[0]
    form = QgsAttributeForm(layer, feature, QgsAttributeEditorContext())
    form.resize(520, 560)
    form.show()
    save_small(form.grab().toImage(), path)
    form.close()


def field_map_png(folder: str, path: Path) -> None:
    from clearfast.fieldmap import build_field_map
    from qgis.core import QgsLayoutExporter, QgsProject

    project = QgsProject()
    layout, _ = build_field_map(folder, project)
    settings = QgsLayoutExporter.ImageExportSettings()
    settings.dpi = 72
    save_small(QgsLayoutExporter(layout).renderPageToImage(0, settings.imageSize, settings.dpi),
               path)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("products", nargs="?", help="products folder [demo products]")
    parser.add_argument("-o", "--out", default=str(REPO / "docs" / "img"))
    args = parser.parse_args(argv)

    from qgis.core import QgsApplication, QgsProject
    from qgis.PyQt.QtWidgets import QApplication

    QgsApplication.setPrefixPath("/usr", True)
    app = QgsApplication([], True)
    app.initQgis()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        folder = args.products
        if folder is None:
            from clearfast_gis.export.testing import make_demo_products

            folder = str(make_demo_products(Path(tmp) / "products").root)
        from clearfast.loader import load_products

        project = QgsProject()
        loaded = load_products(folder, project)
        render_map(loaded, out / "plugin_map.png")
        grab_form(loaded.vectors["suspects"], out / "plugin_form.png")
        field_map_png(folder, out / "plugin_fieldmap.png")
        QApplication.processEvents()
    for name in ("plugin_map.png", "plugin_form.png", "plugin_fieldmap.png"):
        print(out / name)
    return 0


if __name__ == "__main__":
    sys.exit(main())
