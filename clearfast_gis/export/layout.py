"""Where a processing run keeps each scan's files inside a products folder (the one
definition of that layout: the run state, the mosaic worker, the readers and the evaluation all
use it)."""

from __future__ import annotations

STATE_DIR = ".clearfast"
"""Folder of the run state (and the scans' source maps) inside a products folder."""

DECODED_REL = f"{STATE_DIR}/decoded"
"""Scratch folder of a run inside a products folder: the scan mosaics decoded once from their
COGs for the passes of the detector and the stages after it (raw float32, deleted when the
run ends; see :class:`clearfast_gis.export.cog.CogStack`)."""


def mosaic_name(scan: int) -> str:
    """File name of scan ``scan``'s mosaic inside ``mosaics/``: ``scan_007.tif``."""
    if scan < 0:
        raise ValueError("scan index must be >= 0")
    return f"scan_{scan:03d}.tif"


def mosaic_rel(scan: int) -> str:
    """Relative path of a scan's mosaic in the products folder.

    >>> mosaic_rel(7)
    'mosaics/scan_007.tif'
    """
    return f"mosaics/{mosaic_name(scan)}"


def source_rel(scan: int) -> str:
    """Relative path of a scan's source map (scan-pattern position seen in each cell)."""
    return f"{STATE_DIR}/source_{scan:03d}.npy"
