"""``clearfast calibrate``: raw frames to apparent temperature, one TIFF stack per scan and band.

Output: ``OUT/apparent_temperature/scan_NNN_bB.tif``, float32 degrees C, one page per frame in
position order, NaN where a pixel could not be calibrated; and
``OUT/apparent_temperature/calibration.json`` recording the options, the bands (events, whether
the atmospheric correction applies) and each stack's invalid-pixel count.
"""

from __future__ import annotations

import json
from pathlib import Path

import click
import numpy as np

from clearfast_gis.atomic import atomic_path, write_text
from clearfast_gis.cli.options import (
    make_progress,
    products_opt,
    progress_opt,
    resume_opt,
    survey_arg,
)

OUT_DIR = "apparent_temperature"


def output_name(scan: int, band: int) -> str:
    """File name of the apparent-temperature stack of ``scan`` and ``band``."""
    return f"scan_{int(scan):03d}_b{int(band)}.tif"


def _write_stack_c(path: Path, stack_k: np.ndarray, description: str) -> None:
    import tifffile

    data = (stack_k - np.float32(273.15)).astype(np.float32, copy=False)
    with atomic_path(path) as tmp:
        tifffile.imwrite(tmp, data, photometric="minisblack", description=description,
                         metadata=None)


@click.command("calibrate", short_help="Radiometric calibration to apparent temperature.")
@survey_arg
@products_opt
@click.option("--band", "bands", multiple=True,
              help="Band name or index (repeatable); default: every band.")
@click.option("--mode", type=click.Choice(["interpolate", "nearest"]), default="interpolate",
              show_default=True,
              help="Calibration event per frame: interpolated between the bracketing events, "
                   "or the nearest one.")
@click.option("--path-length-m", type=click.FloatRange(0.0, 1000.0), default=20.0,
              show_default=True, help="Camera-to-surface path for the atmospheric correction.")
@click.option("--min-contrast-counts", type=click.FloatRange(0.0, min_open=True), default=4.0,
              show_default=True,
              help="Pixels whose two blackbody means differ by less are left uncalibrated (NaN).")
@progress_opt
@resume_opt
def command(survey: str, products: str, bands: tuple[str, ...], mode: str, path_length_m: float,
            min_contrast_counts: float, progress_mode: str, resume: bool) -> None:
    """Calibrate SURVEY's raw frames to apparent temperature (degrees C) in OUTPUT.

    Two-blackbody calibration per pixel (Eq. 1), atmospheric correction from the weather log
    (Eq. 4) and inversion of the band Planck integral (Eq. 5).
    """
    from clearfast_gis.radiometry.stage import (
        apparent_temperature_scan,
        calibration_events,
        has_transmittance_model,
    )
    from clearfast_gis.survey import read_survey, read_toa5

    srv = read_survey(survey)
    band_ids = sorted({srv.band_index(int(b) if b.isdigit() else b) for b in bands}) if bands \
        else list(range(len(srv.bands)))
    out_dir = Path(products) / OUT_DIR
    progress = make_progress(progress_mode)
    events = calibration_events(srv)
    weather = read_toa5(srv.path("weather"), srv.label("weather"), srv.station_profile)
    scans = [int(s) for s in srv.scans]
    jobs = [(s, b) for s in scans for b in band_ids]
    todo = [(s, b) for s, b in jobs if not (resume and (out_dir / output_name(s, b)).exists())]
    n_frames = sum(srv.scan_rows(s, b).size for s, b in todo)
    summary: dict = {"format": "clearfast-calibration", "format_version": 1, "mode": mode,
                     "path_length_m": path_length_m, "min_contrast_counts": min_contrast_counts,
                     "units": "degC", "bands": [], "scans": []}
    for b in band_ids:
        info = srv.bands[b]
        own = srv.radiometry is not None  # a radiometric camera: no blackbody events
        band_events = [] if own else [e for e in events if e.band == b]
        entry = {"index": b, "name": info.name, "lambda_min_um": info.lambda_min_um,
                 "lambda_max_um": info.lambda_max_um, "n_events": len(band_events),
                 "calibration": f"camera radiometry ({srv.radiometry.kind})" if own
                 else "two blackbodies",
                 "atmospheric_correction": has_transmittance_model(info.lambda_min_um,
                                                                   info.lambda_max_um)}
        if not entry["atmospheric_correction"]:
            progress.message(f"band {info.name}: no transmittance model for "
                             f"{info.lambda_min_um}-{info.lambda_max_um} um; "
                             "atmospheric correction not applied")
        summary["bands"].append(entry)
    progress.start("calibrate", n_frames)
    for s, b in jobs:
        path = out_dir / output_name(s, b)
        if (s, b) not in todo:
            summary["scans"].append({"scan": s, "band": b, "file": path.name, "skipped": True})
            continue
        t_k = apparent_temperature_scan(srv, s, b, events, weather, path_length_m, mode,
                                        min_contrast_counts, progress)
        _write_stack_c(path, t_k, f"clearfast apparent temperature degC scan {s} "
                                  f"band {srv.bands[b].name}")
        summary["scans"].append({
            "scan": s, "band": b, "file": path.name, "frames": int(t_k.shape[0]),
            "invalid_pixels": int(np.isnan(t_k).sum()),
            "mean_c": float(np.nanmean(t_k) - 273.15) if np.isfinite(t_k).any() else None})
    progress.close()
    write_text(out_dir / "calibration.json", json.dumps(summary, indent=1) + "\n")
