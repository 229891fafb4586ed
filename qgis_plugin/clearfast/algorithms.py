"""Processing algorithms that call the clearfast toolkit's command line.

Each algorithm runs ``clearfast <subcommand> ... --progress json`` as a child process (an
argument list, never a shell string), streams its progress into the feedback, stops it when the
user cancels and returns the products as layers (loaded into the project on completion).
"""

from __future__ import annotations

import glob
import json
import os

from qgis.core import (
    QgsProcessing,
    QgsProcessingAlgorithm,
    QgsProcessingContext,
    QgsProcessingException,
    QgsProcessingOutputBoolean,
    QgsProcessingOutputFile,
    QgsProcessingOutputFolder,
    QgsProcessingOutputMultipleLayers,
    QgsProcessingOutputNumber,
    QgsProcessingOutputVectorLayer,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterFolderDestination,
    QgsProcessingParameterNumber,
    QgsRasterLayer,
    QgsVectorLayer,
)
from qgis.PyQt.QtGui import QIcon

from .toolkit import (
    ToolkitCancelled,
    ToolkitMissing,
    error_line,
    run_toolkit,
    toolkit_available,
    toolkit_defaults,
)

ICON_PATH = os.path.join(os.path.dirname(__file__), "icons", "clearfast.svg")
PRODUCT_LAYERS = (("suspects", "Suspects"), ("anomalies", "Anomaly outlines"),
                  ("markers", "Markers"), ("footprint", "Footprint"))


def gpkg_uri(gpkg: str, layer: str) -> str:
    """OGR data source URI of one GeoPackage layer."""
    return f"{gpkg}|layername={layer}"


class ClearfastAlgorithm(QgsProcessingAlgorithm):
    """Name, title, help, group and icon of the provider's algorithms."""

    NAME = ""
    TITLE = ""
    HELP = ""

    def name(self):
        return self.NAME

    def displayName(self):
        return self.TITLE

    def group(self):
        return "Survey processing"

    def groupId(self):
        return "survey"

    def icon(self):
        return QIcon(ICON_PATH)

    def shortHelpString(self):
        return self.HELP

    def createInstance(self):
        return type(self)()


class ToolkitAlgorithm(ClearfastAlgorithm):
    """Shared behaviour: toolkit check, run with progress and cancellation, layer outputs."""

    def shortHelpString(self):
        return self.HELP + "\n\nRuns the clearfast toolkit's command line (`clearfast`)."

    def canExecute(self):
        return toolkit_available()

    def run_cli(self, args, feedback):
        """Run ``clearfast ARGS``; raise QgsProcessingException on failure or cancellation."""
        try:
            result = run_toolkit(args, feedback)
        except ToolkitMissing as exc:
            raise QgsProcessingException(str(exc)) from None
        except ToolkitCancelled as exc:
            raise QgsProcessingException(str(exc)) from None
        return result

    def check(self, result):
        if result.returncode != 0:
            raise QgsProcessingException(f"clearfast failed: {error_line(result)}")
        return result

    @staticmethod
    def load_on_completion(context, uri: str, name: str, provider: str = "ogr") -> bool:
        """Check ``uri`` opens as a valid layer and add it to the layers loaded at the end."""
        layer = (QgsVectorLayer(uri, name, provider) if provider in ("ogr", "delimitedtext")
                 else QgsRasterLayer(uri, name, provider))
        if not layer.isValid():
            return False
        context.temporaryLayerStore().addMapLayer(layer)
        details = QgsProcessingContext.LayerDetails(name, context.project(), name)
        context.addLayerToLoadOnCompletion(layer.id(), details)
        return True

    def product_layers(self, folder, context, feedback) -> dict:
        """Outputs for a products folder: one URI per GeoPackage layer and the mosaics."""
        outputs = {"PRODUCTS": folder}
        gpkg = os.path.join(folder, "anomalies.gpkg")
        for name, title in PRODUCT_LAYERS:
            uri = gpkg_uri(gpkg, name)
            if os.path.isfile(gpkg) and self.load_on_completion(context, uri, title):
                outputs[name.upper()] = uri
            else:
                feedback.reportError(f"{gpkg}: no {name} layer", False)
        mosaics = sorted(glob.glob(os.path.join(folder, "mosaics", "scan_*.tif")))
        outputs["MOSAICS"] = [p for p in mosaics if self.load_on_completion(
            context, p, os.path.splitext(os.path.basename(p))[0], "gdal")]
        return outputs

    def add_product_outputs(self):
        self.addOutput(QgsProcessingOutputFolder("PRODUCTS", "Products folder"))
        for name, title in PRODUCT_LAYERS:
            self.addOutput(QgsProcessingOutputVectorLayer(name.upper(), title))
        self.addOutput(QgsProcessingOutputMultipleLayers("MOSAICS", "Scan mosaics"))


