"""Scenario files: schema errors name file and field; objects land where the scenario says."""

from __future__ import annotations

import csv
import json
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.simulate import load_scenario, parse_scenario, preset, simulate_survey
from clearfast_gis.simulate.objects import KINDS, draw_objects
from clearfast_gis.simulate.run import site_origin
from clearfast_gis.simulate.scenario import scenario_document, scenario_schema
from clearfast_gis.thermal.materials import MINE_FILLS


def _doc(**kw) -> dict:
    return {"format": "clearfast-scenario", "format_version": 1, **kw}


def test_overrides_apply():
    scen = parse_scenario(_doc(preset="trial", n_scans=5, camera={"model": "pinhole"},
                               lift={"height_m": 14.0}, site={"epsg": 32636}))
    assert scen.config.name == "trial" and scen.config.n_scans == 5
    assert scen.config.camera_model == "pinhole" and scen.config.lift_height_m == 14.0
    assert scen.objects is None


@pytest.mark.parametrize(("doc", "field"), [
    (_doc(objects=[{"kind": "bomb", "x_m": 1, "y_m": 1}]), "objects.0.kind"),
    (_doc(objects=[{"kind": "at_mine", "x_m": 1}]), "objects.0"),
    (_doc(camera={"resolution": [160]}), "camera.resolution"),
    (_doc(n_scans=0), "n_scans"),
    (_doc(preset="huge"), "preset"),
    (_doc(objects=[{"kind": "ap_mine", "x_m": 50, "y_m": 1}]), "objects.0"),
    ({"format": "clearfast-scenario"}, "(top level)"),
])
def test_schema_errors_name_file_and_field(tmp_path, doc, field):
    path = tmp_path / "scenario.json"
    path.write_text(json.dumps(doc))
    with pytest.raises(InvalidInput) as info:
        load_scenario(path)
    assert info.value.path == str(path)
    assert info.value.field == field


def test_not_json(tmp_path):
    path = tmp_path / "s.json"
    path.write_text("{nope")
    with pytest.raises(InvalidInput, match="not JSON"):
        load_scenario(path)


_objects = st.lists(st.fixed_dictionaries({
    "kind": st.sampled_from(KINDS),
    "x_m": st.floats(0.0, 8.0), "y_m": st.floats(0.0, 6.0),
    "depth_m": st.floats(0.0, 0.3), "diameter_m": st.floats(0.01, 5.0),
}), max_size=8).map(lambda objs: [
    dict(o, material=MINE_FILLS[i % len(MINE_FILLS)]) if o["kind"] in ("at_mine", "ap_mine")
    and i % 2 else o for i, o in enumerate(objs)])


@settings(max_examples=50, deadline=None)
@given(_objects)
def test_scenario_document_round_trip(objs):
    doc = _doc(objects=[dict(o, id=f"O{i}") for i, o in enumerate(objs)])
    scen = parse_scenario(doc)
    again = parse_scenario(scenario_document(scen.config, list(scen.objects)))
    assert again.objects == scen.objects


