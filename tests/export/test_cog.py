"""COG mosaics: round trip, GDAL's COG validation, tags, overviews, errors."""

from __future__ import annotations

import numpy as np
import pytest
import rasterio
from affine import Affine
from hypothesis import given
from hypothesis import strategies as st

from clearfast_gis.errors import InvalidInput
from clearfast_gis.export import band_description, mosaic_name, read_mosaic, write_cog
from clearfast_gis.export.cog import (
    default_overview_factors,
    keep_decoded,
    mosaic_stack,
    remove_decoded,
)
from clearfast_gis.export.layout import DECODED_REL, mosaic_rel
from clearfast_gis.timeutil import parse_utc

TRANSFORM = Affine(0.05, 0.0, 532780.0, 0.0, -0.05, 3891985.0)


@pytest.fixture()
def bands():
    rng = np.random.default_rng(1)
    arr = rng.normal(15.0, 3.0, size=(2, 300, 500)).astype(np.float32)
    arr[:, :40, :70] = np.nan
    return arr


def test_mosaic_stack_of_a_products_folder(tmp_path):
    """The scans' mosaics, in the order asked, read scan by scan as float32 (B, H, W)."""
    rng = np.random.default_rng(3)
    scans = [5, 2, 9]
    bands = {s: rng.normal(15.0 + s, 1.0, size=(2, 40, 60)).astype(np.float32) for s in scans}
    bands[2][1, :5, :7] = np.nan
    for s in scans:
        write_cog(tmp_path / mosaic_rel(s), bands[s], TRANSFORM, 32636, ["a", "b"],
                  {"CLEARFAST_SCAN": s})
    assert mosaic_rel(2) == f"mosaics/{mosaic_name(2)}" == "mosaics/scan_002.tif"
    stack = mosaic_stack(tmp_path, scans)
    assert (stack.n_scans, stack.n_bands, stack.shape) == (3, 2, (40, 60))
    assert stack.transform == TRANSFORM
    for k, s in enumerate(scans):
        got = stack.scan(k)
        assert got.dtype == np.float32
        np.testing.assert_array_equal(got, bands[s])


def test_mosaic_stack_decoded_once(tmp_path):
    """With ``decode_once`` a scan's COG is decoded at its first read and kept as raw float32
    in the run's scratch folder, shared by the stacks of the folder: every later read gives
    the COG's values bit for bit without decoding it (the COG may even be gone); the scratch
    is deleted by ``remove_decoded``."""
    rng = np.random.default_rng(4)
    scans = [3, 1]
    bands = {s: rng.normal(10.0 * s, 2.0, size=(2, 30, 50)).astype(np.float32) for s in scans}
    bands[1][0, 3:9, 4:6] = np.nan
    for s in scans:
        write_cog(tmp_path / mosaic_rel(s), bands[s], TRANSFORM, 32636, ["a", "b"])
    scratch = tmp_path / DECODED_REL
    stack = mosaic_stack(tmp_path, scans, decode_once=True)
    assert stack.decoded == scratch and scratch.is_dir() and not any(scratch.iterdir())
    np.testing.assert_array_equal(stack.scan(1), bands[1])
    assert sorted(p.name for p in scratch.iterdir()) == ["scan_001.f32"]
    (tmp_path / mosaic_rel(1)).unlink()  # read back from the scratch, not decoded again
    other = mosaic_stack(tmp_path, scans, decode_once=True)  # header of scan 3
    for stk in (stack, other):
        for k, s in enumerate(scans):
            got = stk.scan(k)
            assert got.dtype == np.float32 and got.shape == (2, 30, 50)
            np.testing.assert_array_equal(got, bands[s])
    assert sorted(p.name for p in scratch.iterdir()) == ["scan_001.f32", "scan_003.f32"]
    remove_decoded(tmp_path)
    assert not scratch.exists()
    remove_decoded(tmp_path)  # nothing to delete: no error


