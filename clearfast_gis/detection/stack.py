"""A temporal stack of mosaics read one scan at a time.

The detector and everything after it (blob features, markers, the site's background and
clutter, the report) pass over the stack scan by scan instead of holding all of it: memory
holds the scans being read and what each pass keeps per pixel or per blob, not the
(N, B, H, W) stack. A :class:`ScanStack` gives one scan's bands on request; an in-memory
array (:class:`ArrayStack`) and the mosaic COGs of a products folder
(:class:`clearfast_gis.export.cog.CogStack`) are both one, and every pass gives the same
values on either.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Protocol, TypeVar

import numpy as np

from clearfast_gis.parallel import thread_imap

R = TypeVar("R")

__all__ = ["ArrayStack", "ScanStack", "as_scan_stack", "iter_images", "map_scans"]


class ScanStack(Protocol):
    """N scans of B bands of (H, W) images (float32, degrees C or K, NaN = no data)."""

    n_scans: int
    n_bands: int
    shape: tuple[int, int]

    def scan(self, i: int) -> np.ndarray:
        """The bands of scan ``i``: float32 (B, H, W)."""
        ...


@dataclass(frozen=True)
class ArrayStack:
    """A stack held in memory, float32 (N, B, H, W)."""

    data: np.ndarray

    @property
    def n_scans(self) -> int:
        return int(self.data.shape[0])

    @property
    def n_bands(self) -> int:
        return int(self.data.shape[1])

    @property
    def shape(self) -> tuple[int, int]:
        return int(self.data.shape[2]), int(self.data.shape[3])

    def scan(self, i: int) -> np.ndarray:
        return self.data[i]


def as_scan_stack(stack) -> ScanStack:
    """A :class:`ScanStack` as it is, or an array (H, W), (N, H, W) or (N, B, H, W) viewed
    as float32 (N, B, H, W) in an :class:`ArrayStack`."""
    if hasattr(stack, "scan") and hasattr(stack, "n_bands"):
        return stack
    a = np.asarray(stack)
    if a.ndim == 2:
        a = a[None, None]
    elif a.ndim == 3:
        a = a[:, None]
    elif a.ndim != 4:
        raise ValueError(f"stack must be (H, W), (N, H, W) or (N, B, H, W), got {a.shape}")
    if min(a.shape) < 1:
        raise ValueError(f"empty stack {a.shape}")
    return ArrayStack(np.asarray(a, dtype=np.float32))


def map_scans(fn: Callable[[int, np.ndarray], R], stack: ScanStack) -> Iterator[R]:
    """``fn(i, bands)`` for every scan i of the stack (bands float32 (B, H, W)), yielded in
    scan order. The scans are read and ``fn`` runs on threads, a few scans ahead of the
    consumer at most (memory: about two scans per thread)."""
    return thread_imap(lambda i: fn(i, stack.scan(i)), range(stack.n_scans), ahead=1)


def iter_images(stack: ScanStack) -> Iterator[np.ndarray]:
    """Every image of the stack, float32 (H, W), scan by scan and band by band (image k is
    scan ``k // B``, band ``k % B``)."""
    for bands in map_scans(lambda _, bands: bands, stack):
        yield from bands
