"""The processing chain, survey folder to products folder, with progress and resume.

``process_survey`` runs the stages of ARCHITECTURE §2 in order; each finished stage is recorded
in ``PRODUCTS/.clearfast/state.json`` so an interrupted run continues where it stopped.
"""

from clearfast_gis.pipeline.options import ProcessOptions
from clearfast_gis.pipeline.run import process_survey, redetect

__all__ = ["ProcessOptions", "process_survey", "redetect"]
