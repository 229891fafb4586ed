"""QGIS set-up for the plugin tests: one headless QgsApplication per test process.

The products fixture is built by the toolkit's own writers
(:func:`clearfast_gis.export.testing.make_demo_products`).
"""

from __future__ import annotations

import os
import shlex
import sys
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

import pytest

REPO = Path(__file__).resolve().parents[2]
PLUGIN_DIR = REPO / "qgis_plugin"
FAKE = Path(__file__).resolve().parent / "fake_clearfast.py"


@pytest.fixture(scope="session")
def qgis_app():
    """The QGIS application with Processing initialised and the CLEARFAST provider."""
    from qgis.core import QgsApplication

    app = QgsApplication.instance()
    if app is None:
        QgsApplication.setPrefixPath("/usr", True)
        app = QgsApplication([], False)
        app.initQgis()
    sys.path.insert(0, "/usr/share/qgis/python/plugins")
    sys.path.insert(0, str(PLUGIN_DIR))
    from processing.core.Processing import Processing

    Processing.initialize()
    import clearfast

    plugin = clearfast.classFactory(None)
    plugin.initProcessing()
    app.clearfast_plugin = plugin
    yield app
    plugin.unload()


@pytest.fixture()
def project(qgis_app):
    """An empty QGIS project of its own, cleared afterwards."""
    from qgis.core import QgsProject

    proj = QgsProject()
    yield proj
    proj.clear()


@pytest.fixture()
def session_plugin(qgis_app):
    """The plugin object registered for the session (``classFactory(None)``)."""
    return qgis_app.clearfast_plugin


@pytest.fixture(scope="session")
def products(tmp_path_factory):
    """A small products folder: 4 scan mosaics, 8 suspects, markers, footprint (EPSG:32636)."""
    from clearfast_gis.export.testing import make_demo_products

    return make_demo_products(tmp_path_factory.mktemp("products"))


@pytest.fixture()
def fake_toolkit(monkeypatch):
    """Point the plugin at the fake toolkit script (CLEARFAST_COMMAND)."""
    monkeypatch.setenv("CLEARFAST_COMMAND", shlex.join([sys.executable, str(FAKE)]))
    return FAKE


@pytest.fixture()
def real_toolkit(monkeypatch):
    """Point the plugin at this checkout's toolkit (``python -m clearfast_gis.cli.main``)."""
    monkeypatch.setenv("CLEARFAST_COMMAND",
                       shlex.join([sys.executable, "-m", "clearfast_gis.cli.main"]))
    monkeypatch.setenv("PYTHONPATH", str(REPO))
