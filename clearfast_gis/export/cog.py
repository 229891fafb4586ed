"""Cloud Optimized GeoTIFF mosaics: one file per scan, float32 degrees C, NaN nodata.

A mosaic is written with GDAL's COG driver (through rasterio), so the IFD order, tiling and
overviews follow GDAL's COG rules: the file validates with GDAL's
``validate_cloud_optimized_geotiff.py``. Band descriptions carry the band name and wavelengths
(``"LW1 8.0-9.2 um"``); the scan time is stored twice: as the TIFF ``DateTime`` tag and as the
ISO 8601 UTC metadata item ``CLEARFAST_SCAN_TIME_UTC``.
"""

from __future__ import annotations

import math
import os
import shutil
import tempfile
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path

import numpy as np
from affine import Affine

from clearfast_gis.atomic import atomic_path
from clearfast_gis.errors import InvalidInput
from clearfast_gis.export.layout import DECODED_REL, mosaic_rel
from clearfast_gis.parallel import n_threads
from clearfast_gis.timeutil import format_utc, parse_utc

SCAN_TIME_TAG = "CLEARFAST_SCAN_TIME_UTC"
"""Metadata item holding the scan time as ISO 8601 UTC text."""

BLOCK_SIZE_PX = 256
"""Tile size of the COG (pixels)."""

DEFLATE_LEVEL = 1
"""zlib level of the tiles' DEFLATE (lossless: any level decodes to the same values).

On a trial mosaic (3 x 1097 x 1600 float32, floating-point predictor) level 1 compresses in
0.27-0.29 CPU s against 0.51-0.70 s at GDAL's default 6, for a file 2 % larger (16.6 against
16.2 MB); decoding costs the same."""


@dataclass(frozen=True)
class Mosaic:
    """One scan mosaic read back from its COG.

    Attributes
    ----------
    bands_c : ndarray, float32, shape (B, H, W)
        Apparent temperature, degrees C; NaN where no frame saw the cell.
    transform : affine.Affine
        Pixel-to-map transform of the upper-left pixel corner (rasterio convention).
    epsg : int
        EPSG code of the (UTM) CRS.
    band_descriptions : tuple of str, length B
        E.g. ``("LW1 8.0-9.2 um",)``.
    tags : dict
        Dataset metadata items (default domain).
    scan_time_s : float or None
        Scan time, UTC epoch seconds, from ``CLEARFAST_SCAN_TIME_UTC``.
    overview_factors : tuple of int
        Decimation factors of the internal overviews.
    """

    bands_c: np.ndarray
    transform: Affine
    epsg: int
    band_descriptions: tuple[str, ...]
    tags: dict[str, str] = field(default_factory=dict)
    scan_time_s: float | None = None
    overview_factors: tuple[int, ...] = ()


def band_description(name: str, lambda_min_um: float, lambda_max_um: float) -> str:
    """The band description text, e.g. ``band_description("LW1", 8, 9.2) == "LW1 8.0-9.2 um"``."""
    return f"{name} {float(lambda_min_um):.1f}-{float(lambda_max_um):.1f} um"


def default_overview_factors(height: int, width: int, min_size_px: int = 64) -> list[int]:
    """Overview factors 2, 4, 8, ... while the overview keeps at least ``min_size_px`` pixels.

    At least one level (factor 2) is always returned so that every mosaic has an overview.
    """
    factors = [2]
    while max(height, width) / (factors[-1] * 2) >= min_size_px:
        factors.append(factors[-1] * 2)
    return factors


def _as_affine(grid_transform) -> Affine:
    if isinstance(grid_transform, Affine):
        return grid_transform
    if all(hasattr(grid_transform, a) for a in ("x0", "y0", "pixel_size")):
        ps = float(grid_transform.pixel_size)
        return Affine(ps, 0.0, float(grid_transform.x0), 0.0, -ps, float(grid_transform.y0))
    if isinstance(grid_transform, Sequence) and len(grid_transform) in (6, 9):
        return Affine(*grid_transform[:6])
    raise TypeError("grid_transform must be an affine.Affine or a GroundGrid")


