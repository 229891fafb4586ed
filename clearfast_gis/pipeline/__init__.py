"""The processing chain, survey folder to products folder, with progress and resume.

``process_survey`` runs the stages of ARCHITECTURE §2 in order; each finished stage is recorded
in ``PRODUCTS/.clearfast/state.json`` so an interrupted run continues where it stopped.
The chain's modules are imported on first use, so that :mod:`.options` (the defaults the
command line and the QGIS plugin show) stays light to import.

The package only orchestrates: :mod:`.stages` (the stages and their records), :mod:`.run` (the
loop), :mod:`.state` (run state and resume), :mod:`.options` (the defaults), :mod:`.inputs`
(what is read from a survey folder), :mod:`.scanjob` (the band and mosaic stages' run-state
units; the worker and the scan order are :mod:`clearfast_gis.mosaic.scanjob`),
:mod:`.adjustment` and :mod:`.anomalies` (the attitude-adjustment and anomaly stages).
The algorithms they call live in their domains (``attitude``, ``mosaic``, ``detection``,
``thermal``, ``export``, ...; README "The chain").
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from clearfast_gis.pipeline.options import ProcessOptions

if TYPE_CHECKING:
    from clearfast_gis.pipeline.run import process_survey, redetect

__all__ = ["ProcessOptions", "process_survey", "redetect"]


def __getattr__(name: str):
    if name in ("process_survey", "redetect"):
        from clearfast_gis.pipeline import run

        return getattr(run, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
