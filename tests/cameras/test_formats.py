"""Camera formats on constructed files: SEQ records, CSQ's JPEG-LS raw, PNG byte order, linear
and temperature TIFFs (tags, units, physical range), bad input, the FLIR formula's inverse."""

from __future__ import annotations

import io

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.cameras import read_frames
from clearfast_gis.cameras.flir import decode_raw, split_records
from clearfast_gis.cameras.tags import parse_time
from clearfast_gis.cameras.tiff import write_tiff
from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry.flir import (
    FlirObjectParams,
    FlirPlanck,
    object_temperature_c,
    raw_from_object_temperature_c,
)
from tests.cameras.conftest import entries, frame_of, sample

PLANCK = FlirPlanck(r1=17096.453125, r2=0.0480847954750061, b=1428.0, f=1.0, o=-370.0)


def params(**kw) -> FlirObjectParams:
    base = dict(emissivity=0.95, reflected_c=20.0, atmosphere_c=25.0, distance_m=20.0,
                rh_pct=60.0, window_c=20.0, window_transmission=1.0, x=1.9,
                alpha1=0.006569, alpha2=0.01262, beta1=-0.002276, beta2=-0.00667)
    base.update(kw)
    return FlirObjectParams(**base)


@settings(max_examples=60, deadline=None)
@given(t=st.floats(-20.0, 80.0), e=st.floats(0.5, 1.0), d=st.floats(0.0, 100.0),
       irt=st.floats(0.6, 1.0))
def test_flir_formula_inverse_round_trip(t, e, d, irt):
    p = params(emissivity=e, distance_m=d, window_transmission=irt)
    raw = raw_from_object_temperature_c(t, PLANCK, p)
    assert float(object_temperature_c(raw, PLANCK, p)) == pytest.approx(t, abs=1e-6)


def test_blackbody_at_no_distance_reads_its_own_temperature():
    p = params(emissivity=1.0, distance_m=0.0)
    raw = PLANCK.signal(np.array([273.15, 310.0]))
    np.testing.assert_allclose(object_temperature_c(raw, PLANCK, p), [0.0, 36.85], atol=1e-9)


def test_not_physical_parameters_are_refused():
    with pytest.raises(InvalidInput, match="emissivity"):
        params(emissivity=0.0)
    with pytest.raises(InvalidInput, match="rh_pct"):
        params(rh_pct=150.0)


@given(st.datetimes(min_value=__import__("datetime").datetime(1990, 1, 1)),
       st.sampled_from(["", "+02:00", "-05:30", "Z"]))
