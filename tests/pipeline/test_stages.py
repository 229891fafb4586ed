"""The chain as a declared list of stages: names, options, keys, run-state units."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from clearfast_gis.pipeline.options import MOSAIC_PARAMETERS, ProcessOptions
from clearfast_gis.pipeline.stages import STAGE_NAMES, STAGES, RunContext, stage_index
from clearfast_gis.pipeline.state import RunState
from clearfast_gis.progress import NULL_PROGRESS
from clearfast_gis.resources import StageMeter


def context(options: ProcessOptions, products: Path = Path(".")) -> RunContext:
    return RunContext(Path("survey"), products, options, NULL_PROGRESS, StageMeter())


def keys(options: ProcessOptions) -> dict[str, str]:
    c = context(options)
    return {name: c.stage_key(name) for name in STAGE_NAMES}


def test_every_option_belongs_to_one_stage():
    named = [k for s in STAGES for k in s.options]
    assert len(named) == len(set(named))
    assert set(named) == {f.name for f in dataclasses.fields(ProcessOptions)}
    upto_mosaics = {k for s in STAGES[:stage_index("mosaics") + 1] for k in s.options}
    assert upto_mosaics == set(MOSAIC_PARAMETERS)
    assert len(set(STAGE_NAMES)) == len(STAGES)


@pytest.mark.parametrize(("change", "first_changed"), [
    ({"d2_m": 0.05}, "detection"),
    ({"level_fraction": 0.5}, "detection"),
    ({"invert": False}, "characterisation"),
    ({"pixel_size_m": 0.05}, "mosaics"),
    ({"adjust_attitude": False}, "mosaics"),
    ({"kernels": "reference"}, "band_coregistration"),
])
def test_a_parameter_redoes_its_stage_and_those_after(change, first_changed):
    before, after = keys(ProcessOptions()), keys(ProcessOptions(**change))
    k = stage_index(first_changed)
    assert all(before[n] == after[n] for n in STAGE_NAMES[:k])
    assert all(before[n] != after[n] for n in STAGE_NAMES[k:])


def test_units_are_kept_per_stage_key(tmp_path):
    state = RunState(tmp_path, "inputs")
    c = context(ProcessOptions(), tmp_path)
    c.state = state
    c.stage_state("mosaics").finish("scan_000", {"scan": 0})
    c.stage_state("products").finish("", {"n": 3})
    assert set(state.units) == {"mosaics/scan_000", "products"}
    other = context(ProcessOptions(d1_m=0.4), tmp_path)
    other.state = state
    assert other.stage_state("mosaics").done("scan_000")["scan"] == 0
    assert other.stage_state("products").done() is None
    assert c.stage_state("products").done()["n"] == 3
    state.drop("mosaics")
    assert set(state.units) == {"products"}
    state.close()


def test_unknown_stage_names_the_stages():
    with pytest.raises(ValueError, match="unknown stage 'mosaic'.*residuals_and_footprint"):
        stage_index("mosaic")


def test_from_a_later_stage_redoes_it_and_never_keeps_the_old_products(demo_survey,
                                                                      demo_products, tmp_path):
    """``--from characterisation`` re-runs characterisation and products even though the
    detection stage would otherwise find the earlier run's products up to date."""
    import shutil

    import numpy as np

    from clearfast_gis.export.layout import DECODED_REL
    from clearfast_gis.pipeline import process_survey

    products = tmp_path / "products"
    shutil.copytree(demo_products, products)
    (products / "anomalies.gpkg").unlink()
    # a killed run's decoded mosaics (scratch) are never read: the run deletes them first
    stale = products / DECODED_REL / "scan_000.f32"
    stale.parent.mkdir(parents=True)
    np.zeros(7, dtype=np.float32).tofile(stale)
    manifest = process_survey(demo_survey, products, from_stage="characterisation")
    assert (products / "anomalies.gpkg").exists()
    assert manifest["timings_s"]["characterisation"] > 0.05
    assert not (products / DECODED_REL).exists()  # and deleted when the run ends


def test_the_context_reads_each_table_once(demo_survey, monkeypatch):
    """The chain's context takes the logs and the frame tables validation parsed: the frames
    table and the blackbody frames table are parsed once per run, and the survey's tables
    are validation's own objects, equal to a fresh read of the files."""
    import numpy as np

    from clearfast_gis.pipeline.inputs import open_context
    from clearfast_gis.survey import model, read_survey, tables

    calls = {"frames": 0, "blackbody_frames": 0}
    for name, parse in (("frames", tables.parse_frames_table),
                        ("blackbody_frames", tables.parse_blackbody_frames_table)):
        def counted(*args, _parse=parse, _name=name, **kwargs):
            calls[_name] += 1
            return _parse(*args, **kwargs)
        monkeypatch.setattr(tables, f"parse_{name}_table", counted)
    from clearfast_gis.survey import validate
    monkeypatch.setattr(validate, "parse_frames_table", tables.parse_frames_table)
    monkeypatch.setattr(validate, "parse_blackbody_frames_table",
                        tables.parse_blackbody_frames_table)
    ctx, _, report = open_context(demo_survey)
    assert ctx.survey.frames is report.logs.frames
    assert ctx.survey.blackbody_frames is report.logs.blackbody_frames
    assert calls == {"frames": 1, "blackbody_frames": 1}
    fresh = read_survey(demo_survey)
    assert isinstance(fresh, model.Survey)
    for name in ("frames", "blackbody_frames"):
        a, b = getattr(ctx.survey, name), getattr(fresh, name)
        for field in dataclasses.fields(a):
            np.testing.assert_array_equal(getattr(a, field.name), getattr(b, field.name))
