"""Multi-page uint16 TIFF stacks of raw frames (tifffile): write, read, check headers."""

from __future__ import annotations

import contextlib
import logging
import os
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import tifffile

from clearfast_gis.atomic import atomic_path
from clearfast_gis.errors import InvalidInput


def write_tiff_stack(path: str | os.PathLike, stack_uint16: np.ndarray,
                     metadata: dict | None = None) -> Path:
    """Write a (P, H, W) uint16 stack as a P-page uncompressed TIFF, atomically.

    Uncompressed contiguous pages let :func:`read_tiff_stack` memory-map the file.
    ``metadata`` (JSON-ready) is stored beside the axes in the first page's description and
    read back by :func:`tiff_metadata`.
    """
    stack = np.asarray(stack_uint16)
    if stack.ndim == 2:
        stack = stack[None]
    if stack.ndim != 3 or stack.dtype != np.uint16:
        raise ValueError(f"expected a (P, H, W) uint16 stack, got {stack.shape} {stack.dtype}")
    with atomic_path(path) as tmp:
        tifffile.imwrite(tmp, stack, photometric="minisblack",
                         metadata={"axes": "QYX", **(metadata or {})})
    return Path(path)


def tiff_metadata(path: str | os.PathLike, label: str | None = None) -> dict:
    """The metadata :func:`write_tiff_stack` stored (empty for other TIFFs).

    Raises
    ------
    InvalidInput
        When the file is missing or not a TIFF.
    """
    label = str(path) if label is None else label
    try:
        with tifffile.TiffFile(path) as tif:
            found = tif.shaped_metadata
    except FileNotFoundError:
        raise InvalidInput("file not found", label) from None
    except Exception as exc:  # tifffile raises many kinds on corrupt input
        msg = " ".join(str(exc).split())[:120] or type(exc).__name__
        raise InvalidInput(f"not a readable TIFF ({msg})", label) from None
    return dict(found[0]) if found else {}


@dataclass(frozen=True)
class TiffInfo:
    """Header facts of a TIFF stack: page count, page shape (H, W), dtype, file size."""

    n_pages: int
    shape: tuple[int, int]
    dtype: np.dtype
    file_size: int
    data_end: int
    contiguous: bool


class _LogCollector(logging.Handler):
    """Collects tifffile's error log records (it logs, rather than raises, on bad IFDs)."""

    def __init__(self) -> None:
        super().__init__(logging.ERROR)
        self.messages: list[str] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.messages.append(record.getMessage())


@contextlib.contextmanager
def _tifffile_errors() -> Iterator[_LogCollector]:
    logger = logging.getLogger("tifffile")
    handler = _LogCollector()
    old = logger.propagate
    logger.addHandler(handler)
    logger.propagate = False
    try:
        yield handler
    finally:
        logger.removeHandler(handler)
        logger.propagate = old


def tiff_info(path: str | os.PathLike, label: str | None = None) -> TiffInfo:
    """Read only the headers (IFDs) of a TIFF and check that its pixel data fit in the file.

    Raises
    ------
    InvalidInput
        When the file is missing, not a TIFF, truncated, or its pages differ in shape or dtype.
    """
    label = str(path) if label is None else label
    try:
        size = os.path.getsize(path)
        with _tifffile_errors() as logged, tifffile.TiffFile(path) as tif:
            pages = tif.pages
            pages.useframes = True
            n = len(pages)
            if n == 0:
                raise InvalidInput("TIFF has no page", label)
            first = pages[0]
            shape = tuple(int(s) for s in first.shape[-2:])
            dtype = np.dtype(first.dtype) if first.dtype is not None else np.dtype("V")
            if len(first.shape) != 2 or first.samplesperpixel != 1:
                raise InvalidInput(f"pages must be single-band images, got shape {first.shape}",
                                   label)
            end = 0
            for k in range(n):
                page = pages[k]
                offs, counts = page.dataoffsets, page.databytecounts
                if not offs:
                    raise InvalidInput(f"page {k} has no pixel data", label)
                end = max(end, max(o + c for o, c in zip(offs, counts, strict=False)))
            series = tif.series[0] if tif.series else None
            contiguous = bool(series is not None and series.dataoffset is not None
                              and len(series) == n)
            if logged.messages:
                msg = " ".join(logged.messages[0].split())[:120]
                raise InvalidInput(f"corrupt or truncated TIFF ({msg})", label)
    except InvalidInput:
        raise
    except FileNotFoundError:
        raise InvalidInput("file not found", label) from None
    except Exception as exc:  # tifffile raises many kinds on corrupt input
        msg = " ".join(str(exc).split())[:120] or type(exc).__name__
        raise InvalidInput(f"not a readable TIFF ({msg})", label) from None
    if end > size:
        raise InvalidInput(f"truncated TIFF: pixel data end at byte {end}, file has {size}",
                           label)
    return TiffInfo(n, shape, dtype, size, end, contiguous)


def read_tiff_stack(path: str | os.PathLike, pages: np.ndarray | None = None,
                    label: str | None = None) -> np.ndarray:
    """Read pages of a TIFF stack as (P, H, W), memory-mapped when the file allows it.

    Parameters
    ----------
    path : path
        TIFF file.
    pages : int array, optional
        Pages to read, in this order (default: all).
    label : str, optional
        Name in error messages.
    """
    label = str(path) if label is None else label
    try:
        try:
            data = tifffile.memmap(path, mode="r")
            n_pages = data.shape[0] if data.ndim == 3 else 1
        except ValueError:  # compressed or not contiguous
            with tifffile.TiffFile(path) as tif:
                n_pages = len(tif.pages)
                data = tif.asarray()
        if (data.shape[0] if data.ndim == 3 else 1) != n_pages:
            raise InvalidInput(f"{n_pages} pages that are not one stack (pages of different "
                               "sizes or types?)", label)
        if data.ndim == 2:
            data = data[None]
        if pages is None:
            return data
        pages = np.asarray(pages, dtype=np.int64)
        if pages.size and (pages.min() < 0 or pages.max() >= data.shape[0]):
            raise InvalidInput(f"page {int(pages.max())} out of range ({data.shape[0]} pages)",
                               label)
        if pages.size and np.array_equal(pages, np.arange(pages[0], pages[0] + pages.size)):
            return data[pages[0]:pages[0] + pages.size]
        return np.asarray(data[pages])
    except InvalidInput:
        raise
    except FileNotFoundError:
        raise InvalidInput("file not found", label) from None
    except Exception as exc:
        msg = " ".join(str(exc).split())[:120] or type(exc).__name__
        raise InvalidInput(f"cannot read TIFF ({msg})", label) from None
