"""``--kernels reference`` runs the same chain on the reference libraries: same mosaics."""

from __future__ import annotations

import json

import numpy as np

from clearfast_gis.export.cog import read_mosaic
from clearfast_gis.pipeline import ProcessOptions, process_survey
from clearfast_gis.survey.subset import subset_survey


def test_reference_kernels_give_the_same_mosaics(demo_survey, tmp_path):
    survey = subset_survey(demo_survey, tmp_path / "survey", 2)
    runs = {}
    for k in ("fast", "reference"):
        opts = ProcessOptions(kernels=k, invert=False, attitude_samples=12)
        runs[k] = process_survey(survey, tmp_path / k, opts, until="residuals_and_footprint")
        assert runs[k]["resources"]["kernels"] == k
        assert runs[k]["parameters"]["kernels"] == k
    for scan in (0, 1):
        a = read_mosaic(tmp_path / "fast" / f"mosaics/scan_{scan:03d}.tif").bands_c
        b = read_mosaic(tmp_path / "reference" / f"mosaics/scan_{scan:03d}.tif").bands_c
        both = np.isfinite(a) & np.isfinite(b)
        assert both.sum() > 0.95 * np.isfinite(a).sum()
        assert float(np.sqrt(np.mean((a[both] - b[both]) ** 2))) < 0.05  # K
    fast_att = [s["attitude"]["attitude_rpy_deg"] for s in runs["fast"]["scans"]]
    ref_att = [s["attitude"]["attitude_rpy_deg"] for s in runs["reference"]["scans"]]
    # 12 ties per scan on two scans: the attitude is known to a few hundredths of a degree
    # (0.1 deg moves the ground by ~2 cm at the demo's 12 m range, one mosaic cell)
    np.testing.assert_allclose(fast_att, ref_att, atol=0.1)  # degrees
    stages = json.loads((tmp_path / "fast" / "products.json").read_text())["resources"]
    assert stages["stages"]["mosaics"]["cpu_s"] > 0
