"""The radiometry's reference kernels (``--kernels reference``, :mod:`clearfast_gis.kernels`):
the paper's 0.1 K inverse table and the array chain of Eq. 1, 4 and 5, step by step."""

from __future__ import annotations

import numpy as np

from clearfast_gis.radiometry.apparent import raw_to_apparent
from clearfast_gis.radiometry.calibration import blend_gain_offsets
from clearfast_gis.radiometry.table import BandTable, apparent_temperature_paper


def inverse_planck(table: BandTable, r: np.ndarray, dtype=np.float32) -> np.ndarray:
    """:meth:`~clearfast_gis.radiometry.table.BandTable.temperature` on the reference kernels
    (the paper's 0.1 K table)."""
    return apparent_temperature_paper(r, table).astype(dtype)


def apparent_frames(raw: np.ndarray, parts: list, tau: list, t_air_k: np.ndarray,
                    b_air: np.ndarray, table, out: np.ndarray) -> None:
    """:func:`clearfast_gis.radiometry._kernels.apparent_frames` on the reference kernels,
    frame by frame and step by step (:func:`~clearfast_gis.radiometry.apparent.raw_to_apparent`,
    air temperature ``t_air_k``)."""
    for k in range(raw.shape[0]):
        out[k] = raw_to_apparent(raw[k], blend_gain_offsets(parts[k]), tau[k],
                                 float(t_air_k[k]), table)
