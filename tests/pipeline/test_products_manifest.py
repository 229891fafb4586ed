"""The products manifest of a survey given by a relative path."""

from __future__ import annotations

import os
from types import SimpleNamespace

from clearfast_gis.export.products import base_manifest
from clearfast_gis.survey import read_survey
from clearfast_gis.survey.testing import make_minimal_survey


def test_inputs_of_a_survey_given_by_a_relative_path(tmp_path, monkeypatch):
    make_minimal_survey(tmp_path / "s")
    monkeypatch.chdir(tmp_path)
    survey = read_survey("s")
    options = SimpleNamespace(as_dict=lambda: {})
    manifest = base_manifest(survey, 32636, options, {}, {})
    assert sorted(manifest["inputs"]) == [
        "blackbody/frames.csv", "blackbody/temperatures.csv", "frames.csv", "gnss.nmea",
        "mission.json", "soil.csv", "survey.json", "weather.dat"]
    assert manifest["survey_path"] == os.path.join(str(tmp_path), "s")