class ProcessSurveyAlgorithm(ToolkitAlgorithm):
    NAME = "processsurvey"
    TITLE = "Process survey"
    HELP = ("Run the whole chain on a survey folder: calibration, mosaics, anomaly detection, "
            "depth and diffusivity estimation. Writes a products folder and loads its layers.")

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(
            "SURVEY", "Survey folder", behavior=QgsProcessingParameterFile.Folder))
        self.addParameter(QgsProcessingParameterFolderDestination("OUTPUT", "Products folder"))
        self.add_product_outputs()

    def processAlgorithm(self, parameters, context, feedback):
        survey = self.parameterAsFile(parameters, "SURVEY", context)
        out = self.parameterAsString(parameters, "OUTPUT", context)
        self.check(self.run_cli(["process", survey, "-o", out, "--progress", "json"], feedback))
        return {"OUTPUT": out, **self.product_layers(out, context, feedback)}


class RerunDetectionAlgorithm(ToolkitAlgorithm):
    NAME = "rerundetection"
    TITLE = "Re-run detection with new parameters"
    HELP = ("Re-run anomaly detection on the mosaics of an existing products folder. D1: disc "
            "diameter of the top-hat (larger than the largest expected mine), D2: disc diameter "
            "of the binary opening (D2 < D1), epsilon: tail fraction of the contrast thresholds, "
            "l: number of images (scans x bands) a blob must appear in (empty = the toolkit's "
            "default: {level} of the images covering each pixel), gamma: occurrence threshold of "
            "the combined hot/cold maps (empty = {gamma} of the images covering each pixel). "
            "The defaults shown are the toolkit's (`clearfast options`).")

    def shortHelpString(self):
        defaults = toolkit_defaults()

        def share(key):
            value = defaults.get(key)
            return "the toolkit's share" if value is None else f"{value:g}"

        return super().shortHelpString().format(level=share("level_fraction"),
                                                gamma=share("gamma_fraction"))

    def initAlgorithm(self, config=None):
        defaults = toolkit_defaults()
        self.addParameter(QgsProcessingParameterFile(
            "PRODUCTS", "Products folder", behavior=QgsProcessingParameterFile.Folder))
        self.addParameter(QgsProcessingParameterNumber(
            "D1", "D1: top-hat disc diameter (m)", QgsProcessingParameterNumber.Double,
            defaults.get("d1_m"), minValue=0.01))
        self.addParameter(QgsProcessingParameterNumber(
            "D2", "D2: opening disc diameter (m)", QgsProcessingParameterNumber.Double,
            defaults.get("d2_m"), minValue=0.0))
        self.addParameter(QgsProcessingParameterNumber(
            "EPSILON", "epsilon: threshold tail fraction", QgsProcessingParameterNumber.Double,
            defaults.get("epsilon"), minValue=0.0, maxValue=0.5))
        self.addParameter(QgsProcessingParameterNumber(
            "LEVEL", "l: voting level (images)", QgsProcessingParameterNumber.Integer,
            None, optional=True, minValue=1))
        self.addParameter(QgsProcessingParameterNumber(
            "GAMMA", "gamma: occurrence threshold", QgsProcessingParameterNumber.Double,
            None, optional=True, minValue=0.0))
        self.add_product_outputs()

    def checkParameterValues(self, parameters, context):
        ok, message = super().checkParameterValues(parameters, context)
        if ok:
            d1 = self.parameterAsDouble(parameters, "D1", context)
            d2 = self.parameterAsDouble(parameters, "D2", context)
            if not d2 < d1:
                return False, "D2 must be smaller than D1 (otherwise every object is removed)"
        return ok, message

    def processAlgorithm(self, parameters, context, feedback):
        folder = self.parameterAsFile(parameters, "PRODUCTS", context)
        args = ["detect", folder,
                "--d1", repr(self.parameterAsDouble(parameters, "D1", context)),
                "--d2", repr(self.parameterAsDouble(parameters, "D2", context)),
                "--epsilon", repr(self.parameterAsDouble(parameters, "EPSILON", context))]
        if parameters.get("LEVEL") not in (None, ""):
            args += ["--level", str(self.parameterAsInt(parameters, "LEVEL", context))]
        if parameters.get("GAMMA") not in (None, ""):
            args += ["--gamma", repr(self.parameterAsDouble(parameters, "GAMMA", context))]
        self.check(self.run_cli([*args, "--progress", "json"], feedback))
        return self.product_layers(folder, context, feedback)


