"""Default QGIS styles (QML) of the products, shipped in ``clearfast_gis/styles``.

Point symbology follows the usual mine action map conventions (GICHD-like): red for AT/AP mine
indications, orange for unknown anomalies, grey for clutter. Mosaics use a thermal ramp
(black - violet - orange - yellow - white) whose range is set per products folder.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterable
from pathlib import Path

STYLES_DIR = Path(__file__).resolve().parents[1] / "styles"
"""Folder of the QML files (package data)."""

LAYER_STYLES: dict[str, str] = {
    "anomalies": "anomalies.qml",
    "suspects": "suspects.qml",
    "candidates": "suspects.qml",
    "markers": "markers.qml",
    "footprint": "footprint.qml",
}
"""GeoPackage layer name -> QML file of its default style. ``suspects.qml`` is built in QGIS by
``scripts/build_suspects_style.py`` (the set-aside ``candidates`` share it)."""

MINE_ACTION_STYLE = "mine_action.qml"
MINE_ACTION_LAYER_STYLES: dict[str, str] = {
    "indications": MINE_ACTION_STYLE,
    "hazard_proposals": "hazard_proposals.qml",
    "surveyed_area": "surveyed_area.qml",
}
"""Layer of ``mine_action.gpkg`` -> QML file of its default style."""
MOSAIC_STYLE = "mosaic.qml"

CLASS_COLOURS_RGB: dict[str, tuple[int, int, int]] = {
    "at_mine": (227, 26, 28),
    "ap_mine": (227, 26, 28),
    "unknown": (255, 127, 0),
    "clutter": (150, 150, 150),
}
"""Symbol fill colour of each class cue (RGB 0-255)."""


def style_text(file_name: str) -> str:
    """The QML text of ``clearfast_gis/styles/<file_name>``."""
    return (STYLES_DIR / file_name).read_text(encoding="utf-8")


def default_styles(layers: Iterable[str] | None = None) -> dict[str, str]:
    """Default styles of the ``anomalies.gpkg`` layers: layer name -> QML text.

    ``layers`` limits them to the layers actually written (default: all of
    :data:`LAYER_STYLES`); layers without a default style are left out.
    """
    names = LAYER_STYLES if layers is None else [n for n in layers if n in LAYER_STYLES]
    return {layer: style_text(LAYER_STYLES[layer]) for layer in names}


def mine_action_style() -> str:
    """QML of the mine-action indications layer (class colours, labelled by ``imsma_id``)."""
    return style_text(MINE_ACTION_STYLE)


def mine_action_styles() -> dict[str, str]:
    """Default styles of the ``mine_action.gpkg`` layers: layer name -> QML text (evidence by
    class colour, hazard proposals red, the surveyed area a dashed outline)."""
    return {layer: style_text(name) for layer, name in MINE_ACTION_LAYER_STYLES.items()}


def mosaic_ramp_stops() -> list[tuple[float, tuple[int, int, int]]]:
    """The thermal ramp of the mosaic style: (position 0-1, RGB) pairs, ascending."""
    root = ET.fromstring(style_text(MOSAIC_STYLE))
    items = root.findall(".//colorrampshader/item")
    values = [float(i.get("value")) for i in items]
    lo, hi = values[0], values[-1]
    stops = []
    for item, value in zip(items, values, strict=True):
        colour = item.get("color").lstrip("#")
        rgb = tuple(int(colour[k:k + 2], 16) for k in (0, 2, 4))
        stops.append(((value - lo) / (hi - lo), rgb))
    return stops


def mosaic_style(min_c: float, max_c: float) -> str:
    """The mosaic QML with its thermal ramp stretched over [``min_c``, ``max_c``] degrees C.

    Raises ``ValueError`` unless ``min_c < max_c``.
    """
    if not min_c < max_c:
        raise ValueError("min_c must be below max_c")
    root = ET.fromstring(style_text(MOSAIC_STYLE))
    for renderer in root.iter("rasterrenderer"):
        renderer.set("classificationMin", repr(float(min_c)))
        renderer.set("classificationMax", repr(float(max_c)))
    for shader in root.iter("colorrampshader"):
        shader.set("minimumValue", repr(float(min_c)))
        shader.set("maximumValue", repr(float(max_c)))
    for pos, item in zip((p for p, _ in mosaic_ramp_stops()), root.iter("item"), strict=True):
        value = min_c + pos * (max_c - min_c)
        item.set("value", f"{value:.4f}")
        item.set("label", f"{value:.1f} °C")
    return "<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>\n" + ET.tostring(
        root, encoding="unicode")
