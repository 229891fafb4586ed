"""Exact order statistics by radix selection (numba), behind the fast ``order_statistics``
kernel (:func:`clearfast_gis.detection._kernels.order_statistics`).

Each float's bits are mapped to an unsigned key whose integer order is the float order (the
sign bit set for non-negative values, every bit flipped for negative ones; both zeros get
+0.0's key, as they compare equal). One pass counts the keys' top bits (:data:`RADIX_BITS`,
fewer for a small array: :func:`_bucket_bits`); a second gathers the keys of the buckets that
hold the requested ranks (a bucket of nothing but zeros, most of a hat image, is its own
answer); a bucket of more than :data:`SORT_BELOW` keys is narrowed by bucketing its range
again, then sorted. Two passes over the data and no copy of it, against ``np.partition``'s
copy and introselect.
"""

from __future__ import annotations

import numba
import numpy as np

RADIX_BITS = 16
"""Key bits resolved per pass at most (fewer for fewer keys: :func:`_bucket_bits`)."""

SORT_BELOW = 4096
"""A bucket of at most this many keys is sorted rather than narrowed further."""


@numba.njit(cache=True, nogil=True)
def _bucket_bits(n):  # pragma: no cover - compiled
    """Key bits resolved by one pass over ``n`` keys: :data:`RADIX_BITS` for large arrays,
    about ``log2(n) - 4`` (at least 8) for small ones, so that the buckets' counts (zeroed,
    summed and scanned once per pass) cost less than the keys themselves (a median of a
    10,000-value window spent most of its time on 65,536 buckets). The buckets chosen do
    not change the key found at a rank."""
    bits = 0
    while n >> bits:
        bits += 1
    return min(RADIX_BITS, max(8, bits - 4))


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
def _narrow(keys, rank):  # pragma: no cover - compiled
    """The key of ``rank`` (0-based, sorted order) among ``keys``."""
    while keys.size > SORT_BELOW:
        lo = keys[0]
        hi = keys[0]
        for k in keys:
            lo = min(lo, k)
            hi = max(hi, k)
        if lo == hi:  # e.g. the zeros of a hat image
            return lo
        # buckets of (k - lo) >> shift: the range spread over at most 2**bits buckets, of which
        # lo and hi fall in different ones, so every pass narrows
        bits = _bucket_bits(keys.size)
        shift = 0
        while (hi - lo) >> np.uint64(shift + bits):
            shift += 1
        hist = np.zeros(1 << bits, dtype=np.int64)
        for k in keys:
            hist[((k - lo) >> np.uint64(shift))] += 1
        below = 0
        t = 0
        while below + hist[t] <= rank:
            below += hist[t]
            t += 1
        part = np.empty(hist[t], dtype=np.uint64)
        want = np.uint64(t)
        m = 0
        for k in keys:
            if (k - lo) >> np.uint64(shift) == want:
                part[m] = k
                m += 1
        keys = part
        rank -= below
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
    n = bits.size
    n_buckets = 1 << _bucket_bits(n)
    shift = np.uint64(nbits) - np.uint64(_bucket_bits(n))
    # four interleaved counts (no chain of increments of one counter when a bucket holds
    # most values), and the exact zeros: a hat image is mostly zeros
    counts = np.zeros((4, n_buckets), dtype=np.int64)
    zeros = 0
    for i in range(n):
        k = _key(bits[i], sign, ones)
        zeros += k == sign
        counts[i & 3, k >> shift] += 1
    hist = counts[0] + counts[1] + counts[2] + counts[3]
    nr = ranks.size
    bucket = np.empty(nr, dtype=np.int64)
    base = np.empty(nr, dtype=np.int64)
    start = 0
    r = 0
    for t in range(n_buckets):
        while r < nr and ranks[r] < start + hist[t]:
            bucket[r] = t
            base[r] = start
            r += 1
        start += hist[t]
    zero_t = np.int64(sign >> shift)
    only_zeros = hist[zero_t] == zeros
    offset = np.full(n_buckets, -1, dtype=np.int64)  # where each gathered bucket's keys go
    total = 0
    for r in range(nr):
        t = bucket[r]
        if offset[t] < 0 and not (t == zero_t and only_zeros):
            offset[t] = total
            total += hist[t]
    gathered = np.empty(total, dtype=np.uint64)
    fill = offset.copy()
    if total > 0:
        for i in range(n):
            k = _key(bits[i], sign, ones)
            o = fill[k >> shift]
            if o >= 0:
                gathered[o] = k
                fill[k >> shift] = o + 1
    out = np.empty(nr, dtype=np.uint64)
    for r in range(nr):
        t = bucket[r]
        if t == zero_t and only_zeros:
            out[r] = sign
        else:
            out[r] = _narrow(gathered[offset[t]:offset[t] + hist[t]], ranks[r] - base[r])
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
    if v.dtype not in (np.float32, np.float64):
        raise TypeError(f"radix selection takes float32 or float64 values, not {v.dtype}")
    unsigned = {4: np.uint32, 8: np.uint64}[v.dtype.itemsize]
    nbits = 8 * v.dtype.itemsize
    r = np.asarray(ranks, dtype=np.int64).ravel()
    order = np.argsort(r, kind="stable")
    keys = select_keys(v.view(unsigned), nbits, r[order])
    found = key_to_bits(keys, nbits).astype(unsigned).view(v.dtype)
    out = np.empty_like(found)
    out[order] = found
    return out