def test_exif_time_round_trip(dt, zone):
    dt = dt.replace(microsecond=dt.microsecond // 1000 * 1000)
    text = dt.strftime("%Y:%m:%d %H:%M:%S.") + f"{dt.microsecond // 1000:03d}" + zone
    got = parse_time(text, "f.jpg", "DateTimeOriginal")
    assert got.replace(tzinfo=None) == dt
    assert (got.tzinfo is None) == (zone == "")


def test_bad_exif_time_names_file_and_tag():
    with pytest.raises(InvalidInput, match="f.jpg: DateTimeOriginal: not an EXIF time"):
        parse_time("yesterday", "f.jpg", "DateTimeOriginal")


@pytest.mark.parametrize("entry", entries("flir_fff"))
def test_seq_file_is_split_into_its_frames(entry, tmp_path):
    one = sample(entry).read_bytes()
    seq = tmp_path / "flight.seq"
    seq.write_bytes(one + one + one)
    assert len(split_records(seq.read_bytes())) == 3
    frames = read_frames(seq, frame=2)
    assert [f.index for f in frames] == [2] and frames[0].format == "flir-seq"
    np.testing.assert_array_equal(frames[0].raw, frame_of(entry).raw)
    with pytest.raises(InvalidInput, match=r"frame 3 does not exist \(the file holds 3 frames"):
        read_frames(seq, frame=3)


def test_magic_inside_image_data_does_not_split_a_record():
    rec = b"FFF\0" + b"FLIR".ljust(16, b"\0") + (100).to_bytes(4, "big") + b"\x00" * 8
    data = rec + b"..FFF\0garbage-not-a-header" + rec
    assert len(split_records(data)) == 2


def test_csq_jpeg_ls_raw_decodes_losslessly():
    import imagecodecs

    raw = (np.arange(60 * 80, dtype=np.uint16).reshape(60, 80) * 13 + 9000).astype(np.uint16)
    blob = imagecodecs.jpegls_encode(raw)
    np.testing.assert_array_equal(decode_raw(blob, "JPEG-LS", 80, 60, "x.csq"), raw)


def test_png_raw_is_byte_swapped_back():
    from PIL import Image

    raw = np.array([[0x1234, 0x00FF], [0xABCD, 7]], dtype=np.uint16)
    buf = io.BytesIO()
    Image.fromarray(raw.byteswap()).save(buf, format="PNG")
    np.testing.assert_array_equal(decode_raw(buf.getvalue(), "PNG", 2, 2, "x.jpg"), raw)


def test_corrupt_raw_is_one_error_naming_the_file():
    with pytest.raises(InvalidInput, match="x.jpg: FLIR:RawThermalImage: .*cannot be decoded"):
        decode_raw(b"\x89PNG garbage", "PNG", 2, 2, "x.jpg")


def test_linear_tiff_tags_round_trip(tmp_path):
    counts = np.array([[7000, 7500], [8000, 6500]], dtype=np.uint16)
    write_tiff(tmp_path / "t.tif", counts, "K", scale=0.04)
    frame, = read_frames(tmp_path / "t.tif")
    assert frame.format == "tlinear-tiff"
    np.testing.assert_allclose(frame.object_temperature_c(), counts * 0.04 - 273.15, atol=1e-4)


@pytest.mark.parametrize("unit,offset", [("degC", 0.0), ("K", -273.15)])
def test_temperature_tiff_units(tmp_path, unit, offset):
    t_c = np.array([[12.5, 30.0], [-5.25, 45.0]], dtype=np.float32)
    write_tiff(tmp_path / "t.tif", (t_c - offset).astype(np.float32), unit)
    frame, = read_frames(tmp_path / "t.tif")
    assert frame.format == "temperature-tiff"
    np.testing.assert_allclose(frame.object_temperature_c(), t_c, atol=1e-4)


def test_temperature_tiff_without_unit_is_refused(tmp_path):
    import tifffile

    tifffile.imwrite(tmp_path / "t.tif", np.full((4, 4), 20.0, dtype=np.float32))
    with pytest.raises(InvalidInput, match="t.tif: float TIFF without a stated unit"):
        read_frames(tmp_path / "t.tif")
    frame, = read_frames(tmp_path / "t.tif", unit="C")
    assert float(frame.object_temperature_c()[0, 0]) == pytest.approx(20.0)


def test_kelvin_stated_as_celsius_is_not_physical(tmp_path):
    import tifffile

    tifffile.imwrite(tmp_path / "t.tif", np.full((4, 4), 293.0, dtype=np.float32))
    with pytest.raises(InvalidInput, match="not physical"):
        read_frames(tmp_path / "t.tif", unit="C")


def test_jpeg_without_radiometric_data_is_refused(tmp_path):
    from PIL import Image

    Image.fromarray(np.zeros((8, 8), np.uint8)).save(tmp_path / "photo.jpg")
    with pytest.raises(InvalidInput, match="photo.jpg: no radiometric data"):
        read_frames(tmp_path / "photo.jpg")


@pytest.mark.parametrize("kind", ["fff", "jpg"])
def test_written_flir_files_read_back_through_exiftool(tmp_path, kind):
    from datetime import UTC, datetime

    from clearfast_gis.cameras.flir_write import fff_bytes, write_fff, write_rjpeg

    raw = (np.arange(60 * 80).reshape(60, 80) % 900 + 3000).astype(np.uint16)
    p = params(emissivity=0.9, distance_m=12.0, rh_pct=40.0)
    when = datetime(2026, 11, 15, 6, 30, 1, 250000, tzinfo=UTC)
    record = fff_bytes(raw, PLANCK, p, when, fov_deg=24.0)
    path = tmp_path / f"f.{kind}"
    if kind == "fff":
        write_fff(path, record)
    else:
        write_rjpeg(path, record, (raw // 16).astype(np.uint8))
    frame, = read_frames(path)
    assert frame.format == ("flir-fff" if kind == "fff" else "flir-rjpeg")
    np.testing.assert_array_equal(frame.raw, raw)
    assert frame.planck == PLANCK and frame.time == when
    got, want = frame.object_params, p
    for name in ("emissivity", "distance_m", "rh_pct", "reflected_c", "atmosphere_c"):
        assert getattr(got, name) == pytest.approx(getattr(want, name), abs=1e-4), name
    # float32 storage of the parameters moves the object temperature by far under 0.01 K
    np.testing.assert_allclose(frame.object_temperature_c(),
                               object_temperature_c(raw, PLANCK, p), atol=1e-3)


def test_twin_flir_frames_keep_the_at_sensor_temperature(tmp_path):
    from clearfast_gis.simulate.camera_files import TWIN_FLIR_PLANCK, write_frame
    from clearfast_gis.timeutil import parse_utc

    t_k = 285.0 + np.linspace(0.0, 30.0, 128 * 160).reshape(128, 160)
    t_s = parse_utc("2026-11-15T12:00:00.500Z")
    name = write_frame(tmp_path, "a", t_k, "flir-rjpeg", t_s)
    frame, = read_frames(tmp_path / name)
    back = TWIN_FLIR_PLANCK.temperature_k(frame.raw)
    assert np.max(np.abs(back - t_k)) < 0.015  # half a count at ~50 counts per K
    assert frame.time.timestamp() == pytest.approx(t_s, abs=1e-3)
