"""The CLEARFAST Processing algorithms inside a real QGIS: outputs as layers, progress,
cancellation, errors and the missing-toolkit message."""

from __future__ import annotations

import importlib.util
import json
import os
import shlex
import threading
import time

import pytest

pytestmark = pytest.mark.qgis

# Process survey runs the real chain (on a simulated survey) once the pipeline's CLI has landed
# and CLEARFAST_PLUGIN_REAL_PIPELINE=1; otherwise the fake toolkit stands in for it.
REAL_PIPELINE = (importlib.util.find_spec("clearfast_gis.cli.process") is not None
                 and importlib.util.find_spec("clearfast_gis.cli.simulate") is not None
                 and os.environ.get("CLEARFAST_PLUGIN_REAL_PIPELINE") == "1")


class RecordingFeedback:
    """A QgsProcessingFeedback that records progress values and log lines."""

    def __new__(cls):
        from qgis.core import QgsProcessingFeedback

        class _Feedback(QgsProcessingFeedback):
            def __init__(self):
                super().__init__()
                self.values, self.infos, self.console, self.texts = [], [], [], []
                self.progressChanged.connect(self.values.append)

            def pushInfo(self, info):
                self.infos.append(info)
                super().pushInfo(info)

            def pushConsoleInfo(self, info):
                self.console.append(info)
                super().pushConsoleInfo(info)

            def setProgressText(self, text):
                self.texts.append(text)
                super().setProgressText(text)

        return _Feedback()


def run_alg(alg_id, params, feedback=None):
    from qgis.core import QgsApplication, QgsProcessingContext, QgsProject

    alg = QgsApplication.processingRegistry().createAlgorithmById(alg_id)
    assert alg is not None, alg_id
    context = QgsProcessingContext()
    project = QgsProject()
    context.setProject(project)
    feedback = feedback or RecordingFeedback()
    ok, message = alg.checkParameterValues(params, context)
    assert ok, message
    results, success = alg.run(params, context, feedback)
    return results, success, context, feedback


def layers_to_load(context):
    from qgis.core import QgsProcessingUtils

    layers = {}
    for layer_id, details in context.layersToLoadOnCompletion().items():
        layer = QgsProcessingUtils.mapLayerFromString(layer_id, context)
        layers[details.name] = layer
    return layers


def test_export_mine_action_real_toolkit(qgis_app, products, real_toolkit, tmp_path):
    out = tmp_path / "ma"
    results, ok, context, feedback = run_alg(
        "clearfast:exportmineaction", {"PRODUCTS": str(products.root), "OUTPUT": str(out),
                                       "ALL_SUSPECTS": True, "ORGANISATION": "Test org"})
    assert ok, feedback.textLog()
    assert results["COUNT"] == products.n_suspects
    assert os.path.isfile(results["CSV"])
    layers = layers_to_load(context)
    layer = layers["Mine action indications"]
    assert layer.isValid() and layer.crs().authid() == "EPSG:4326"
    assert layer.featureCount() == products.n_suspects
    assert layer.renderer().type() == "categorizedSymbol"  # default style from the GeoPackage
    assert {f["land_class"] for f in layer.getFeatures()} == {"indication"}
    assert {f["organisation"] for f in layer.getFeatures()} == {"Test org"}
    hazards = layers["Hazard polygon proposals"]
    assert hazards.isValid() and hazards.featureCount() >= 1
    assert all(f.geometry().isGeosValid() for f in hazards.getFeatures())
    assert layers["Surveyed area"].featureCount() == 1
    # the default: only the mine indications (AT/AP cue) are evidence
    results, ok, context, feedback = run_alg(
        "clearfast:exportmineaction", {"PRODUCTS": str(products.root),
                                       "OUTPUT": str(tmp_path / "mines")})
    assert ok and results["COUNT"] == 4
    assert feedback.values and max(feedback.values) == pytest.approx(100.0)


