"""Writers of the simulated survey's ground truth (``truth/``), a fixed interface.

- ``objects.csv``: ``id,kind,x,y,depth_m,diameter_m,diffusivity_m2s,height_m,material,
  surface_material,polarity,x_local_m,y_local_m`` (x, y in the survey CRS, metres;
  polarity is the expected day-time contrast sign of the object: ``hot``, ``cold`` or
  ``mixed``).
- ``apparent_temperature/scan_NNN.tif``: float32 GeoTIFF, degrees C, band 0's apparent
  temperature (surface-leaving radiance inverted through Planck) on the area grid.
- ``poses.csv``: true camera pose per frame
  ``scan,position,band,time_utc,e_m,n_m,z_m,azimuth_deg,elevation_deg,roll_deg,pitch_deg,
  yaw_deg``.
- ``bands.csv``: ``band,name,lambda_min_um,lambda_max_um,shift_u_px,shift_v_px``
  (filter-wheel misregistration of each band's frames with respect to its nominal pointing).
"""

from __future__ import annotations

import csv
import io
import os
from pathlib import Path

import numpy as np
import rasterio
from rasterio.transform import Affine

from clearfast_gis.atomic import atomic_path, write_text
from clearfast_gis.simulate.config import Band
from clearfast_gis.simulate.objects import SceneObject
from clearfast_gis.simulate.scene import GridSpec
from clearfast_gis.simulate.surface import (
    OBJECT_SURFACE,
    object_diffusivity_m2s,
    object_material,
)
from clearfast_gis.timeutil import format_utc

OBJECT_COLUMNS = ("id", "kind", "x", "y", "depth_m", "diameter_m", "diffusivity_m2s",
                  "height_m", "material", "surface_material", "polarity", "x_local_m",
                  "y_local_m")
POSE_COLUMNS = ("scan", "position", "band", "time_utc", "e_m", "n_m", "z_m", "azimuth_deg",
                "elevation_deg", "roll_deg", "pitch_deg", "yaw_deg")


def _csv_text(header: tuple[str, ...], rows: list[list]) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    w.writerows(rows)
    return buf.getvalue()


def _polarity(obj: SceneObject) -> str:
    if obj.kind in ("at_mine", "ap_mine", "disturbed_soil"):
        return "hot"
    if obj.kind == "vegetation":
        return "cold"
    if obj.kind == "marker":
        return "hot" if obj.variant != "cold" else "cold"
    return "mixed"


def write_objects(path: str | os.PathLike, objects: list[SceneObject],
                  origin_m: tuple[float, float]) -> Path:
    """Write ``truth/objects.csv`` (positions in the survey CRS)."""
    rows = []
    for o in objects:
        alpha = object_diffusivity_m2s(o)
        material = object_material(o)
        surface = OBJECT_SURFACE.get(o.kind, {"marker": f"marker_{o.variant or 'hot'}",
                                              "disturbed_soil": "disturbed_soil"}.get(
                                                  o.kind, "vegetation"))
        if o.kind in OBJECT_SURFACE and o.depth_m > 0:
            surface = "soil"
        rows.append([o.id, o.kind, f"{o.x_m + origin_m[0]:.3f}", f"{o.y_m + origin_m[1]:.3f}",
                     f"{o.depth_m:.3f}", f"{o.diameter_m:.3f}",
                     "" if not np.isfinite(alpha) else f"{alpha:.4g}", f"{o.height_m:.3f}",
                     material, surface, _polarity(o), f"{o.x_m:.3f}", f"{o.y_m:.3f}"])
    return write_text(path, _csv_text(OBJECT_COLUMNS, rows))


def write_poses(path: str | os.PathLike, rows: list[tuple]) -> Path:
    """Write ``truth/poses.csv`` from rows (scan, position, band, time_s, pose, rpy)."""
    out = []
    for scan, pos, band, t, pose in rows:
        e, n, z = pose.position_m
        r, p, y = pose.attitude_rpy_deg
        out.append([scan, pos, band, format_utc(t), f"{e:.4f}", f"{n:.4f}", f"{z:.4f}",
                    f"{pose.azimuth_deg:.5f}", f"{pose.elevation_deg:.5f}", f"{r:.5f}",
                    f"{p:.5f}", f"{y:.5f}"])
    return write_text(path, _csv_text(POSE_COLUMNS, out))


def write_bands(path: str | os.PathLike, bands: tuple[Band, ...]) -> Path:
    """Write ``truth/bands.csv`` (band limits and filter-wheel misregistration)."""
    rows = [[i, b.name, b.lambda_min_um, b.lambda_max_um, b.shift_px[0], b.shift_px[1]]
            for i, b in enumerate(bands)]
    return write_text(path, _csv_text(("band", "name", "lambda_min_um", "lambda_max_um",
                                       "shift_u_px", "shift_v_px"), rows))


def write_temperature_tif(path: str | os.PathLike, temp_c: np.ndarray, grid: GridSpec,
                          description: str) -> Path:
    """Write a float32 single-band GeoTIFF (degrees C, NaN nodata) on ``grid``, atomically."""
    data = np.asarray(temp_c, np.float32)
    profile = {
        "driver": "GTiff", "width": grid.width, "height": grid.height, "count": 1,
        "dtype": "float32", "crs": f"EPSG:{grid.epsg}", "nodata": float("nan"),
        "transform": Affine(grid.pixel_size, 0.0, grid.x0, 0.0, -grid.pixel_size, grid.y0),
        "compress": "deflate", "predictor": 3, "tiled": True, "blockxsize": 256,
        "blockysize": 256,
    }
    with atomic_path(path) as tmp, rasterio.open(tmp, "w", **profile) as dst:
        dst.write(data, 1)
        dst.set_band_description(1, description)
        dst.update_tags(1, units="degC")
    return Path(path)
