"""Products that cannot be written: a disk that fills up during a write, an unwritable
products folder. One line naming the file or folder, exit 1, no half-written product."""

from __future__ import annotations

import contextlib
import errno
import re
import subprocess
from pathlib import Path

import pytest

from .conftest import assert_fatal, assert_nothing_half_written


@contextlib.contextmanager
def tmpfs(mountpoint: Path, options: str):
    """A tmpfs mounted at ``mountpoint`` (None if this system does not allow mounting)."""
    mountpoint.mkdir(parents=True, exist_ok=True)
    done = subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(mountpoint)],
                          capture_output=True)
    try:
        yield mountpoint if done.returncode == 0 else None
    finally:
        if done.returncode == 0:
            subprocess.run(["umount", "-l", str(mountpoint)], check=True)  # lazy: files may be open


def test_disk_fills_up_during_a_write(survey, tmp_path, process, monkeypatch):
    with tmpfs(tmp_path / "small", "size=96k") as mnt:
        if mnt is None:  # no mount allowed: the OS error a full disk gives, at the rename
            import clearfast_gis.atomic as atomic

            real = atomic.os.replace

            def full(src, dst):
                if str(dst).endswith(".tif"):
                    raise OSError(errno.ENOSPC, "No space left on device")
                return real(src, dst)

            monkeypatch.setattr(atomic.os, "replace", full)
            products = tmp_path / "products"
        else:
            products = mnt / "products"
        result = process(survey, products)
        assert_fatal(result, f"{products / 'mosaics'}/scan_")
        line = result[2].strip()
        assert re.fullmatch(r".*/mosaics/scan_\d{3}\.tif: no space left on device", line), line
        assert_nothing_half_written(products)
        assert not Path(line.split(": ")[2]).exists()  # the mosaic that did not fit


def test_products_folder_under_a_regular_file(survey, tmp_path, process):
    (tmp_path / "report.txt").write_text("a file, not a folder")
    products = tmp_path / "report.txt" / "products"
    assert_fatal(process(survey, products), f"{products}: cannot write the products folder: "
                 "Not a directory")


def test_read_only_products_folder(survey, tmp_path, process):
    with tmpfs(tmp_path / "ro", "ro,size=64k") as mnt:
        products = (mnt or tmp_path / "ro") / "products"
        if mnt is None:  # no mount allowed: the same OS error at the folder's creation
            import clearfast_gis.pipeline.state as state

            def refuse(*args, **kwargs):
                raise OSError(errno.EROFS, "Read-only file system")

            with pytest.MonkeyPatch.context() as mp:
                mp.setattr(state.Path, "mkdir", refuse)
                result = process(survey, products)
        else:
            result = process(survey, products)
        assert_fatal(result, f"{products}: cannot write the products folder: not writable "
                     "(permission denied or read-only)")
        assert not products.exists()