def test_process_survey_returns_layers(qgis_app, fake_toolkit, tmp_path, monkeypatch):
    import subprocess
    import sys

    survey = tmp_path / "survey"
    if REAL_PIPELINE:
        subprocess.run([sys.executable, "-m", "clearfast_gis.cli.main", "simulate", str(survey)],
                       check=True, capture_output=True)
        monkeypatch.setenv("CLEARFAST_COMMAND",
                           shlex.join([sys.executable, "-m", "clearfast_gis.cli.main"]))
    else:
        survey.mkdir()
    out = tmp_path / "products"
    results, ok, context, feedback = run_alg(
        "clearfast:processsurvey", {"SURVEY": str(survey), "OUTPUT": str(out)})
    assert ok, feedback.textLog()
    assert results["OUTPUT"] == str(out)
    layers = layers_to_load(context)
    assert {"Suspects", "Anomaly outlines", "Markers", "Footprint"} <= set(layers)
    assert all(layer.isValid() for layer in layers.values())
    assert len(results["MOSAICS"]) >= 1
    assert results["SUSPECTS"].endswith("|layername=suspects")
    if not REAL_PIPELINE:
        assert len(results["MOSAICS"]) == 3
        args = json.loads((out / "fake_args.json").read_text())
        assert args == ["process", str(survey), "-o", str(out), "--progress", "json"]


def test_rerun_detection_passes_parameters(qgis_app, fake_toolkit, tmp_path):
    from clearfast_gis.export.testing import make_demo_products

    folder = tmp_path / "p"
    make_demo_products(folder, n_scans=2, pixel_size_m=0.1, figures=False)
    results, ok, context, feedback = run_alg("clearfast:rerundetection", {
        "PRODUCTS": str(folder), "D1": 0.4, "D2": 0.06, "EPSILON": 0.02, "LEVEL": 3,
        "GAMMA": 1.5})
    assert ok, feedback.textLog()
    args = json.loads((folder / "fake_args.json").read_text())
    assert args == ["detect", str(folder), "--d1", "0.4", "--d2", "0.06", "--epsilon", "0.02",
                    "--level", "3", "--gamma", "1.5", "--progress", "json"]
    assert "Suspects" in layers_to_load(context)
    results2, ok, _, _ = run_alg("clearfast:rerundetection", {
        "PRODUCTS": str(folder), "D1": 0.5, "D2": 0.05, "EPSILON": 0.01})
    args = json.loads((folder / "fake_args.json").read_text())
    assert "--level" not in args and "--gamma" not in args


def test_rerun_detection_rejects_d2_not_below_d1(qgis_app, products):
    from qgis.core import QgsApplication, QgsProcessingContext

    alg = QgsApplication.processingRegistry().createAlgorithmById("clearfast:rerundetection")
    ok, message = alg.checkParameterValues(
        {"PRODUCTS": str(products.root), "D1": 0.1, "D2": 0.2, "EPSILON": 0.01},
        QgsProcessingContext())
    assert not ok and "D2" in message


def test_validate_survey(qgis_app, fake_toolkit, tmp_path, monkeypatch):
    survey = tmp_path / "survey"
    survey.mkdir()
    (survey / "markers.csv").write_text("id,lat_deg,lon_deg,description\n"
                                        "M1,35.17,33.36,stake\nM2,35.1701,33.3601,stake\n")
    report = tmp_path / "report.json"
    results, ok, context, feedback = run_alg(
        "clearfast:validatesurvey", {"SURVEY": str(survey), "REPORT": str(report)})
    assert ok, feedback.textLog()
    assert results["VALID"] is True and report.is_file()
    markers = layers_to_load(context)["Survey markers"]
    assert markers.isValid() and markers.featureCount() == 2


def test_validate_survey_reports_invalid(qgis_app, fake_toolkit, tmp_path, monkeypatch):
    monkeypatch.setenv("FAKE_CLEARFAST_FAIL", "1")
    results, ok, _, feedback = run_alg("clearfast:validatesurvey", {"SURVEY": str(tmp_path)})
    assert ok and results["VALID"] is False
    assert "camera.resolution: expected 2 integers" in feedback.textLog()


