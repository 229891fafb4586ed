"""The Processing provider "CLEARFAST"."""

from __future__ import annotations

import os

from qgis.core import QgsProcessingProvider
from qgis.PyQt.QtGui import QIcon

from .algorithms import (
    ExportMineActionAlgorithm,
    FieldMapAlgorithm,
    ProcessSurveyAlgorithm,
    RerunDetectionAlgorithm,
    ValidateSurveyAlgorithm,
)

ICON_PATH = os.path.join(os.path.dirname(__file__), "icons", "clearfast.svg")


class ClearfastProvider(QgsProcessingProvider):
    """Algorithms that run the clearfast toolkit (``clearfast:<name>`` in qgis_process)."""

    def id(self):
        return "clearfast"

    def name(self):
        return "CLEARFAST"

    def longName(self):
        return "CLEARFAST stand-off thermal-IR minefield survey"

    def icon(self):
        return QIcon(ICON_PATH)

    def svgIconPath(self):
        return ICON_PATH

    def loadAlgorithms(self):
        for cls in (ProcessSurveyAlgorithm, RerunDetectionAlgorithm, ExportMineActionAlgorithm,
                    ValidateSurveyAlgorithm, FieldMapAlgorithm):
            self.addAlgorithm(cls())
