"""Grey-scale erosion by a disk as a minimum over its chords (numba), behind
:func:`clearfast_gis.detection.morphology.erode_disk` and
:func:`~clearfast_gis.detection.morphology.dilate_disk` for float images.

A digital disk of radius r is, row by row, 2 r + 1 horizontal chords centred on its column
axis (half-widths ``w[dy]``, :func:`chord_half_widths`). The erosion at a pixel is the minimum
over the chords of each chord's minimum, and a chord's minimum is the row's erosion by a
segment of that half-width. Each image row is eroded by the segments the disk needs, each from
a shorter one (:func:`segment_schedule`: ``E_k(x) = min(E_j(x - m), E_j(x + m))`` with
``m = k - j <= j``, one comparison a pixel), kept in a ring of 2 r + 1 rows; each output row
is then the minimum of 2 r + 1 of them. For D1 = 25 pixels that is 11 + 24 comparisons a pixel
against the 441 cells of the disk that a kernel visiting them all compares (OpenCV's
``cv2.erode``, whose SIMD loop this beats two to three times).

Pixels outside the image are ignored (OpenCV's constant border at +inf for the erosion; for a
disk also its replicated border, as a replicated pixel lies inside the disk of the pixel it
borders). A minimum returns one of its inputs, so the result holds the same values as OpenCV's,
bit for bit (tested; of two zeros of opposite sign, equal as numbers, either may be returned).
No NaN may be in the input (the callers set no-data to +inf).
"""

from __future__ import annotations

import numba
import numpy as np


def chord_half_widths(footprint: np.ndarray) -> np.ndarray | None:
    """Half-width of each row's chord of a square ``footprint`` (2r+1, 2r+1), int64 (2r+1,);
    None when a row is not one run of ones centred on the middle column (not a disk)."""
    fp = np.asarray(footprint, dtype=bool)
    if fp.ndim != 2 or fp.shape[0] != fp.shape[1] or fp.shape[0] % 2 == 0:
        return None
    r = fp.shape[0] // 2
    out = np.empty(fp.shape[0], dtype=np.int64)
    for i, row in enumerate(fp):
        w = int(row.sum()) // 2
        if not row.any() or row.sum() != 2 * w + 1 or not row[r - w:r + w + 1].all():
            return None
        out[i] = w
    return out


def segment_schedule(half_widths: np.ndarray) -> np.ndarray:
    """How the row erosions ``E_k`` for every half-width of ``half_widths`` are made, int64
    (S, 3) rows ``(k, j, m)`` in order: ``E_k(x) = min(E_j(x - m), E_j(x + m))`` when
    ``m <= j`` (the two segments overlap or touch), else ``min(E_j(x - m), E_j(x), E_j(x + m))``
    (``m <= 2 j + 1``), ``j`` the longest made before; ``E_0`` is the row itself, and a
    segment of about half a target is made first where it is too far from every one made."""
    made = [0]
    rows: list[tuple[int, int, int]] = []

    def make(k: int) -> None:
        if k in made:
            return
        if k - max(made) > 2 * max(made) + 1:  # too far from every segment made
            make((k + 1) // 2)  # a step of about half of it first
        j = max(made)
        rows.append((k, j, k - j))
        made.append(k)

    for k in sorted(set(int(w) for w in half_widths) - {0}):
        make(k)
    return np.array(rows, dtype=np.int64).reshape(-1, 3)


@numba.njit(cache=True, nogil=True)
def erode_chords(image, half_widths, schedule, out):  # pragma: no cover - compiled
    """``out`` = erosion of ``image`` (float (H, W), no NaN) by the disk whose row ``dy``
    (0 .. 2r) is the chord of half-width ``half_widths[dy]`` (int64 (2r+1,), each <= r);
    pixels outside the image ignored. ``schedule``: :func:`segment_schedule` of the
    half-widths. ``out``: float (H, W) of the image's dtype, not ``image``."""
    h, w = image.shape
    n = half_widths.size
    r = n // 2
    # ring[y % n, k] = row y eroded by the segment of half-width k (the k of the schedule)
    ring = np.empty((n, r + 1, w), dtype=image.dtype)
    for y in range(min(r, h)):  # the rows below the first output row's centre
        _segments(image[y], ring[y % n], schedule)
    for y0 in range(h):
        y_new = y0 + r
        if y_new < h:
            _segments(image[y_new], ring[y_new % n], schedule)
        dst = out[y0]
        first = True
        for dy in range(n):
            y = y0 + dy - r
            if y < 0 or y >= h:
                continue
            src = ring[y % n, half_widths[dy]]
            if first:
                for x in range(w):
                    dst[x] = src[x]
                first = False
            else:
                for x in range(w):
                    a = src[x]
                    b = dst[x]
                    dst[x] = a if a < b else b


@numba.njit(cache=True, nogil=True, inline="always")
def _segments(row, seg, schedule):  # pragma: no cover - compiled
    """``seg[k]`` = ``row`` eroded by the segment of half-width k for every k of
    ``schedule`` (ends clipped to the row: an index outside is clamped, whose segment then
    lies inside the wanted one). The inner loops run over views from index 0, which the
    compiler vectorises (an offset index may be negative and is not)."""
    w = row.size
    last = w - 1
    first = seg[0]
    for x in range(w):
        first[x] = row[x]
    for s in range(schedule.shape[0]):
        k, j, m = schedule[s, 0], schedule[s, 1], schedule[s, 2]
        src, cur = seg[j], seg[k]
        lo = min(m, w)  # x < lo: the left end is clamped
        hi = max(w - m, lo)  # x >= hi: the right end is clamped
        three = m > j  # the two ends do not touch: the middle too
        for x in range(lo):
            a = src[0]
            b = src[min(x + m, last)]
            a = b if b < a else a
            if three:
                b = src[x]
                a = b if b < a else a
            cur[x] = a
        for x in range(hi, w):
            a = src[max(x - m, 0)]
            b = src[last]
            a = b if b < a else a
            if three:
                b = src[x]
                a = b if b < a else a
            cur[x] = a
        if hi > lo:
            left, right, dst = src[lo - m:hi - m], src[lo + m:hi + m], cur[lo:hi]
            if three:
                mid = src[lo:hi]
                for x in range(dst.size):
                    a = left[x]
                    b = right[x]
                    a = b if b < a else a
                    b = mid[x]
                    dst[x] = b if b < a else a
            else:
                for x in range(dst.size):
                    a = left[x]
                    b = right[x]
                    dst[x] = b if b < a else a
