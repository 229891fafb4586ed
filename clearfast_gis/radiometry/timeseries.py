"""Linear interpolation in an instrument log (blackbody temperatures, weather records)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.errors import InvalidInput


def interpolate_log(
    log_time_s: ArrayLike,
    values: ArrayLike,
    time_s: ArrayLike,
    max_gap_s: float,
    source: str | None = None,
    field: str | None = None,
) -> np.ndarray:
    """Values of a logged quantity at given times, linearly interpolated.

    Records with a NaN time or value (a logger's ``NAN``) are skipped. Queries before the first
    or after the last valid record take that record's value, provided it is within
    ``max_gap_s``.

    Parameters
    ----------
    log_time_s : array_like (T,)
        Record times, UTC epoch seconds (any order).
    values : array_like (T,)
        Logged values.
    time_s : array_like
        Query times, UTC epoch seconds, any shape.
    max_gap_s : float
        A query farther than this from every valid record raises :class:`InvalidInput`.
    source, field : str, optional
        Log file and column for error messages.

    Returns
    -------
    ndarray of float64
        Shape of ``time_s``.
    """
    t = np.asarray(log_time_s, dtype=np.float64).ravel()
    v = np.asarray(values, dtype=np.float64).ravel()
    ok = np.isfinite(t) & np.isfinite(v)
    if not ok.any():
        raise InvalidInput("no valid records", source, field)
    order = np.argsort(t[ok], kind="stable")
    t, v = t[ok][order], v[ok][order]
    q = np.asarray(time_s, dtype=np.float64)
    j = np.clip(np.searchsorted(t, q), 1, max(t.size - 1, 1))
    gap = np.minimum(np.abs(q - t[j - 1]), np.abs(q - t[np.minimum(j, t.size - 1)]))
    if np.any(~np.isfinite(q)) or np.any(gap > max_gap_s):
        raise InvalidInput(f"no valid record within {max_gap_s:g} s of a requested time",
                           source, field)
    return np.interp(q, t, v)
