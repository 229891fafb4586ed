"""clearfast-gis: stand-off thermal-IR minefield survey toolkit.

The processing chain (paper: CLEARFAST, stand-off thermal IR minefield survey) as pure functions
over numpy arrays, with file I/O at the edges (:mod:`clearfast_gis.survey`,
:mod:`clearfast_gis.export`).
"""

__version__ = "0.1.0"
