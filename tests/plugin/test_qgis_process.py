"""The plugin's provider under ``qgis_process`` (headless), from a temporary QGIS profile."""

from __future__ import annotations

import json
import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.qgis

REPO = Path(__file__).resolve().parents[2]
FAKE = Path(__file__).resolve().parent / "fake_clearfast.py"


def qgis_process_exe() -> str:
    """``qgis_process``; Debian's wrapper passes --noversioncheck from /etc/default/qgis, which
    qgis_process 3.22 rejects, so prefer the real binary beside it."""
    exe = shutil.which("qgis_process")
    assert exe, "qgis_process not on PATH (install Debian's qgis package)"
    binary = exe + ".bin"
    return binary if os.access(binary, os.X_OK) else exe


def run_qgis_process(args, env, timeout=240):
    return subprocess.run([qgis_process_exe(), *args], env=env, capture_output=True, text=True,
                          timeout=timeout)


@pytest.fixture(scope="module")
def qgis_env(tmp_path_factory):
    """A temporary QGIS profile with the plugin installed from the zip the script builds."""
    import zipfile

    home = tmp_path_factory.mktemp("qgis-profile")
    plugins = home / "plugins"
    build = subprocess.run([str(REPO / "scripts" / "build_plugin_zip.sh"), str(home / "dist")],
                           capture_output=True, text=True, check=True, timeout=60)
    zipfile.ZipFile(build.stdout.strip()).extractall(plugins)
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", XDG_DATA_HOME=str(home),
               QGIS_PLUGINPATH=str(plugins),
               CLEARFAST_COMMAND=shlex.join([sys.executable, str(FAKE)]))
    r = run_qgis_process(["plugins", "enable", "clearfast"], env)
    assert r.returncode == 0, r.stdout + r.stderr
    return env


def test_qgis_process_runs_validate(qgis_env, tmp_path):
    survey = tmp_path / "survey"
    survey.mkdir()
    report = tmp_path / "report.json"
    r = run_qgis_process(["--json", "run", "clearfast:validatesurvey", "--",
                          f"SURVEY={survey}", f"REPORT={report}"], qgis_env)
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout[r.stdout.index("{"):])
    assert doc["results"]["VALID"] is True
    assert report.is_file()


def test_qgis_process_export_with_real_toolkit(qgis_env, products, tmp_path):
    env = dict(qgis_env, CLEARFAST_COMMAND=shlex.join(
        [sys.executable, "-m", "clearfast_gis.cli.main"]), PYTHONPATH=str(REPO))
    out = tmp_path / "ma"
    r = run_qgis_process(["--json", "run", "clearfast:exportmineaction", "--",
                          f"PRODUCTS={products.root}", f"OUTPUT={out}"], env)
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout[r.stdout.index("{"):])
    assert doc["results"]["COUNT"] == 4  # the AT/AP mine indications
    assert (out / "mine_action.csv").is_file() and (out / "hazard_proposals.csv").is_file()


def test_qgis_process_field_map(qgis_env, products, tmp_path):
    pdf = tmp_path / "field_map.pdf"
    r = run_qgis_process(["--json", "run", "clearfast:fieldmap", "--",
                          f"PRODUCTS={products.root}", f"OUTPUT={pdf}"], qgis_env)
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout[r.stdout.index("{"):])
    assert doc["results"]["OUTPUT"] == str(pdf)
    info = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True, check=True)
    assert "Pages:           1" in info.stdout