@settings(max_examples=20, deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_drawn_objects_inside_and_apart(seed):
    cfg = preset("demo")
    objs = draw_objects(cfg, np.random.default_rng(seed))
    assert len({o.id for o in objs}) == len(objs)
    for o in objs:
        assert 0.0 <= o.x_m - o.radius_m and o.x_m + o.radius_m <= cfg.area_width_m
        assert 0.0 <= o.y_m - o.radius_m and o.y_m + o.radius_m <= cfg.area_length_m
    for i, a in enumerate(objs):
        for b in objs[i + 1:]:
            assert np.hypot(a.x_m - b.x_m, a.y_m - b.y_m) > a.radius_m + b.radius_m
    depths = {o.depth_m for o in objs if o.kind in ("at_mine", "ap_mine")}
    assert 0.0 in depths and max(depths) >= 0.05


def test_objects_placed_where_the_scenario_says(tmp_path, small_config):
    objects = [
        {"id": "AT-A", "kind": "at_mine", "x_m": 1.5, "y_m": 2.0, "depth_m": 0.0},
        {"id": "AP-B", "kind": "ap_mine", "x_m": 3.5, "y_m": 1.2, "depth_m": 0.02},
        {"id": "MK-C", "kind": "marker", "x_m": 4.4, "y_m": 3.4, "variant": "cold"},
    ]
    path = tmp_path / "scenario.json"
    path.write_text(json.dumps(_doc(objects=objects)))
    scen = load_scenario(path, replace(small_config, n_scans=2))
    res = simulate_survey(tmp_path / "out", scen.config, seed=4, objects=list(scen.objects))
    origin = site_origin(scen.config)
    with open(res.root / "truth" / "objects.csv") as fh:
        rows = {r["id"]: r for r in csv.DictReader(fh)}
    assert set(rows) == {"AT-A", "AP-B", "MK-C"}
    for o in objects:
        r = rows[o["id"]]
        assert float(r["x"]) == pytest.approx(origin[0] + o["x_m"], abs=1e-3)
        assert float(r["y"]) == pytest.approx(origin[1] + o["y_m"], abs=1e-3)
        assert r["kind"] == o["kind"]
    assert float(rows["AT-A"]["diameter_m"]) == pytest.approx(0.337)
    assert float(rows["AP-B"]["depth_m"]) == pytest.approx(0.02)
    # the truth's own scenario.json reproduces the objects
    again = load_scenario(res.root / "truth" / "scenario.json", scen.config)
    assert [o.id for o in again.objects] == ["AT-A", "AP-B", "MK-C"]
    # and the surface-laid AT mine shows in the truth apparent temperature at its position
    import rasterio

    with rasterio.open(res.root / "truth" / "apparent_temperature" / "scan_001.tif") as src:
        img = src.read(1)
        r0, c0 = src.index(origin[0] + 1.5, origin[1] + 2.0)
        r1, c1 = src.index(origin[0] + 1.5, origin[1] + 2.6)
    assert abs(float(img[r0, c0]) - float(img[r1, c1])) > 0.3


def test_mine_fills_are_the_materials_the_schema_allows():
    """One list of mine bodies: the schema's enums are :data:`MINE_FILLS`."""
    schema = scenario_schema()["properties"]
    assert schema["mine_fills"]["items"]["enum"] == list(MINE_FILLS)
    assert schema["objects"]["items"]["properties"]["material"]["enum"] == list(MINE_FILLS)


def test_mine_fills_drawn_per_mine_keep_the_layout():
    """``mine_fills`` gives each mine a body from the list, seeded; the layout and every other
    object are those of the same seed without it."""
    plain = preset("demo")
    varied = parse_scenario(_doc(mine_fills=["comp_b", "plastic", "pine"])).config
    assert varied.mine_fills == ("comp_b", "plastic", "pine")
    seen = set()
    for seed in range(6):
        a = draw_objects(plain, np.random.default_rng(seed))
        b = draw_objects(varied, np.random.default_rng(seed))
        again = draw_objects(varied, np.random.default_rng(seed))
        assert b == again
        assert [replace(o, material="") for o in b] == a
        for o in b:
            if o.kind in ("at_mine", "ap_mine"):
                assert o.material in varied.mine_fills
                seen.add(o.material)
            else:
                assert o.material == ""
    assert seen == set(varied.mine_fills)
    assert all(o.material == "" for o in draw_objects(plain, np.random.default_rng(0)))


def test_material_is_for_mines_only():
    doc = _doc(objects=[{"kind": "stone", "x_m": 1, "y_m": 1, "material": "pine"}])
    with pytest.raises(InvalidInput) as info:
        parse_scenario(doc)
    assert info.value.field == "objects.0.material"
    with pytest.raises(InvalidInput) as info:
        parse_scenario(_doc(mine_fills=["tnt", "wax"]))
    assert info.value.field == "mine_fills.1"


def test_a_mines_body_sets_its_truth_and_its_contrast(tmp_path, small_config):
    """A plastic-bodied and a wooden mine at 2 cm: truth records their material and
    diffusivity, and each has its own thermal run, the plastic one (higher diffusivity,
    lower heat capacity than TNT) with a different contrast from a TNT mine's."""
    from clearfast_gis.simulate.surface import object_key, thermal_truth
    from clearfast_gis.simulate.twin import build_twin
    from clearfast_gis.thermal import MATERIALS

    objects = [
        {"id": "AP-T", "kind": "ap_mine", "x_m": 1.0, "y_m": 2.0, "depth_m": 0.02},
        {"id": "AP-P", "kind": "ap_mine", "x_m": 2.5, "y_m": 2.0, "depth_m": 0.02,
         "material": "plastic"},
        {"id": "AP-W", "kind": "ap_mine", "x_m": 4.0, "y_m": 2.0, "depth_m": 0.02,
         "material": "pine"},
    ]
    scen = parse_scenario(_doc(objects=objects), None, replace(small_config, n_scans=2))
    res = simulate_survey(tmp_path / "out", scen.config, seed=4, objects=list(scen.objects))
    with open(res.root / "truth" / "objects.csv") as fh:
        rows = {r["id"]: r for r in csv.DictReader(fh)}
    for oid, name in (("AP-T", "tnt"), ("AP-P", "plastic"), ("AP-W", "pine")):
        assert rows[oid]["material"] == name
        assert float(rows[oid]["diffusivity_m2s"]) == pytest.approx(MATERIALS[name].alpha_m2s,
                                                              rel=1e-3)
    again = load_scenario(res.root / "truth" / "scenario.json", scen.config)
    assert [o.material for o in again.objects] == ["", "plastic", "pine"]
    twin = build_twin(scen.config, seed=4)
    times = twin.start_s + np.array([10.0, 14.0]) * 3600.0
    truth = thermal_truth(twin.forcing, times, list(scen.objects))
    runs = [truth.objects[object_key(o)].contrast_k[:, 0] for o in scen.objects]
    assert len(truth.objects) == 3
    assert np.max(np.abs(runs[1] - runs[0])) > 0.02
    assert np.max(np.abs(runs[2] - runs[0])) > 0.02
