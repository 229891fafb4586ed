"""Real camera files against independent decoders (the samples' manifest, item 6 of issue 20).

FLIR: every file's object temperature within 0.01 K of exiftool + Thermimage ``raw2temp`` (which
flirimageextractor and flirpy match within 0.0015 K) at the manifest's three pixels, with the
file's own ObjectDistance; the metadata (time, GPS, gimbal) as exiftool reads it. DJI: refused
with one line naming the file and model.
"""

from __future__ import annotations

import dataclasses
from datetime import datetime

import numpy as np
import pytest

from clearfast_gis.cameras import read_frames
from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry.flir import object_temperature_c
from tests.cameras.conftest import entries, frame_of, reference_pixels, sample

FLIR = entries("flir_rjpeg", "flir_fff")


@pytest.mark.parametrize("entry", FLIR)
def test_flir_object_temperature_matches_references(entry):
    frame = frame_of(entry)
    assert frame.shape == (entry["raw"]["height"], entry["raw"]["width"])
    t = frame.object_temperature_c()
    assert t.dtype == np.float32
    for name, px in reference_pixels(entry).items():
        assert int(frame.raw[px["row"], px["col"]]) == px["raw"], name
        assert abs(float(t[px["row"], px["col"]]) - px["temp_C"]) < 0.01, name
    ref = next(iter(entry["reference_temps"].values()))
    assert np.nanmin(t) == pytest.approx(ref["image_min_C"], abs=0.01)
    assert np.nanmax(t) == pytest.approx(ref["image_max_C"], abs=0.01)


@pytest.mark.parametrize("entry", FLIR)
def test_flir_parameters_and_transmittance(entry):
    frame = frame_of(entry)
    p, pl, ref = frame.object_params, frame.planck, entry["params"]
    assert (pl.r1, pl.r2, pl.b, pl.f, pl.o) == pytest.approx(
        (ref["PlanckR1"], ref["PlanckR2"], ref["PlanckB"], ref["PlanckF"], ref["PlanckO"]))
    assert p.distance_m == pytest.approx(ref["ObjectDistance"])
    assert p.rh_pct == pytest.approx(ref["RelativeHumidity_percent"])
    # the manifest states tau of each half path (raw2temp's tau1 = tau2)
    assert p.half_path_transmittance() == pytest.approx(ref["atmospheric_transmission_tau"],
                                                        abs=1e-9)


@pytest.mark.parametrize("entry", FLIR)
def test_flir_uncorrected_blackbody_temperature(entry):
    """The bare Planck inversion (no emissivity, atmosphere) matches the manifest too."""
    frame = frame_of(entry)
    for name, px in reference_pixels(entry).items():
        t = float(frame.planck.temperature_k(px["raw"])) - 273.15
        assert t == pytest.approx(px["temp_C_blackbody_uncorrected"], abs=1e-3), name


def test_object_distance_not_subject_distance_sets_the_atmosphere():
    """The Zenmuse XT file (ObjectDistance 20 m): a 1 m path instead is off by far more than
    the 0.01 K tolerance, so the test above does depend on reading the right distance."""
    entry = next(e.values[0] for e in FLIR if "zenmuse_xtr" in e.id)
    frame = frame_of(entry)
    near = dataclasses.replace(frame.object_params, distance_m=1.0)
    px = reference_pixels(entry)["max"]
    raw = frame.raw[px["row"], px["col"]]
    assert abs(float(object_temperature_c(raw, frame.planck, near)) - px["temp_C"]) > 0.3


@pytest.mark.parametrize("entry", FLIR + entries("radiometric_tiff"))
def test_time_and_gps_tags(entry):
    frame = frame_of(entry, entry["params"].get("scale_K_per_count"))
    tags = entry["time_gps_gimbal_tags"]
    stamp = tags.get("FLIR:DateTimeOriginal") or tags.get("ExifIFD:DateTimeOriginal")
    if stamp:
        assert frame.time == datetime.fromisoformat(
            stamp.replace(":", "-", 2)[:19] + stamp[19:])
    lat = tags.get("Composite:GPSLatitude", tags.get("FLIR:GPSLatitude"))
    if lat is not None:
        assert frame.gps[0] == pytest.approx(lat)
        assert frame.gps[1] == pytest.approx(tags.get("Composite:GPSLongitude",
                                                      tags.get("FLIR:GPSLongitude")))
    else:
        assert frame.gps is None
    if "XMP-drone-dji:GimbalYawDegree" in tags:
        assert frame.gimbal.yaw_deg == pytest.approx(float(tags["XMP-drone-dji:GimbalYawDegree"]))
        assert frame.gimbal.pitch_deg == pytest.approx(
            float(tags["XMP-drone-dji:GimbalPitchDegree"]))


@pytest.mark.parametrize("entry", entries("radiometric_tiff"))
def test_linear_tiff_matches_reference(entry):
    frame = frame_of(entry, scale_k=entry["params"]["scale_K_per_count"])
    assert frame.format == "tlinear-tiff"
    t = frame.object_temperature_c()
    for name, px in reference_pixels(entry).items():
        assert int(frame.raw[px["row"], px["col"]]) == px["counts"], name
        assert float(t[px["row"], px["col"]]) == pytest.approx(px["temp_C"], abs=1e-4), name


@pytest.mark.parametrize("entry", entries("radiometric_tiff"))
def test_linear_tiff_without_scale_is_refused(entry):
    path = sample(entry)
    with pytest.raises(InvalidInput, match="without a stated scale") as err:
        read_frames(path)
    assert str(path) in str(err.value)


@pytest.mark.parametrize("entry", entries("dji_rjpeg"))
def test_dji_rjpeg_is_refused_with_the_model(entry):
    path = sample(entry)
    with pytest.raises(InvalidInput, match="DJI radiometric JPEG") as err:
        read_frames(path)
    assert str(path) in str(err.value) and entry["camera"]["Model"] in str(err.value)