def _tiff_datetime(t_s: float) -> str:
    return datetime.fromtimestamp(float(t_s), tz=UTC).strftime("%Y:%m:%d %H:%M:%S")


def write_cog(
    path: str | os.PathLike,
    bands: np.ndarray,
    grid_transform,
    epsg: int,
    band_descriptions: Sequence[str],
    tags: Mapping[str, object] | None = None,
    overview_levels: Sequence[int] | None = None,
    scan_time_s: float | None = None,
) -> str:
    """Write one scan mosaic as a Cloud Optimized GeoTIFF, atomically.

    Parameters
    ----------
    path : path
        Output file (``mosaics/scan_NNN.tif``).
    bands : ndarray, shape (B, H, W) or (H, W)
        Apparent temperature, degrees C; NaN = no data. Stored as float32.
    grid_transform : affine.Affine or GroundGrid
        Pixel-to-map transform (upper-left corner of pixel (0, 0)), metres in the survey CRS.
    epsg : int
        EPSG code of the projected (UTM) survey CRS.
    band_descriptions : sequence of str, length B
        One text per band, e.g. ``"LW1 8.0-9.2 um"`` (see :func:`band_description`).
    tags : mapping, optional
        Extra dataset metadata items (values converted to text).
    overview_levels : sequence of int, optional
        Overview decimation factors; default :func:`default_overview_factors`.
    scan_time_s : float, optional
        Scan time, UTC epoch seconds: written as TIFF ``DateTime`` and
        ``CLEARFAST_SCAN_TIME_UTC``. A ``CLEARFAST_SCAN_TIME_UTC`` item in ``tags`` is used
        when this is not given.

    Returns
    -------
    str
        The final path.
    """
    import rasterio
    import rasterio.shutil
    from rasterio.crs import CRS
    from rasterio.enums import Resampling
    from rasterio.io import MemoryFile

    arr = np.asarray(bands)
    if arr.ndim == 2:
        arr = arr[np.newaxis]
    if arr.ndim != 3 or arr.shape[1] < 1 or arr.shape[2] < 1:
        raise InvalidInput(f"expected bands of shape (B, H, W), got {arr.shape}", path, "bands")
    n_bands, height, width = arr.shape
    descriptions = list(band_descriptions)
    if len(descriptions) != n_bands:
        raise InvalidInput(f"{len(descriptions)} band descriptions for {n_bands} bands", path,
                           "band_descriptions")
    arr = arr.astype(np.float32, copy=False)
    transform = _as_affine(grid_transform)
    meta = {str(k): str(v) for k, v in (tags or {}).items()}
    if scan_time_s is None and SCAN_TIME_TAG in meta:
        try:
            scan_time_s = parse_utc(meta[SCAN_TIME_TAG])
        except ValueError:
            raise InvalidInput("not an ISO 8601 UTC time", path, f"tags.{SCAN_TIME_TAG}") from None
    if scan_time_s is not None:
        meta[SCAN_TIME_TAG] = format_utc(scan_time_s, timespec="seconds")
        meta["TIFFTAG_DATETIME"] = _tiff_datetime(scan_time_s)
    factors = [int(f) for f in (overview_levels or default_overview_factors(height, width))]
    if any(f < 2 for f in factors) or factors != sorted(set(factors)):
        raise InvalidInput("overview factors must be increasing integers >= 2", path,
                           "overview_levels")

    profile = {
        "driver": "GTiff", "width": width, "height": height, "count": n_bands,
        "dtype": "float32", "crs": CRS.from_epsg(int(epsg)), "transform": transform,
        "nodata": float("nan"),
    }
    with MemoryFile() as mem, mem.open(**profile) as src:
        src.write(arr)
        for i, text in enumerate(descriptions, start=1):
            src.set_band_description(i, text)
        src.units = ["deg C"] * n_bands
        src.update_tags(**meta)
        src.build_overviews(factors, Resampling.average)
        # built in memory, then written by Python: a full disk or a refused write is an
        # OSError that atomic_path reports as one line, not a libtiff message
        with MemoryFile(ext=".tif") as out:
            rasterio.shutil.copy(
                src, out.name, driver="COG", COMPRESS="DEFLATE", PREDICTOR="3",
                LEVEL=str(DEFLATE_LEVEL), BLOCKSIZE=str(BLOCK_SIZE_PX),
                OVERVIEWS="FORCE_USE_EXISTING", BIGTIFF="IF_SAFER", NUM_THREADS=str(n_threads()),
            )
            # written from a view of the in-memory file: ``read()`` would copy it into a
            # bytes object first while holding the GIL (30 ms for a trial scan's 12 MB,
            # during which the chain's other threads wait)
            with memoryview(out.getbuffer()) as view, atomic_path(path) as tmp:
                tmp.write_bytes(view)
    return os.fspath(path)


