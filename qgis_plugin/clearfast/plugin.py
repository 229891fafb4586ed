"""The plugin object: a menu/toolbar action to open products and the Processing provider."""

from __future__ import annotations

import os

from qgis.core import QgsApplication, QgsProject
from qgis.PyQt.QtGui import QIcon
from qgis.PyQt.QtWidgets import QAction, QFileDialog

from .loader import ProductsError, load_products
from .provider import ClearfastProvider

MENU = "&CLEARFAST"
ICON_PATH = os.path.join(os.path.dirname(__file__), "icons", "clearfast.svg")


class ClearfastPlugin:
    """Registers the Processing provider and, with a GUI, the "Open survey products" action."""

    def __init__(self, iface=None):
        self.iface = iface
        self.provider = None
        self.actions: list[QAction] = []

    def initProcessing(self):
        if self.provider is None:
            self.provider = ClearfastProvider()
            QgsApplication.processingRegistry().addProvider(self.provider)

    def initGui(self):
        self.initProcessing()
        if self.iface is None:
            return
        action = QAction(QIcon(ICON_PATH), "Open survey products…", self.iface.mainWindow())
        action.setObjectName("clearfastOpenProducts")
        action.setToolTip("Open a CLEARFAST products folder: mosaics, suspects, markers")
        action.triggered.connect(self.open_products)
        self.iface.addPluginToMenu(MENU, action)
        self.iface.addToolBarIcon(action)
        self.actions.append(action)

    def unload(self):
        for action in self.actions:
            if self.iface is not None:
                self.iface.removePluginMenu(MENU, action)
                self.iface.removeToolBarIcon(action)
            action.deleteLater()
        self.actions = []
        if self.provider is not None:
            QgsApplication.processingRegistry().removeProvider(self.provider)
            self.provider = None

    def open_products(self):
        """Ask for a products folder and load it into the current project."""
        folder = QFileDialog.getExistingDirectory(
            self.iface.mainWindow(), "Open CLEARFAST survey products")
        if not folder:
            return
        try:
            load_products(folder, QgsProject.instance(), self.iface.mapCanvas())
        except ProductsError as exc:
            self.iface.messageBar().pushCritical("CLEARFAST", str(exc))
