"""Georeferenced mosaics (paper §5): ground projection, co-registration, insertion, seams.

The functions here work on arrays; :mod:`clearfast_gis.pipeline` feeds them frames from a survey
and writes the results with :mod:`clearfast_gis.export`. The mosaic stage's worker
(:mod:`.scanjob`) builds the scans in order and writes them; it is imported on its own.
"""

from clearfast_gis.mosaic.build import FrameInput, ScanMosaic, build_scan_mosaic
from clearfast_gis.mosaic.grid import mosaic_grid
from clearfast_gis.mosaic.insert import MosaicCanvas
from clearfast_gis.mosaic.project import ProjectedFrame, project_frame
from clearfast_gis.mosaic.seams import fit_linear_histogram_mapping
from clearfast_gis.mosaic.temporal import TemporalResidual, temporal_residual, temporal_transform

__all__ = [
    "FrameInput",
    "MosaicCanvas",
    "ProjectedFrame",
    "ScanMosaic",
    "TemporalResidual",
    "build_scan_mosaic",
    "fit_linear_histogram_mapping",
    "mosaic_grid",
    "project_frame",
    "temporal_residual",
    "temporal_transform",
]