def read_mosaic(path: str | os.PathLike) -> Mosaic:
    """Read a scan mosaic written by :func:`write_cog`.

    Raises
    ------
    InvalidInput
        If the file is missing, not a raster or has no projected CRS.
    """
    import rasterio
    from rasterio.errors import RasterioIOError

    try:
        with rasterio.open(path) as ds:
            bands = ds.read(masked=False).astype(np.float32, copy=False)
            if ds.nodata is not None and not math.isnan(ds.nodata):
                bands = np.where(bands == ds.nodata, np.nan, bands).astype(np.float32)
            epsg = ds.crs.to_epsg() if ds.crs is not None else None
            tags = dict(ds.tags())
            descriptions = tuple(d or "" for d in ds.descriptions)
            overviews = tuple(ds.overviews(1))
            transform = ds.transform
    except RasterioIOError as exc:
        raise InvalidInput(f"cannot read the mosaic ({exc})", path) from None
    if epsg is None:
        raise InvalidInput("the mosaic has no EPSG-coded CRS", path, "crs")
    scan_time_s = None
    if SCAN_TIME_TAG in tags:
        try:
            scan_time_s = parse_utc(tags[SCAN_TIME_TAG])
        except ValueError:
            raise InvalidInput("not an ISO 8601 UTC time", path, SCAN_TIME_TAG) from None
    return Mosaic(bands, transform, int(epsg), descriptions, tags, scan_time_s, overviews)


@dataclass(frozen=True)
class CogStack:
    """The scan mosaics of a products folder as a
    :class:`~clearfast_gis.detection.stack.ScanStack`: a scan is read each time it is asked
    for, so that no pass holds more than the scans it is reading.

    With a ``decoded`` folder, a scan's COG is decoded once, at its first read by any stack
    of the run, and its bands are kept there as raw float32 (4 B H W bytes a scan, 21 MB on
    the trial's grid); later reads copy them back (about a tenth of the cost of decoding the
    tiles' DEFLATE again: the residuals, the detector and the stages after it pass over the
    scans up to seven times). The values are the COG's, bit for bit.

    Attributes
    ----------
    paths : tuple of Path
        One COG per scan, in scan order.
    n_bands : int
    shape : (int, int)
        (H, W) of every mosaic.
    transform : affine.Affine
        The mosaics' grid transform.
    decoded : Path or None
        Folder of the decoded scans (:func:`mosaic_stack`; valid while no COG is rewritten:
        the run deletes it with :func:`remove_decoded` when it starts and ends), or None to
        decode the COG at every read.
    """

    paths: tuple[Path, ...]
    n_bands: int
    shape: tuple[int, int]
    transform: Affine
    decoded: Path | None = None

    @property
    def n_scans(self) -> int:
        return len(self.paths)

    def scan(self, i: int) -> np.ndarray:
        """The bands of scan ``i``, float32 (B, H, W), degrees C."""
        shape = (self.n_bands, *self.shape)
        raw = None if self.decoded is None else _decoded_file(self.decoded, self.paths[i])
        if raw is not None and raw.exists():
            return np.fromfile(raw, dtype=np.float32).reshape(shape)
        bands = read_mosaic(self.paths[i]).bands_c
        if bands.shape != shape:
            raise InvalidInput(f"mosaic of shape {bands.shape}, the first scan's is {shape}",
                               self.paths[i])
        if raw is not None:
            _keep_decoded(raw, bands)
        return bands


