"""products.json and the default QML styles."""

from __future__ import annotations

import hashlib
import json
import xml.etree.ElementTree as ET

import pytest

from clearfast_gis.errors import InvalidInput
from clearfast_gis.export import (
    default_styles,
    mine_action_style,
    mosaic_style,
    read_products_manifest,
    sha256_file,
    write_products_manifest,
)
from clearfast_gis.export.styles import CLASS_COLOURS_RGB, mosaic_ramp_stops

MANIFEST = {"survey_id": "demo-seed0", "crs": {"epsg": 32636},
            "time": {"start_utc": "2026-11-15T00:00:00Z", "end_utc": "2026-11-16T00:00:00Z"},
            "software": {"name": "clearfast-gis", "version": "0.1.0"},
            "timings_s": {"mosaic": 1.5},
            "scans": [{"scan": 0, "time_utc": "2026-11-15T00:00:00Z",
                       "file": "mosaics/scan_000.tif"}]}


def test_manifest_round_trip(tmp_path):
    path = write_products_manifest(tmp_path, MANIFEST)
    assert path == tmp_path / "products.json"
    doc = read_products_manifest(tmp_path)
    assert doc == {"format": "clearfast-products", "format_version": 1, **MANIFEST}


@pytest.mark.parametrize(("change", "field"), [
    ({"crs": {"epsg": "32636"}}, "crs.epsg"),
    ({"survey_id": "bad id/1"}, "survey_id"),
    ({"scans": [{"scan": 0, "time_utc": "2026-11-15T00:00:00Z", "file": "scan0.tif"}]},
     "scans[0].file"),
    ({"timings_s": {"mosaic": -1}}, "timings_s.mosaic"),
])
def test_manifest_invalid_field(tmp_path, change, field):
    with pytest.raises(InvalidInput) as err:
        write_products_manifest(tmp_path, {**MANIFEST, **change})
    assert err.value.field == field
    assert not (tmp_path / "products.json").exists()


def test_manifest_missing_and_broken(tmp_path):
    doc = dict(MANIFEST)
    del doc["time"]
    with pytest.raises(InvalidInput, match="time: missing"):
        write_products_manifest(tmp_path, doc)
    with pytest.raises(InvalidInput, match="not a products folder"):
        read_products_manifest(tmp_path)
    (tmp_path / "products.json").write_text("{\n  oops")
    with pytest.raises(InvalidInput) as err:
        read_products_manifest(tmp_path)
    assert err.value.field == "line 2"


def test_sha256_known_answer(tmp_path):
    (tmp_path / "abc").write_bytes(b"abc")
    assert sha256_file(tmp_path / "abc") == (
        "sha256:ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad")
    big = bytes(range(256)) * 10000
    (tmp_path / "big").write_bytes(big)
    assert sha256_file(tmp_path / "big", chunk_bytes=777) == (
        "sha256:" + hashlib.sha256(big).hexdigest())


def _categories(qml: str) -> tuple[str, dict]:
    root = ET.fromstring(qml)
    renderer = root.find("renderer-v2")
    symbols = {s.get("name"): s for s in renderer.find("symbols")}
    colours = {}
    for cat in renderer.find("categories"):
        sym = symbols[cat.get("symbol")]
        opt = sym.find(".//Option[@name='color']")
        colours[cat.get("value")] = tuple(int(v) for v in opt.get("value").split(",")[:3])
    return renderer.get("attr"), colours


def _rule_colours(qml: str) -> dict[str, tuple[int, int, int]]:
    """Rule label -> fill colour (RGB) of a rule-based renderer."""
    renderer = ET.fromstring(qml).find("renderer-v2")
    assert renderer.get("type") == "RuleRenderer"
    symbols = {s.get("name"): s for s in renderer.find("symbols")}
    colours = {}
    for rule in renderer.iter("rule"):
        opt = symbols[rule.get("symbol")].find(".//Option[@name='color']")
        colours[rule.get("label")] = tuple(int(v) for v in opt.get("value").split(",")[:3])
    return colours


def test_default_styles_layers_and_class_colours():
    styles = default_styles()
    assert set(styles) == {"anomalies", "suspects", "candidates", "markers", "footprint"}
    assert set(default_styles(["suspects", "markers", "other"])) == {"suspects", "markers"}
    for qml in styles.values():
        assert ET.fromstring(qml).tag == "qgis"
    attr, colours = _categories(mine_action_style())
    assert attr == "class_cue" and colours == CLASS_COLOURS_RGB
    assert _rule_colours(styles["suspects"]) == {
        "AT mine indication": CLASS_COLOURS_RGB["at_mine"],
        "AP mine indication": CLASS_COLOURS_RGB["ap_mine"],
        "Mine indication, other cue": CLASS_COLOURS_RGB["at_mine"],
        "Other suspect": CLASS_COLOURS_RGB["unknown"],
        "Clutter": CLASS_COLOURS_RGB["clutter"]}
    root = ET.fromstring(styles["suspects"])
    # clutter is off by default (one click in the legend), everything else on
    assert {r.get("label"): r.get("checkstate", "1") for r in root.iter("rule")
            if r.get("label")}["Clutter"] == "0"
    assert root.find(".//labeling").get("type") == "rule-based"
    assert root.find(".//labeling//text-style").get("fieldName") == "short_id"
    assert ET.fromstring(mine_action_style()).find(
        ".//labeling/settings/text-style").get("fieldName") == "imsma_id"


def test_mosaic_style_stretch():
    stops = mosaic_ramp_stops()
    assert stops[0] == (0.0, (0, 0, 0)) and stops[-1] == (1.0, (255, 255, 255))
    root = ET.fromstring(mosaic_style(5.0, 25.0))
    renderer = root.find(".//rasterrenderer")
    assert renderer.get("type") == "singlebandpseudocolor"
    assert float(renderer.get("classificationMin")) == 5.0
    assert float(renderer.get("classificationMax")) == 25.0
    values = [float(i.get("value")) for i in root.iter("item")]
    assert values == pytest.approx([5.0 + 20.0 * p for p, _ in stops], abs=1e-4)
    with pytest.raises(ValueError):
        mosaic_style(3.0, 3.0)
    json.dumps(stops)  # plain data
