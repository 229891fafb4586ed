"""The radiometry's fast kernels (``--kernels fast``, :mod:`clearfast_gis.kernels`).

- :func:`inverse_planck` (the registry's ``inverse_planck``): Eq. 5 on the radiance-uniform
  inverse table of :class:`~clearfast_gis.radiometry.table.BandTable`, by index arithmetic
  and linear interpolation (numba); :func:`_uniform_hermite` evaluates the forward table.
- :func:`apparent_frames` (``apparent_frames``): counts to apparent temperature in one pass
  over a block of frames. :func:`clearfast_gis.radiometry.stage.apparent_temperature_frames`
  chains, per frame, the blend of two calibrations in time, Eq. 1 (counts to radiance),
  Eq. 4 (atmosphere) and Eq. 5 (the inverse Planck table); the kernel does the same
  arithmetic pixel by pixel in one loop (numba, no temporaries, GIL released), row by row
  over the block's frames so that the calibration images' rows are read once per block; it
  agrees with the array chain to 1 mK (tested).

The references are in :mod:`clearfast_gis.radiometry._reference`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numba
import numpy as np

if TYPE_CHECKING:
    from clearfast_gis.radiometry.table import BandTable


@numba.njit(cache=True, nogil=True)
def _uniform_linear(x, x0, inv_dx, y, out):
    """out[i] = y interpolated linearly at x[i] on the uniform grid x0 + k / inv_dx; NaN
    outside the grid or for NaN input."""
    n = y.size - 1
    for i in range(x.size):
        s = (np.float64(x[i]) - x0) * inv_dx
        if s >= 0.0 and s <= n:
            j = min(int(s), n - 1)
            f = s - j
            out[i] = y[j] + f * (y[j + 1] - y[j])
        else:
            out[i] = np.nan


@numba.njit(cache=True, nogil=True)
def _uniform_hermite(x, x0, dx, y, dy, out):
    """Cubic Hermite interpolation of (y, dy/dx) on a uniform grid; NaN outside."""
    n = y.size - 1
    inv_dx = 1.0 / dx
    for i in range(x.size):
        s = (np.float64(x[i]) - x0) * inv_dx
        if s >= 0.0 and s <= n:
            j = min(int(s), n - 1)
            t = s - j
            t2 = t * t
            t3 = t2 * t
            h00 = 2.0 * t3 - 3.0 * t2 + 1.0
            h10 = t3 - 2.0 * t2 + t
            h01 = -2.0 * t3 + 3.0 * t2
            h11 = t3 - t2
            out[i] = h00 * y[j] + h10 * dx * dy[j] + h01 * y[j + 1] + h11 * dx * dy[j + 1]
        else:
            out[i] = np.nan


@numba.njit(cache=True, nogil=True, error_model="numpy")
def _fused(raw, gain_a, offset_a, gain_b, offset_b, first, second, w1, tau, b_air, r0, inv_dr,
           t_nodes, out):  # pragma: no cover - compiled
    p, h, w = raw.shape
    n = t_nodes.size - 1
    s_row = np.empty(w, dtype=np.float64)  # table coordinate of each pixel of a row
    # row by row, every frame of the block: a row of the calibration images is read from
    # memory once for all the frames (it stays in the cache), not once per frame
    for i in range(h):
        for k in range(p):
            wk1 = w1[k]
            w0 = 1.0 - wk1
            # each frame's two calibrations are images a or b (slots 0 and 1)
            gain0 = gain_a[i] if first[k] == 0 else gain_b[i]
            offset0 = offset_a[i] if first[k] == 0 else offset_b[i]
            gain1 = gain_a[i] if second[k] == 0 else gain_b[i]
            offset1 = offset_a[i] if second[k] == 0 else offset_b[i]
            counts, trans, b_k = raw[k, i], tau[k, i], b_air[k]
            # the arithmetic of a row first (no branch, so the loop vectorises), then the table
            for j in range(w):
                g = w0 * gain0[j] + wk1 * gain1[j]
                o = w0 * offset0[j] + wk1 * offset1[j]
                t = trans[j]
                surf = (counts[j] * g + o - (1.0 - t) * b_k) / t
                s_row[j] = (surf - r0) * inv_dr
            row = out[k, i]
            for j in range(w):
                s = s_row[j]
                if s >= 0.0 and s <= n:  # False for NaN
                    m = min(int(s), n - 1)
                    f = s - m
                    row[j] = t_nodes[m] + f * (t_nodes[m + 1] - t_nodes[m])
                else:
                    row[j] = np.nan


def inverse_planck(table: BandTable, r: np.ndarray, dtype=np.float32) -> np.ndarray:
    """:meth:`~clearfast_gis.radiometry.table.BandTable.temperature` on the fast kernels
    (radiance-uniform table, numba)."""
    if r.dtype not in (np.float32, np.float64):
        r = r.astype(np.float64)
    flat = np.ascontiguousarray(r).ravel()
    out = np.empty(flat.shape, dtype=dtype)
    _uniform_linear(flat, table.inverse_radiance0, 1.0 / table.inverse_step,
                    table.inverse_t_k, out)
    return out.reshape(r.shape)


def apparent_frames(raw: np.ndarray, parts: list, tau: list, t_air_k: np.ndarray,
                    b_air: np.ndarray, table, out: np.ndarray) -> None:
    """Frames' apparent temperature (kelvin) into ``out`` on the fast kernels: calibration,
    atmosphere and inverse Planck fused per pixel, the frames of a block together (the
    registry's ``apparent_frames``, called by
    :func:`clearfast_gis.radiometry.stage.apparent_temperature_frames`).

    ``raw`` (P, H, W) raw counts; ``parts`` per frame, one calibration (weight 1) or two
    blended linearly in time (weights summing to 1), as (GainOffset, weight); ``tau`` per
    frame its transmittance, a scalar or (H, W) (used as float32); ``t_air_k`` (P,) is used
    by the reference only; ``b_air`` (P,) band radiance of a blackbody at the air
    temperature, W m-2 sr-1 (path radiance ``(1 - tau) b_air``); ``table`` the band's
    :class:`~clearfast_gis.radiometry.table.BandTable`; ``out`` float32 (P, H, W), written
    with the apparent temperature, kelvin (NaN at uncalibrated pixels and outside the table).
    """
    raw = np.ascontiguousarray(raw)
    trans = np.empty(raw.shape, dtype=np.float32)
    for k, t in enumerate(tau):
        trans[k] = np.asarray(t, dtype=np.float32)
    b_air = np.asarray(b_air, dtype=np.float64)
    for a, b, images, first, second, w1 in _runs(parts):
        _fused(raw[a:b], images[0].gain, images[0].offset, images[-1].gain, images[-1].offset,
               first, second, w1, trans[a:b], b_air[a:b], table.inverse_radiance0,
               1.0 / table.inverse_step, table.inverse_t_k, out[a:b])


def _runs(parts: list) -> list[tuple]:
    """The frames in runs that use at most two calibration images: ``(start, stop, images,
    first, second, w1)`` with each frame's slots (0 or 1) in ``images`` and the weight of
    its second calibration. The kernel reads the images as they are (no stacked copy of a
    scan's calibration per block); a block crosses a third event only when a calibration
    falls inside it."""
    def distinct(cals: list, known: list) -> list:
        out: list = []
        for c in cals:
            if not any(c is i for i in known + out):
                out.append(c)
        return out

    runs = []
    start, images = 0, []
    for k, frame_parts in enumerate(parts + [None]):
        cals = [] if frame_parts is None else [c for c, _w in frame_parts]
        new = distinct(cals, images)
        if frame_parts is not None and len(images) + len(new) <= 2:
            images += new
            continue
        if k > start:
            span = parts[start:k]
            slot = {id(c): i for i, c in enumerate(images)}
            first = np.array([slot[id(fp[0][0])] for fp in span], dtype=np.int64)
            second = np.array([slot[id(fp[-1][0])] for fp in span], dtype=np.int64)
            w1 = np.array([float(fp[1][1]) if len(fp) > 1 else 0.0 for fp in span])
            runs.append((start, k, images, first, second, w1))
        start, images = k, distinct(cals, [])
    return runs
