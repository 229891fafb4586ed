"""``clearfast thermal-frame``: the camera's own object temperature as a degrees C TIFF."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
import rasterio

from tests.cameras.conftest import entries, frame_of, reference_pixels, sample

pytestmark = pytest.mark.filterwarnings("ignore::rasterio.errors.NotGeoreferencedWarning")


def run(*args) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "clearfast_gis.cli.main", "thermal-frame",
                           *map(str, args)], capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize("entry", [e for e in entries("flir_rjpeg") if "zenmuse" in e.id])
def test_writes_degrees_c_tiff_matching_references(entry, tmp_path):
    out = tmp_path / "t.tif"
    r = run(sample(entry), "-o", out)
    assert r.returncode == 0, r.stderr
    with rasterio.open(out) as src:
        t = src.read(1)
        assert src.dtypes[0] == "float32" and src.units[0] == "degC"
    assert t.shape == frame_of(entry).shape  # orientation of the stored raw image
    for px in reference_pixels(entry).values():
        assert abs(float(t[px["row"], px["col"]]) - px["temp_C"]) < 0.01


@pytest.mark.parametrize("entry", entries("flir_fff"))
def test_multi_frame_file_takes_frame(entry, tmp_path):
    seq = tmp_path / "a.seq"
    seq.write_bytes(sample(entry).read_bytes() * 2)
    r = run(seq, "-o", tmp_path / "t.tif")
    assert r.returncode == 2 and "choose one with --frame N" in r.stderr
    r = run(seq, "--frame", 1, "-o", tmp_path / "t.tif")
    assert r.returncode == 0, r.stderr
    with rasterio.open(tmp_path / "t.tif") as src:
        np.testing.assert_allclose(src.read(1), frame_of(entry).object_temperature_c())


@pytest.mark.parametrize("entry", entries("dji_rjpeg")[:1])
def test_bad_input_is_one_line_and_nothing_written(entry, tmp_path):
    out = tmp_path / "t.tif"
    r = run(sample(entry), "-o", out)
    assert r.returncode == 1 and "Traceback" not in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and str(sample(entry)) in r.stderr
    assert list(tmp_path.iterdir()) == []