class ExportMineActionAlgorithm(ToolkitAlgorithm):
    NAME = "exportmineaction"
    TITLE = "Export for a mine action centre"
    HELP = ("Write what IMSMA Core imports without editing (WGS84 GeoPackage and CSV tables, "
            "field names of at most 31 characters, imsma_id and imsma_links): the surveyed "
            "area, suspected-hazard polygon proposals around clusters of mine indications, and "
            "the evidence points (suspects from the stated mine likelihood, or all) linked to "
            "them. The evidence is indirect: proposals are to review, never confirmed hazards. "
            "The organisation defaults to the QGIS setting clearfast/organisation.")

    def initAlgorithm(self, config=None):
        from qgis.core import (
            QgsProcessingParameterBoolean,
            QgsProcessingParameterString,
            QgsSettings,
        )

        self.addParameter(QgsProcessingParameterFile(
            "PRODUCTS", "Products folder", behavior=QgsProcessingParameterFile.Folder))
        self.addParameter(QgsProcessingParameterNumber(
            "MIN_LIKELIHOOD", "Mine likelihood from which a suspect is evidence (0-1)",
            QgsProcessingParameterNumber.Double, 0.5, False, 0.0, 1.0))
        self.addParameter(QgsProcessingParameterBoolean(
            "ALL_SUSPECTS", "Export every suspect as evidence", False))
        self.addParameter(QgsProcessingParameterNumber(
            "HAZARD_BUFFER", "Hazard polygon radius around each mine indication (m)",
            QgsProcessingParameterNumber.Double, 5.0, False, 0.1, 1000.0))
        self.addParameter(QgsProcessingParameterString(
            "ORGANISATION", "Surveying organisation",
            str(QgsSettings().value("clearfast/organisation", "")), optional=True))
        self.addParameter(QgsProcessingParameterFolderDestination("OUTPUT", "Output folder"))
        self.addOutput(QgsProcessingOutputVectorLayer(
            "INDICATIONS", "Mine action indications", QgsProcessing.TypeVectorPoint))
        self.addOutput(QgsProcessingOutputVectorLayer(
            "HAZARDS", "Hazard polygon proposals", QgsProcessing.TypeVectorPolygon))
        self.addOutput(QgsProcessingOutputVectorLayer(
            "SURVEYED_AREA", "Surveyed area", QgsProcessing.TypeVectorPolygon))
        self.addOutput(QgsProcessingOutputFile("CSV", "Mine action CSV"))
        self.addOutput(QgsProcessingOutputNumber("COUNT", "Number of indications"))

    def processAlgorithm(self, parameters, context, feedback):
        folder = self.parameterAsFile(parameters, "PRODUCTS", context)
        out = self.parameterAsString(parameters, "OUTPUT", context)
        args = ["export", folder, "--mine-action", "-o", out,
                "--min-likelihood",
                repr(self.parameterAsDouble(parameters, "MIN_LIKELIHOOD", context)),
                "--hazard-buffer",
                repr(self.parameterAsDouble(parameters, "HAZARD_BUFFER", context))]
        if self.parameterAsBool(parameters, "ALL_SUSPECTS", context):
            args.append("--all-suspects")
        organisation = self.parameterAsString(parameters, "ORGANISATION", context)
        if organisation:
            args += ["--organisation", organisation]
        result = self.check(self.run_cli([*args, "--progress", "json"], feedback))
        gpkg = os.path.join(out, "mine_action.gpkg")
        outputs = {"OUTPUT": out, "CSV": os.path.join(out, "mine_action.csv")}
        for key, layer, title in (("SURVEYED_AREA", "surveyed_area", "Surveyed area"),
                                  ("HAZARDS", "hazard_proposals", "Hazard polygon proposals"),
                                  ("INDICATIONS", "indications", "Mine action indications")):
            uri = gpkg_uri(gpkg, layer)
            if not self.load_on_completion(context, uri, title):
                raise QgsProcessingException(f"{gpkg}: the export wrote no {layer} layer")
            outputs[key] = uri
        outputs["COUNT"] = next(
            (e.get("count") for e in result.events if e.get("event") == "result"), None)
        return outputs