def test_decoded_copy_kept_at_the_write_is_the_cogs_bytes(tmp_path):
    """The copy a writer keeps with ``keep_decoded`` (the scan job, after each COG) holds the
    bytes that decoding the COG gives, NaN payloads and signed zeros included, and a
    ``decode_once`` stack reads it instead of decoding the COG."""
    rng = np.random.default_rng(8)
    bands = rng.normal(12.0, 4.0, size=(3, 70, 90)).astype(np.float32)
    bands[0, :9, :11] = np.nan
    bands[1, 5, 5:9] = [0.0, -0.0, np.inf, -np.inf]
    bands[2, 60:, 80:] = np.float32(np.nan) * -1  # a NaN with the sign bit
    rel = mosaic_rel(4)
    write_cog(tmp_path / rel, bands, TRANSFORM, 32636, ["a", "b", "c"])
    keep_decoded(tmp_path, rel, bands)
    kept = (tmp_path / DECODED_REL / "scan_004.f32").read_bytes()
    assert kept == read_mosaic(tmp_path / rel).bands_c.tobytes() == bands.tobytes()
    stack = mosaic_stack(tmp_path, [4], decode_once=True)
    (tmp_path / rel).rename(tmp_path / "elsewhere.tif")  # the header was read: no decoding
    assert stack.scan(0).tobytes() == bands.tobytes()


def test_a_rewritten_cog_never_keeps_its_old_copy(tmp_path, monkeypatch):
    """A COG written again (the attitude adjustment re-projects a scan) replaces its decoded
    copy; when the new copy cannot be written (disk full) the old one is gone too, so the
    stages after read the new COG, never the old values."""
    import errno
    import os

    from clearfast_gis.export import cog

    rel = mosaic_rel(2)
    first = np.full((1, 20, 30), 5.0, dtype=np.float32)
    second = np.full((1, 20, 30), 7.0, dtype=np.float32)
    write_cog(tmp_path / rel, first, TRANSFORM, 32636, ["a"])
    keep_decoded(tmp_path, rel, first)
    write_cog(tmp_path / rel, second, TRANSFORM, 32636, ["a"])
    keep_decoded(tmp_path, rel, second)
    stack = mosaic_stack(tmp_path, [2], decode_once=True)
    np.testing.assert_array_equal(stack.scan(0), second)

    def full(fd, *args, **kwargs):
        os.close(fd)
        raise OSError(errno.ENOSPC, "No space left on device")

    write_cog(tmp_path / rel, first, TRANSFORM, 32636, ["a"])
    with monkeypatch.context() as m:
        m.setattr(cog.os, "fdopen", full)
        keep_decoded(tmp_path, rel, first)
    assert list((tmp_path / DECODED_REL).iterdir()) == []
    np.testing.assert_array_equal(stack.scan(0), first)  # decoded from the COG


def test_mosaic_stack_decoded_once_without_room(tmp_path, monkeypatch):
    """A decoded copy that cannot be written (disk full) is not kept: the scan is decoded
    again at its next read, with the same values, and no partial file is left."""
    import errno

    bands = np.arange(2 * 20 * 30, dtype=np.float32).reshape(2, 20, 30)
    write_cog(tmp_path / mosaic_rel(0), bands, TRANSFORM, 32636, ["a", "b"])
    stack = mosaic_stack(tmp_path, [0], decode_once=True)

    import os

    from clearfast_gis.export import cog

    def full(fd, *args, **kwargs):  # the temporary file is made, then the disk is full
        os.close(fd)
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(cog.os, "fdopen", full)
    for _ in range(2):
        np.testing.assert_array_equal(stack.scan(0), bands)
    assert list((tmp_path / DECODED_REL).iterdir()) == []

