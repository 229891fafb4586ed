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
        for text, name, tip, slot, toolbar in (
                ("Open survey products…", "clearfastOpenProducts",
                 "Open a CLEARFAST products folder: mosaics, suspects, markers",
                 self.open_products, True),
                ("Export field map (PDF)…", "clearfastFieldMap",
                 "A one-page field map of a products folder, as PDF", self.export_field_map,
                 False)):
            action = QAction(QIcon(ICON_PATH), text, self.iface.mainWindow())
            action.setObjectName(name)
            action.setToolTip(tip)
            action.triggered.connect(slot)
            self.iface.addPluginToMenu(MENU, action)
            if toolbar:
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

    def export_field_map(self):
        """Ask for a products folder and a PDF name, and write the field map."""
        from .fieldmap import export_field_map

        window = self.iface.mainWindow()
        folder = QFileDialog.getExistingDirectory(window, "Field map of CLEARFAST products")
        if not folder:
            return
        pdf, _ = QFileDialog.getSaveFileName(
            window, "Save the field map", os.path.join(folder, "field_map.pdf"),
            "PDF files (*.pdf)")
        if not pdf:
            return
        try:
            export_field_map(folder, pdf)
        except (ProductsError, OSError) as exc:
            self.iface.messageBar().pushCritical("CLEARFAST", str(exc))
            return
        self.iface.messageBar().pushSuccess("CLEARFAST", f"Field map written: {pdf}")