def test_validate_survey_takes_a_station_profile(qgis_app, real_toolkit, tmp_path):
    from tests.survey.test_station_profile_cli import PROFILE, station_survey

    survey = station_survey(tmp_path / "s")
    results, ok, _, feedback = run_alg("clearfast:validatesurvey", {"SURVEY": str(survey)})
    assert ok and results["VALID"] is False
    assert "weather.dat: line 2: missing air temperature" in feedback.textLog()
    profile = tmp_path / "station.json"
    profile.write_text(json.dumps(PROFILE))
    results, ok, _, feedback = run_alg("clearfast:validatesurvey", {
        "SURVEY": str(survey), "STATION_PROFILE": str(profile)})
    assert ok and results["VALID"] is True, feedback.textLog()


def test_validate_survey_real_toolkit_lists_problems(qgis_app, real_toolkit, tmp_path):
    report = tmp_path / "report.json"
    results, ok, _, feedback = run_alg(
        "clearfast:validatesurvey", {"SURVEY": str(tmp_path), "REPORT": str(report)})
    assert ok and results["VALID"] is False and results["PROBLEMS"] >= 1
    doc = json.loads(report.read_text())
    assert doc["valid"] is False
    assert doc["problems"][0]["line"] in feedback.textLog()
    assert "survey.json" in doc["problems"][0]["line"]


def test_progress_lines_drive_feedback(qgis_app, fake_toolkit, monkeypatch, products, tmp_path):
    monkeypatch.setenv("FAKE_CLEARFAST_STEPS", "10")
    feedback = RecordingFeedback()
    results, ok, _, _ = run_alg("clearfast:rerundetection", {
        "PRODUCTS": str(products.root), "D1": 0.5, "D2": 0.05, "EPSILON": 0.01}, feedback)
    assert ok
    steps = [v for v in feedback.values if 0 < v < 100]
    assert steps == pytest.approx([10.0 * k for k in range(1, 10)])
    assert feedback.values[-1] == pytest.approx(100.0)
    assert "fake" in feedback.texts
    assert "half-way note" in feedback.infos
    assert "fake clearfast starting" in feedback.console  # plain lines go to the log


def test_failure_raises_with_one_line_error(qgis_app, fake_toolkit, monkeypatch, products):
    monkeypatch.setenv("FAKE_CLEARFAST_FAIL", "1")
    results, ok, _, feedback = run_alg("clearfast:rerundetection", {
        "PRODUCTS": str(products.root), "D1": 0.5, "D2": 0.05, "EPSILON": 0.01})
    assert not ok
    assert "clearfast failed: clearfast: error: survey.json: camera.resolution: expected 2 " \
           "integers" in feedback.textLog()


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    # a zombie awaiting its parent counts as ended
    try:
        with open(f"/proc/{pid}/stat") as fh:
            return fh.read().split()[2] != "Z"
    except FileNotFoundError:
        return False


def test_cancel_stops_the_run(qgis_app, fake_toolkit, monkeypatch, products, tmp_path):
    pid_file = tmp_path / "pid"
    monkeypatch.setenv("FAKE_CLEARFAST_PID_FILE", str(pid_file))
    monkeypatch.setenv("FAKE_CLEARFAST_STEPS", "300")
    monkeypatch.setenv("FAKE_CLEARFAST_STEP_S", "0.1")  # 30 s if not cancelled
    feedback = RecordingFeedback()
    timer = threading.Timer(1.5, feedback.cancel)
    timer.start()
    t0 = time.monotonic()
    results, ok, _, _ = run_alg("clearfast:rerundetection", {
        "PRODUCTS": str(products.root), "D1": 0.5, "D2": 0.05, "EPSILON": 0.01}, feedback)
    elapsed = time.monotonic() - t0
    assert not ok and "cancelled by the user" in feedback.textLog()
    assert elapsed < 8.0
    assert 0 < max(feedback.values) < 100
    assert not _alive(int(pid_file.read_text()))


