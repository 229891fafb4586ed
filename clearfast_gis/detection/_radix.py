"""Exact order statistics by radix selection (numba), behind the fast ``order_statistics``
kernel (:func:`clearfast_gis.detection._kernels.order_statistics`).

Each float's bits are mapped to an unsigned key whose integer order is the float order (the
sign bit set for non-negative values, every bit flipped for negative ones; both zeros get
+0.0's key, as they compare equal). One pass counts the keys' top :data:`RADIX_BITS` bits; a
second gathers the keys of the buckets that hold the requested ranks; a bucket is narrowed
by the next bits while it holds more than :data:`SORT_BELOW` keys, then sorted. Two passes
over the data and no copy of it, against ``np.partition``'s copy and introselect.
"""

from __future__ import annotations

import numba
import numpy as np

RADIX_BITS = 16
"""Key bits resolved per pass."""

SORT_BELOW = 4096
"""A bucket of at most this many keys is sorted rather than narrowed further."""

_BUCKETS = 1 << RADIX_BITS


@numba.njit(cache=True, nogil=True, inline="always")
def _key(bits, sign, ones):  # pragma: no cover - compiled
    """Order-preserving key of a float's bits (``sign``: its sign bit; ``ones``: all bits)."""
    b = np.uint64(bits)
    if b == sign:  # -0.0 == +0.0
        b = np.uint64(0)
    if b & sign:
        return b ^ ones
    return b | sign


@numba.njit(cache=True, nogil=True)
def _narrow(keys, rank, shift):  # pragma: no cover - compiled
    """The key of ``rank`` (0-based, sorted order) among ``keys``, which share every bit
    above ``shift``."""
    while keys.size > SORT_BELOW and shift > 0:
        shift = max(shift - RADIX_BITS, 0)
        hist = np.zeros(_BUCKETS, dtype=np.int64)
        for k in keys:
            hist[(k >> np.uint64(shift)) & np.uint64(_BUCKETS - 1)] += 1
        below = 0
        t = 0
        while below + hist[t] <= rank:
            below += hist[t]
            t += 1
        part = np.empty(hist[t], dtype=np.uint64)
        m = 0
        want = np.uint64(t)
        for k in keys:
            if (k >> np.uint64(shift)) & np.uint64(_BUCKETS - 1) == want:
                part[m] = k
                m += 1
        keys = part
        rank -= below
    if shift == 0:  # every key of the bucket is the same
        return keys[rank]
    return np.sort(keys)[rank]


@numba.njit(cache=True, nogil=True)
def select_keys(bits, nbits, ranks):  # pragma: no cover - compiled
    """Keys of the values at ``ranks`` in sorted order.

    Parameters
    ----------
    bits : uint32 or uint64 (N,)
        The values' bits (a float32 or float64 array viewed as unsigned integers), N >= 1.
    nbits : int
        32 or 64.
    ranks : int64 (R,)
        Ascending ranks, 0 <= rank < N.

    Returns
    -------
    uint64 (R,)
        Keys (:func:`key_to_bits` gives the values back).
    """
    sign = np.uint64(1) << np.uint64(nbits - 1)
    ones = (sign - np.uint64(1)) | sign
    shift = np.uint64(nbits - RADIX_BITS)
    hist = np.zeros(_BUCKETS, dtype=np.int64)
    for i in range(bits.size):
        hist[_key(bits[i], sign, ones) >> shift] += 1
    nr = ranks.size
    bucket = np.empty(nr, dtype=np.int64)
    base = np.empty(nr, dtype=np.int64)
    start = 0
    r = 0
    for t in range(_BUCKETS):
        while r < nr and ranks[r] < start + hist[t]:
            bucket[r] = t
            base[r] = start
            r += 1
        start += hist[t]
    offset = np.full(_BUCKETS, -1, dtype=np.int64)  # where each wanted bucket's keys go
    total = 0
    for r in range(nr):
        if offset[bucket[r]] < 0:
            offset[bucket[r]] = total
            total += hist[bucket[r]]
    gathered = np.empty(total, dtype=np.uint64)
    fill = offset.copy()
    for i in range(bits.size):
        k = _key(bits[i], sign, ones)
        o = fill[k >> shift]
        if o >= 0:
            gathered[o] = k
            fill[k >> shift] = o + 1
    out = np.empty(nr, dtype=np.uint64)
    for r in range(nr):
        t = bucket[r]
        out[r] = _narrow(gathered[offset[t]:offset[t] + hist[t]], ranks[r] - base[r],
                         nbits - RADIX_BITS)
    return out


def key_to_bits(keys: np.ndarray, nbits: int) -> np.ndarray:
    """The float bits (uint64 (R,)) of keys of :func:`select_keys` (the inverse mapping)."""
    sign = np.uint64(1) << np.uint64(nbits - 1)
    ones = (sign - np.uint64(1)) | sign
    keys = np.asarray(keys, dtype=np.uint64)
    return np.where(keys & sign, keys ^ sign, keys ^ ones)


def radix_order_statistics(values: np.ndarray, ranks) -> np.ndarray:
    """``np.partition(values, ranks)[ranks]`` by radix selection.

    Parameters
    ----------
    values : float32 or float64 (N,)
        Finite values, N >= 1 (any shape is flattened).
    ranks : sequence of int
        0-based ranks in sorted order, each in [0, N).

    Returns
    -------
    ndarray (R,) of the values' dtype
        The values at ``ranks`` (in the order given).
    """
    v = np.ascontiguousarray(values).ravel()
    unsigned = {4: np.uint32, 8: np.uint64}[v.dtype.itemsize]
    nbits = 8 * v.dtype.itemsize
    r = np.asarray(ranks, dtype=np.int64).ravel()
    order = np.argsort(r, kind="stable")
    keys = select_keys(v.view(unsigned), nbits, r[order])
    found = key_to_bits(keys, nbits).astype(unsigned).view(v.dtype)
    out = np.empty_like(found)
    out[order] = found
    return out
