"""The whole chain on a radiometric-camera survey with known truth (issue 20, items 3 and 5):
the demo simulated as a FLIR camera writes it (radiometric JPEGs with their own time and
field object parameters, one LWIR band, no blackbodies), imported with ``clearfast import``
(times from the files' FFF records), processed unchanged, held to the raw-count demo's
accuracy targets (``tests/pipeline/test_end_to_end.py``). The TLinear and temperature-TIFF
paths are covered by ``test_import.py`` and the acquire tests; all three formats end to end
in BENCHMARKS.md (``benchmarks/camera_survey.py``)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from clearfast_gis.evaluation.truth import score_against_truth
from tests.conftest import _build_once
from tests.pipeline.test_end_to_end import assert_mosaics_match_truth

pytestmark = [pytest.mark.slow,
              pytest.mark.filterwarnings("ignore::rasterio.errors.NotGeoreferencedWarning")]


def _simulate(target):
    from clearfast_gis.simulate import preset, simulate_survey
    from clearfast_gis.simulate.camera_files import radiometric_camera_config, write_camera_folder

    res = simulate_survey(target, radiometric_camera_config(preset("demo")), seed=0)
    write_camera_folder(res.root, res.twin, "flir-rjpeg")


@pytest.fixture(scope="module")
def camera_survey():
    """(camera folder with truth/, imported survey, products)."""
    from clearfast_gis.cameras.survey_import import ImportSpec, import_survey
    from clearfast_gis.cli.import_survey import read_layout
    from clearfast_gis.pipeline import process_survey

    folder = _build_once("demo-rjpeg-camera", _simulate)
    survey = _build_once("demo-rjpeg-survey",
                         lambda t: import_survey(ImportSpec(**read_layout(folder)), t))
    products = _build_once("demo-rjpeg-products", lambda t: process_survey(survey, t))
    return folder, survey, products


def test_imported_survey_has_camera_radiometry_and_no_blackbodies(camera_survey):
    folder, survey, _ = camera_survey
    doc = json.loads((survey / "survey.json").read_text())
    assert doc["camera"]["radiometry"]["kind"] == "flir-planck"
    assert doc["camera"]["radiometry"]["source_format"] == "flir-rjpeg"
    assert "blackbody_frames" not in doc["files"] and not (survey / "blackbody").exists()
    assert len(list((folder / "camera").iterdir())) == 144
    products = json.loads((camera_survey[2] / "products.json").read_text())
    assert "camera_check" not in products  # nothing to check without blackbodies
    assert all(k.startswith(("survey", "mission", "frames", "gnss", "weather", "soil"))
               for k in products["inputs"])


def test_mosaics_match_true_apparent_temperature(camera_survey):
    folder, _, products = camera_survey
    assert_mosaics_match_truth(folder, products, 6)


def test_mines_found_as_in_the_raw_count_demo(camera_survey):
    folder, survey, products = camera_survey
    score = score_against_truth(survey, products, truth=folder)
    assert score.n_detected >= 4, score.summary()
    assert np.sqrt(np.mean(np.square(score.centre_errors_m))) < 0.05, score.summary()
