"""Atomic product writes: write under a temporary name in the same folder, then rename.

A reader never sees a half-written file under its final name, and a run killed at any point
leaves either the previous file or the new one.
"""

from __future__ import annotations

import contextlib
import errno
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

from clearfast_gis.errors import OutputError


def _describe_os_error(exc: OSError) -> str:
    if exc.errno == errno.ENOSPC:
        return "no space left on device"
    if exc.errno in (errno.EACCES, errno.EPERM, errno.EROFS):
        return "not writable (permission denied or read-only)"
    return exc.strerror or str(exc)


@contextlib.contextmanager
def atomic_path(final: str | os.PathLike, suffix: str | None = None) -> Iterator[Path]:
    """Yield a temporary path beside ``final``; rename it to ``final`` if the block succeeds.

    The temporary file keeps the final suffix (GDAL drivers choose the format by it). On any
    error the temporary file is removed and an :class:`OutputError` naming ``final`` is raised
    for OS errors (disk full, permission denied).

    Parameters
    ----------
    final : path
        Final file name.
    suffix : str, optional
        Suffix of the temporary file; default: the suffix of ``final``.
    """
    final = Path(final)
    try:
        final.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp_name = tempfile.mkstemp(
            prefix=f".{final.stem}.", suffix=(final.suffix if suffix is None else suffix) + ".part",
            dir=final.parent,
        )
        os.close(fd)
        os.unlink(tmp_name)  # writers (GDAL, sqlite) want to create the file themselves
    except OSError as exc:
        raise OutputError(_describe_os_error(exc), final.parent) from None
    tmp = Path(tmp_name)
    try:
        yield tmp
        if not tmp.exists():
            raise OutputError("the writer produced no file", final)
        _fsync(tmp)
        os.replace(tmp, final)
        _fsync_dir(final.parent)
    except OSError as exc:
        raise OutputError(_describe_os_error(exc), final) from None
    finally:
        with contextlib.suppress(OSError):
            if tmp.exists():
                tmp.unlink()


def _fsync(path: Path) -> None:
    with open(path, "rb") as fh:
        os.fsync(fh.fileno())


def _fsync_dir(path: Path) -> None:
    with contextlib.suppress(OSError):
        fd = os.open(path, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)


def write_bytes(final: str | os.PathLike, data: bytes) -> Path:
    """Write ``data`` to ``final`` atomically and return the final path."""
    with atomic_path(final) as tmp:
        tmp.write_bytes(data)
    return Path(final)


def write_text(final: str | os.PathLike, text: str) -> Path:
    """Write UTF-8 ``text`` to ``final`` atomically and return the final path."""
    return write_bytes(final, text.encode("utf-8"))


def is_temporary(name: str) -> bool:
    """Whether a file name is one of :func:`atomic_path`'s temporaries."""
    return name.startswith(".") and (name.endswith(".part") or ".part." in name)


def remove_temporaries(folder: str | os.PathLike) -> list[Path]:
    """Delete the atomic writers' temporary files under ``folder``; return what was removed."""
    removed = []
    for dirpath, _dirs, names in os.walk(folder):
        for name in names:
            if is_temporary(name):
                p = Path(dirpath) / name
                with contextlib.suppress(FileNotFoundError):
                    p.unlink()
                    removed.append(p)
    return removed
