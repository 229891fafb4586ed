"""Insertion of projected frames into a mosaic: per cell, the frame seen closest to nadir."""

from __future__ import annotations

import numba
import numpy as np

from clearfast_gis.mosaic.project import ProjectedFrame


@numba.njit(cache=True, nogil=True)
def _insert(values, incidence, source, frame_values, frame_incidence, row0, col0,
            index):  # pragma: no cover - compiled
    h, w = frame_incidence.shape
    n = 0
    for i in range(h):
        for j in range(w):
            a = frame_incidence[i, j]
            if a < incidence[row0 + i, col0 + j]:  # False where the frame is NaN (unseen)
                incidence[row0 + i, col0 + j] = a
                source[row0 + i, col0 + j] = index
                for b in range(values.shape[0]):
                    values[b, row0 + i, col0 + j] = frame_values[b, i, j]
                n += 1
    return n


class MosaicCanvas:
    """A mosaic under construction.

    Temperatures are never blended: each cell takes its value from one source frame, the one
    that saw it at the smallest incidence angle (paper §5: insertion following the scan
    pattern).

    Parameters
    ----------
    n_bands, height, width : int
        Mosaic size.

    Attributes
    ----------
    values : float32 (B, H, W)
        Degrees C, NaN where no frame has been inserted.
    incidence_deg : float32 (H, W)
        Incidence angle of the chosen source, degrees (inf where empty).
    source : int32 (H, W)
        Index of the source frame, -1 where empty.
    """

    def __init__(self, n_bands: int, height: int, width: int) -> None:
        self.values = np.full((n_bands, height, width), np.nan, dtype=np.float32)
        self.incidence_deg = np.full((height, width), np.inf, dtype=np.float32)
        self.source = np.full((height, width), -1, dtype=np.int32)

    def window_values(self, projected: ProjectedFrame) -> np.ndarray:
        """The mosaic's current values under a projected frame's window, (B, h, w)."""
        rs, cs = projected.window.slices
        return self.values[:, rs, cs]

    def insert(self, projected: ProjectedFrame, frame_index: int) -> int:
        """Insert a projected frame; returns the number of cells it now supplies (compiled,
        one pass over the window, GIL released)."""
        win = projected.window
        return int(_insert(self.values, self.incidence_deg, self.source,
                           np.ascontiguousarray(projected.values, dtype=np.float32),
                           np.ascontiguousarray(projected.incidence_deg, dtype=np.float32),
                           win.row0, win.col0, int(frame_index)))

    @property
    def covered(self) -> np.ndarray:
        """Cells with a value, bool (H, W)."""
        return self.source >= 0