def test_missing_toolkit_says_how_to_install(qgis_app, monkeypatch, tmp_path):
    from clearfast import toolkit
    from qgis.core import QgsApplication

    monkeypatch.setenv("CLEARFAST_COMMAND", str(tmp_path / "no-such-clearfast"))
    alg = QgsApplication.processingRegistry().createAlgorithmById("clearfast:validatesurvey")
    ok, message = alg.canExecute()
    assert not ok and "pip install clearfast-gis" in message
    results, ok, _, feedback = run_alg("clearfast:validatesurvey", {"SURVEY": str(tmp_path)})
    assert not ok and "pip install clearfast-gis" in feedback.textLog()
    # nothing configured, nothing on PATH, not importable
    monkeypatch.delenv("CLEARFAST_COMMAND")
    monkeypatch.setenv("PATH", str(tmp_path))
    monkeypatch.setattr(toolkit.importlib.util, "find_spec", lambda name: None)
    with pytest.raises(toolkit.ToolkitMissing, match="CLEARFAST_COMMAND"):
        toolkit.toolkit_command()


def test_toolkit_command_fallbacks(qgis_app, monkeypatch, tmp_path):
    from clearfast import toolkit

    monkeypatch.delenv("CLEARFAST_COMMAND", raising=False)
    exe = tmp_path / "clearfast"
    exe.write_text("#!/bin/sh\n")
    exe.chmod(0o755)
    monkeypatch.setenv("PATH", str(tmp_path))
    assert toolkit.toolkit_command() == [str(exe)]
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    cmd = toolkit.toolkit_command()  # this checkout's toolkit is importable here
    assert cmd[1:] == ["-m", "clearfast_gis.cli.main"]


def test_detection_defaults_are_the_toolkits(qgis_app, real_toolkit):
    """The plugin shows the toolkit's own defaults (``clearfast options --json``), the same
    ones ``clearfast detect`` uses: changing a default in ProcessOptions changes both."""
    from qgis.core import QgsApplication

    from clearfast_gis.pipeline.options import ProcessOptions

    defaults = ProcessOptions()
    alg = QgsApplication.processingRegistry().createAlgorithmById("clearfast:rerundetection")
    shown = {name: alg.parameterDefinition(name).defaultValue()
             for name in ("D1", "D2", "EPSILON", "LEVEL", "GAMMA")}
    assert shown == {"D1": defaults.d1_m, "D2": defaults.d2_m, "EPSILON": defaults.epsilon,
                     "LEVEL": defaults.level, "GAMMA": defaults.gamma}
    assert f"{defaults.level_fraction:g} of the images" in alg.shortHelpString()


def test_defaults_unknown_without_a_toolkit(qgis_app, fake_toolkit):
    """A command that does not answer ``options --json`` gives no defaults, not made-up ones."""
    from clearfast.toolkit import toolkit_defaults

    assert toolkit_defaults() == {}


def test_progress_text_names_the_chains_stage_and_step(qgis_app):
    """The toolkit's own JSON lines of a chain stage (``clearfast_gis.progress``) show in the
    Processing dialog as the stage's name and label, then ``stage / step``."""
    import io

    from clearfast import toolkit

    from clearfast_gis.progress import Progress

    out = io.StringIO()
    p = Progress("json", stream=out)
    with p.chain_stage("attitude_adjustment", "survey-wide attitude adjustment"):
        p.start("refined attitude adjustment", 4)
        p.advance(2)
    feedback, events = RecordingFeedback(), []
    for line in out.getvalue().splitlines():
        toolkit.handle_line(line, feedback, events)
    assert feedback.texts == ["attitude_adjustment: survey-wide attitude adjustment",
                              "attitude_adjustment / refined attitude adjustment"]
    assert "attitude_adjustment / refined attitude adjustment: 4 steps" in feedback.infos
    assert feedback.values[-1] == 50.0