def test_round_trip_values_crs_tags(tmp_path, bands):
    path = tmp_path / "mosaics" / mosaic_name(7)
    t_s = parse_utc("2026-11-15T12:30:00Z")
    descriptions = [band_description("LW1", 8.0, 9.2), band_description("LW2", 9.2, 10.5)]
    write_cog(path, bands, TRANSFORM, 32636, descriptions, {"CLEARFAST_SCAN": 7},
              scan_time_s=t_s)
    assert path.name == "scan_007.tif"
    m = read_mosaic(path)
    np.testing.assert_array_equal(m.bands_c, bands)  # lossless, NaN where NaN
    assert m.transform == TRANSFORM and m.epsg == 32636
    assert m.band_descriptions == ("LW1 8.0-9.2 um", "LW2 9.2-10.5 um")
    assert m.scan_time_s == t_s
    assert m.tags["CLEARFAST_SCAN_TIME_UTC"] == "2026-11-15T12:30:00Z"
    assert m.tags["TIFFTAG_DATETIME"] == "2026:11:15 12:30:00"
    assert m.tags["CLEARFAST_SCAN"] == "7"
    assert m.overview_factors == (2, 4)
    with rasterio.open(path) as ds:
        assert ds.dtypes == ("float32", "float32")
        assert np.isnan(ds.nodata)
        assert ds.block_shapes[0] == (256, 256)
        assert ds.units == ("deg C", "deg C")
        assert ds.tags(ns="IMAGE_STRUCTURE")["LAYOUT"] == "COG"
    assert [p.name for p in path.parent.iterdir()] == ["scan_007.tif"]  # no temp left


def test_valid_under_gdal_cog_rules(tmp_path, bands):
    from osgeo_utils.samples.validate_cloud_optimized_geotiff import validate

    path = tmp_path / "scan_000.tif"
    write_cog(path, bands[:1], TRANSFORM, 32636, ["LW1 8.0-9.2 um"], overview_levels=[2, 4, 8])
    warnings, errors, details = validate(str(path), full_check=True)
    assert errors == [] and warnings == []
    offsets = details["ifd_offsets"]
    assert set(offsets) == {"main", "overview_0", "overview_1", "overview_2"}
    # IFDs first (main, then overviews), image data of the smallest overview first
    assert offsets["main"] < offsets["overview_0"] < offsets["overview_2"]
    data = details["data_offsets"]
    assert data["overview_2"] < data["overview_1"] < data["overview_0"] < data["main"]


def test_overview_is_nan_aware_average(tmp_path):
    arr = np.full((1, 128, 128), 10.0, np.float32)
    arr[0, ::2, ::2] = np.nan  # one cell in four missing
    arr[0, 64:, :] = 20.0
    path = tmp_path / "a.tif"
    write_cog(path, arr, TRANSFORM, 32636, ["LW1 8.0-9.2 um"], overview_levels=[2])
    with rasterio.open(path) as ds:
        ov = ds.read(1, out_shape=(64, 64))
    assert np.nanmax(np.abs(ov[:32] - 10.0)) < 1e-5 and np.allclose(ov[32:], 20.0)


def test_grid_object_accepted(tmp_path):
    class Grid:
        x0, y0, pixel_size = 532780.0, 3891985.0, 0.05

    write_cog(tmp_path / "g.tif", np.zeros((4, 6), np.float32), Grid(), 32636, ["b"])
    assert read_mosaic(tmp_path / "g.tif").transform == TRANSFORM


@pytest.mark.parametrize(("kwargs", "field"), [
    ({"bands": np.zeros((2, 3, 4, 5))}, "bands"),
    ({"band_descriptions": ["a", "b"]}, "band_descriptions"),
    ({"overview_levels": [4, 2]}, "overview_levels"),
    ({"tags": {"CLEARFAST_SCAN_TIME_UTC": "noon"}}, "tags.CLEARFAST_SCAN_TIME_UTC"),
])
def test_bad_input_names_field(tmp_path, kwargs, field):
    args = {"bands": np.zeros((1, 8, 8), np.float32), "grid_transform": TRANSFORM, "epsg": 32636,
            "band_descriptions": ["LW1"], **kwargs}
    with pytest.raises(InvalidInput) as err:
        write_cog(tmp_path / "x.tif", **args)
    assert err.value.field == field
    assert not list(tmp_path.iterdir())


def test_read_missing_file(tmp_path):
    with pytest.raises(InvalidInput, match="cannot read"):
        read_mosaic(tmp_path / "nope.tif")


@given(st.integers(1, 20000), st.integers(1, 20000))
def test_overview_factors_property(h, w):
    f = default_overview_factors(h, w)
    assert f[0] == 2 and all(b == 2 * a for a, b in zip(f, f[1:], strict=False))
    if len(f) > 1:
        assert max(h, w) / f[-1] >= 64 > max(h, w) / (2 * f[-1])


def test_band_description_text():
    assert band_description("LW1", 8, 9.2) == "LW1 8.0-9.2 um"
