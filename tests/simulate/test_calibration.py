"""Frames calibrated with the simulated blackbodies return the true apparent temperatures."""

from __future__ import annotations

import csv

import numpy as np
import pytest
import rasterio

from clearfast_gis.geometry import camera_from_manifest
from clearfast_gis.geometry.pose import CameraPose
from clearfast_gis.radiometry.atmosphere import atmospheric_transmittance, correct_atmosphere
from clearfast_gis.radiometry.calibration import calibrate_two_point
from clearfast_gis.radiometry.table import BandTable
from clearfast_gis.survey import read_blackbody_frames, read_blackbody_log, read_survey, read_toa5
from clearfast_gis.timeutil import parse_utc
from clearfast_gis.units import ZERO_CELSIUS_K


def _poses(root) -> dict:
    out = {}
    with open(root / "truth" / "poses.csv") as fh:
        for r in csv.DictReader(fh):
            pose = CameraPose(np.array([float(r["e_m"]), float(r["n_m"]), float(r["z_m"])]),
                              float(r["azimuth_deg"]), float(r["elevation_deg"]),
                              (float(r["roll_deg"]), float(r["pitch_deg"]),
                               float(r["yaw_deg"])))
            out[(int(r["scan"]), int(r["position"]), int(r["band"]))] = (
                pose, parse_utc(r["time_utc"]))
    return out


@pytest.mark.parametrize("scan", [0, 2, 4])
def test_calibrated_frames_match_truth(demo_survey, scan):
    """Eq. 1 with the logged blackbody temperatures, then Eq. 4 with the weather log and the
    slant range, gives the truth grid's apparent temperature within the NETD (0.05 K)."""
    root = demo_survey.root
    sv = read_survey(root)
    cam = camera_from_manifest(sv.manifest["camera"])
    band = sv.bands[0]
    table = BandTable(band.lambda_min_um, band.lambda_max_um)
    event = next(e for e in read_blackbody_frames(sv) if e.event == scan and e.band == 0)
    bbl = read_blackbody_log(sv.path("blackbody_log"))
    t1 = np.interp(event.bb1_time_s, bbl.time_s, bbl.bb1_c) + ZERO_CELSIUS_K
    t2 = np.interp(event.bb2_time_s, bbl.time_s, bbl.bb2_c) + ZERO_CELSIUS_K
    wx = read_toa5(sv.path("weather"))
    poses = _poses(root)
    with rasterio.open(root / "truth" / "apparent_temperature" / f"scan_{scan:03d}.tif") as src:
        truth = src.read(1)
        transform = src.transform
    errors = []
    for p in range(0, demo_survey.n_positions, 2):
        raw = sv.read_frame(scan, p, 0)
        radiance, valid = calibrate_two_point(raw, event.bb1_mean, event.bb2_mean,
                                              table.radiance(t1), table.radiance(t2))
        assert valid.all()
        pose, t = poses[(scan, p, 0)]
        vv, uu = np.mgrid[0:cam.height, 0:cam.width]
        ground = cam.ground_points(uu.ravel(), vv.ravel(), pose)
        range_m = np.linalg.norm(ground - pose.position_m, axis=1).reshape(raw.shape)
        air_k = np.interp(t, wx.time_s, wx.air_temp_c) + ZERO_CELSIUS_K
        tau = atmospheric_transmittance(range_m, air_k, np.interp(t, wx.time_s, wx.rh_pct),
                                        np.interp(t, wx.time_s, wx.pressure_hpa),
                                        band.lambda_min_um, band.lambda_max_um)
        assert 0.9 < tau.min() < tau.max() < 1.0
        t_app = table.temperature(correct_atmosphere(radiance, tau, air_k, table))
        rows, cols = rasterio.transform.rowcol(transform, ground[:, 0], ground[:, 1])
        rows, cols = np.asarray(rows), np.asarray(cols)
        inside = (rows >= 0) & (rows < truth.shape[0]) & (cols >= 0) & (cols < truth.shape[1])
        err = t_app.ravel()[inside] - ZERO_CELSIUS_K - truth[rows[inside], cols[inside]]
        errors.append(err)
    err = np.concatenate(errors)
    assert err.size > 20000
    assert abs(np.median(err)) < 0.03  # bias: blackbody sensors 0.02 K, drift within a scan
    mad = np.median(np.abs(err - np.median(err)))
    assert mad < 0.07  # NETD 0.05 K (MAD of white noise: 0.034 K) plus footprint blur
    assert np.percentile(np.abs(err), 90) < 0.25


def test_raw_counts_are_uncalibrated(demo_survey):
    """Raw frames carry fixed-pattern non-uniformity that only the blackbodies remove."""
    sv = read_survey(demo_survey.root)
    event = next(e for e in read_blackbody_frames(sv) if e.event == 0 and e.band == 0)
    spread = np.std(event.bb2_mean) / (np.mean(event.bb1_mean) - np.mean(event.bb2_mean))
    assert spread > 0.05  # pixel-to-pixel offset spread > 0.5 K equivalent
    assert sv.read_frame(0, 0, 0).dtype == np.uint16
    assert sv.read_frame(0, 0, 0).max() < 2 ** 14
