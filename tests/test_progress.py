"""Progress lines: inside the chain every line carries the chain's stage name (the meter's
and the run state's), its label and the step counted; elsewhere a step is its own stage."""

from __future__ import annotations

import io
import json

import pytest

from clearfast_gis.pipeline.stages import STAGES
from clearfast_gis.progress import Progress


def _lines(out: io.StringIO) -> list[dict]:
    return [json.loads(s) for s in out.getvalue().splitlines()]


def test_chain_stage_lines_carry_the_stage_name_label_and_step():
    out = io.StringIO()
    p = Progress("json", stream=out)
    stage = next(s for s in STAGES if s.name == "attitude_adjustment")
    with p.chain_stage(stage.name, stage.label):
        p.message("a note")
        p.start("refined attitude adjustment", 4)
        p.advance(3, scan=7)
        p.advance(1, scan=8)
    ev = _lines(out)
    assert [e["event"] for e in ev] == ["stage", "message", "start", "progress", "progress",
                                        "end"]
    assert {e["stage"] for e in ev} == {"attitude_adjustment"}
    assert {e["label"] for e in ev} == {"survey-wide attitude adjustment"}
    assert [e.get("step") for e in ev] == [None, None] + ["refined attitude adjustment"] * 4
    assert [e.get("done") for e in ev[2:]] == [0, 3, 4, 4]
    assert ev[3]["scan"] == 7 and ev[-1]["fraction"] == 1.0


def test_a_stage_without_steps_reports_its_name_once_and_no_end():
    out = io.StringIO()
    p = Progress("json", stream=out)
    with p.chain_stage("read_and_validate", "read and validate the survey folder"):
        pass
    assert _lines(out) == [{"event": "stage", "stage": "read_and_validate",
                            "label": "read and validate the survey folder"}]


def test_outside_the_chain_a_step_is_its_own_stage():
    out = io.StringIO()
    p = Progress("json", stream=out)
    p.start("import", 2)
    p.advance(2)
    p.close()
    ev = _lines(out)
    assert [(e["event"], e["stage"]) for e in ev] == [("start", "import"),
                                                     ("progress", "import"), ("end", "import")]
    assert not any("label" in e or "step" in e for e in ev)


def test_bar_names_the_chain_stage(capsys):
    p = Progress("bar")
    with p.chain_stage("mosaics", "one mosaic per scan, attitude fitted"):
        p.start("mosaics", 2)
        p.advance(2)
    with p.chain_stage("detection", "anomaly detection on the mosaics"):
        p.start("detect", 1)
        p.advance(1)
    err = capsys.readouterr().err
    assert "mosaics (one mosaic per scan, attitude fitted)" in err
    assert "detection: detect" in err


def test_stage_labels_are_one_line_each_and_distinct():
    labels = [s.label for s in STAGES]
    assert len(set(labels)) == len(labels) and all(x and "\n" not in x for x in labels)


@pytest.mark.parametrize("mode", ["json", "none"])
def test_unknown_mode_is_refused_and_known_modes_work(mode):
    Progress(mode, stream=io.StringIO()).close()
    with pytest.raises(ValueError, match="unknown progress mode"):
        Progress("xml")