def _decoded_file(decoded: Path, cog: Path) -> Path:
    """The raw float32 copy of the COG ``cog`` in the folder ``decoded``."""
    return decoded / f"{Path(cog).stem}.f32"


def keep_decoded(products: Path, cog_rel: str, bands: np.ndarray) -> None:
    """Keep ``bands`` (float32 (B, H, W), degrees C), just written to the COG ``cog_rel`` of
    the products folder, as that scan's decoded copy (:class:`CogStack`), so that its first
    read by a ``decode_once`` stack does not decode the tiles' DEFLATE again (55-67 CPU ms a
    trial scan). The values are the COG's bit for bit (DEFLATE is lossless and the COG stores
    the float32 values as they are). Call it after every write of the COG: a copy is only
    valid as long as its COG is not rewritten, so the scan's earlier copy is deleted first
    (a new one that cannot be written leaves none, and the COG is decoded at its next read)."""
    decoded = Path(products) / DECODED_REL
    raw = _decoded_file(decoded, Path(cog_rel))
    raw.unlink(missing_ok=True)
    try:
        decoded.mkdir(parents=True, exist_ok=True)
    except OSError:
        return
    _keep_decoded(raw, bands)


def _keep_decoded(raw: Path, bands: np.ndarray) -> None:
    """Write ``bands`` to ``raw`` (float32, C order) under a temporary name, then rename it,
    so that a concurrent reader sees the whole file or none (scratch: not synced to disk).
    Without room on the disk (or any other write error) the scan is simply not kept: it is
    decoded again at its next read."""
    tmp = None
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{raw.stem}.", suffix=".part", dir=raw.parent)
        with os.fdopen(fd, "wb") as fh:
            np.ascontiguousarray(bands, dtype=np.float32).tofile(fh)
        os.replace(tmp, raw)
    except OSError:
        pass
    finally:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)


def remove_decoded(products: Path) -> None:
    """Delete the decoded scans of a products folder (:data:`~clearfast_gis.export.layout.
    DECODED_REL`), if any."""
    shutil.rmtree(Path(products) / DECODED_REL, ignore_errors=True)


def mosaic_stack(products: Path, scans: list[int], decode_once: bool = False) -> CogStack:
    """The scans' mosaics in a products folder, in the order of ``scans``, as a
    :class:`CogStack` (the first mosaic's header read for its shape and transform).

    With ``decode_once``, each COG is decoded at most once and kept decoded in the
    :data:`~clearfast_gis.export.layout.DECODED_REL` folder, shared by every such stack of the
    products folder until :func:`remove_decoded` (call it before any COG is rewritten and when
    the passes are done)."""
    import rasterio
    from rasterio.errors import RasterioIOError

    paths = tuple(Path(products) / mosaic_rel(s) for s in scans)
    try:
        with rasterio.open(paths[0]) as ds:
            n_bands, shape, transform = int(ds.count), (int(ds.height), int(ds.width)), \
                ds.transform
    except RasterioIOError as exc:
        raise InvalidInput(f"cannot read the mosaic ({exc})", paths[0]) from None
    decoded = None
    if decode_once:
        decoded = Path(products) / DECODED_REL
        decoded.mkdir(parents=True, exist_ok=True)
    return CogStack(paths, n_bands, shape, transform, decoded)