class ValidateSurveyAlgorithm(ToolkitAlgorithm):
    NAME = "validatesurvey"
    TITLE = "Validate survey"
    HELP = ("Check a survey folder completely (manifest, frames, logs, markers) and report every "
            "problem. Writes the toolkit's JSON report when an output file is given. A station "
            "profile (JSON) maps a real weather station's or soil logger's columns and units "
            "(default: the one survey.json names).")

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(
            "SURVEY", "Survey folder", behavior=QgsProcessingParameterFile.Folder))
        self.addParameter(QgsProcessingParameterFile(
            "STATION_PROFILE", "Station profile (JSON)", extension="json", optional=True))
        self.addParameter(QgsProcessingParameterFileDestination(
            "REPORT", "Validation report (JSON)", "JSON files (*.json)", optional=True))
        self.addOutput(QgsProcessingOutputBoolean("VALID", "Survey is valid"))
        self.addOutput(QgsProcessingOutputNumber("PROBLEMS", "Number of problems"))
        self.addOutput(QgsProcessingOutputVectorLayer(
            "MARKERS", "Survey markers", QgsProcessing.TypeVectorPoint))

    def processAlgorithm(self, parameters, context, feedback):
        survey = self.parameterAsFile(parameters, "SURVEY", context)
        report = self.parameterAsFileOutput(parameters, "REPORT", context)
        profile = self.parameterAsFile(parameters, "STATION_PROFILE", context)
        args = ["validate", survey, "--json"]
        if profile:
            args += ["--station-profile", profile]
        result = self.run_cli(args, feedback)
        if result.returncode not in (0, 1):
            raise QgsProcessingException(f"clearfast failed: {error_line(result)}")
        valid = result.returncode == 0
        text = result.stdout.strip()
        try:
            doc = json.loads(text) if text else {}
        except ValueError:
            doc = {}
        problems = [p for p in doc.get("problems", []) if isinstance(p, dict)]
        for item in doc.get("warnings", []):
            if isinstance(item, dict):
                feedback.pushInfo(f"warning: {item.get('line', item.get('message', ''))}")
        for item in problems:
            feedback.reportError(str(item.get("line", item.get("message", ""))), False)
        if not valid and not problems:
            feedback.reportError(f"survey is not valid: {error_line(result)}", False)
        if report:
            with open(report, "w", encoding="utf-8") as fh:
                fh.write((json.dumps(doc, indent=2) if doc else text) + "\n")
        outputs = {"VALID": valid, "REPORT": report or None, "PROBLEMS": len(problems)}
        markers = os.path.join(survey, "markers.csv")
        if os.path.isfile(markers):
            uri = ("file://" + markers.replace(os.sep, "/") +
                   "?type=csv&xField=lon_deg&yField=lat_deg&crs=EPSG:4326&detectTypes=yes")
            if self.load_on_completion(context, uri, "Survey markers", "delimitedtext"):
                outputs["MARKERS"] = uri
        return outputs


class FieldMapAlgorithm(ClearfastAlgorithm):
    """The one-page field map (PDF) of a products folder; needs only QGIS, not the toolkit."""

    NAME = "fieldmap"
    TITLE = "Field map (PDF)"
    HELP = ("An A4 field map of a products folder as PDF: the footprint over the scan with the "
            "best contrast, suspects (mine indications labelled) and markers, UTM grid and "
            "WGS84 ticks, scale bar, north arrow, legend, a title block (survey, dates, CRS, "
            "method, the indirect-evidence disclaimer) and the table of mine indications with "
            "their coordinates. Runs in QGIS; the current project is not changed.")

    def flags(self):
        # layouts and map rendering belong on the main thread
        return super().flags() | QgsProcessingAlgorithm.FlagNoThreading

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(
            "PRODUCTS", "Products folder", behavior=QgsProcessingParameterFile.Folder))
        self.addParameter(QgsProcessingParameterFileDestination(
            "OUTPUT", "Field map", "PDF files (*.pdf)"))

    def processAlgorithm(self, parameters, context, feedback):
        from .fieldmap import export_field_map
        from .loader import ProductsError

        folder = self.parameterAsFile(parameters, "PRODUCTS", context)
        pdf = self.parameterAsFileOutput(parameters, "OUTPUT", context)
        try:
            export_field_map(folder, pdf)
        except (ProductsError, OSError) as exc:
            raise QgsProcessingException(str(exc)) from None
        feedback.pushInfo(f"field map: {pdf}")
        return {"OUTPUT": pdf}
