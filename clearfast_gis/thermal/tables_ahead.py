"""Site tables built ahead of the inversions that need them.

A characterisation needs one site table per mine type and body
(:func:`clearfast_gis.thermal.sitesoil.characterise`). A table is a grid of forward runs
on the thread pool; the kernels release the GIL. The inversions are scipy least squares
that hold it. Asked for ahead, a table is built on a helper thread while the inversions
go on on the caller's, so the two overlap on two cores. Each table is built once and is
the same whenever it is built: the products do not depend on the order.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable
from concurrent.futures import Future, ThreadPoolExecutor
from typing import Generic, TypeVar

T = TypeVar("T")


class TablesAhead(Generic[T]):
    """Tables by key, each built once by ``build(key)`` on one helper thread, in the order
    asked for (:meth:`ahead`); :meth:`get` waits for one. Use as a context manager: on
    leaving, the tables not yet started are dropped."""

    def __init__(self, build: Callable[[Hashable], T]) -> None:
        self._build = build
        self._pool = ThreadPoolExecutor(1, thread_name_prefix="clearfast-tables")
        self._futures: dict[Hashable, Future] = {}

    def ahead(self, key: Hashable) -> bool:
        """Start building the table of ``key`` (behind those asked for before) unless it
        was asked for already; True when this call started it."""
        if key in self._futures:
            return False
        self._futures[key] = self._pool.submit(self._build, key)
        return True

    def get(self, key: Hashable) -> T:
        """The table of ``key``, built now if it was not asked for ahead (an error of its
        build is raised here)."""
        self.ahead(key)
        return self._futures[key].result()

    def close(self) -> None:
        """Drop the builds not started, wait for the one running."""
        self._pool.shutdown(wait=True, cancel_futures=True)

    def __enter__(self) -> TablesAhead[T]:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


__all__ = ["TablesAhead"]
