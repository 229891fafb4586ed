"""The field map in a real QGIS (headless): layout items, the mine-indication table, the PDF."""

from __future__ import annotations

import subprocess

import pytest

pytestmark = pytest.mark.qgis


def pdf_text(pdf) -> str:
    return subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True,
                          text=True, check=True).stdout


def test_nice_steps(qgis_app):
    from clearfast.fieldmap import nice_floor, nice_step

    assert [nice_step(s) for s in (11.0, 30.0, 0.7)] == [5.0, 10.0, 0.2]
    assert [nice_floor(v) for v in (2.2, 7.9, 0.031)] == [2.0, 5.0, 0.02]


def test_layout_items_and_table(project, products):
    from clearfast.fieldmap import build_field_map
    from qgis.core import (
        QgsLayoutItemLegend,
        QgsLayoutItemManualTable,
        QgsLayoutItemMap,
        QgsLayoutItemPicture,
        QgsLayoutItemScaleBar,
    )

    layout, loaded = build_field_map(str(products.root), project)
    items = layout.items()
    maps = [i for i in items if isinstance(i, QgsLayoutItemMap)]
    assert len(maps) == 1 and layout.pageCollection().pageCount() == 1
    grids = maps[0].grids().asList()
    assert [g.crs().authid() for g in grids] == ["EPSG:32636", "EPSG:4326"]
    assert maps[0].crs().authid() == "EPSG:32636"
    assert maps[0].extent().contains(loaded.extent)
    names = {layer.name() for layer in maps[0].layers()}
    assert {"Suspects", "Markers", "Footprint"} <= names
    # the best-contrast scan: 12:00 UTC, when the day contrasts peak in make_demo_products
    assert any(n.startswith("Scan 002 2026-11-15 12:00") for n in names)
    assert any(isinstance(i, QgsLayoutItemScaleBar) for i in items)
    assert any(isinstance(i, QgsLayoutItemLegend) for i in items)
    assert any(isinstance(i, QgsLayoutItemPicture) and i.northMode() is not None for i in items)
    tables = [m for m in layout.multiFrames() if isinstance(m, QgsLayoutItemManualTable)]
    assert len(tables) == 1
    rows = [[c.content() for c in row] for row in tables[0].tableContents()]
    # the four AT/AP mine indications, AT first then AP, each by contrast (the style's order)
    assert [r[0] for r in rows] == ["S-001", "S-002", "S-003", "S-004"]
    assert [r[1] for r in rows] == ["AT", "AT", "AP", "AP"]
    a1 = next(f for f in loaded.vectors["suspects"].getFeatures() if f["anomaly_id"] == "A001")
    assert rows[0][2:6] == [f"{a1['x']:.2f}", f"{a1['y']:.2f}", f"{a1['lat']:.7f}",
                            f"{a1['lon']:.7f}"]
    assert rows[0][6] == "1.0 ± 0.5 cm"


def test_pdf_one_page_with_title_block_and_table(qgis_app, products, tmp_path):
    from clearfast.fieldmap import export_field_map

    pdf = tmp_path / "maps" / "field_map.pdf"
    assert export_field_map(str(products.root), str(pdf)) == str(pdf)
    info = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True, check=True)
    assert "Pages:           1" in info.stdout
    assert "297 x 210 pts" not in info.stdout and "842 x 595" in info.stdout  # A4 landscape
    text = pdf_text(pdf)
    for needle in ("demo-seed0", "EPSG:32636", "stand-off thermal IR", "Indirect evidence",
                   "Mine indications", "S-001", "S-004", "AT mine indication"):
        assert needle in text, needle
    assert "S-005" not in text  # clutter and unknown suspects are not in the table


def test_field_map_algorithm(qgis_app, products, tmp_path):
    from qgis.core import QgsApplication, QgsProcessingContext, QgsProcessingFeedback

    alg = QgsApplication.processingRegistry().createAlgorithmById("clearfast:fieldmap")
    assert alg is not None and alg.canExecute()
    pdf = tmp_path / "fm.pdf"
    context = QgsProcessingContext()
    results, ok = alg.run({"PRODUCTS": str(products.root), "OUTPUT": str(pdf)}, context,
                          QgsProcessingFeedback())
    assert ok and results["OUTPUT"] == str(pdf) and pdf.stat().st_size > 10_000
    results, ok = alg.run({"PRODUCTS": str(tmp_path), "OUTPUT": str(tmp_path / "x.pdf")},
                          context, QgsProcessingFeedback())
    assert not ok and not (tmp_path / "x.pdf").exists()
