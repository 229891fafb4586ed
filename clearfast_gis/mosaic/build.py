"""One mosaic per scan: project, co-register and insert frames in scan-pattern order."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np

from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.geometry.pose import CameraPose
from clearfast_gis.mosaic.coregister import FrameCorrection, coregister_projected
from clearfast_gis.mosaic.insert import MosaicCanvas
from clearfast_gis.mosaic.project import frame_geometry, project_frame
from clearfast_gis.mosaic.seams import fit_linear_histogram_mapping
from clearfast_gis.parallel import thread_imap
from clearfast_gis.progress import NULL_PROGRESS, Progress


@dataclass
class FrameInput:
    """One frame ready for the mosaic.

    Attributes
    ----------
    index : int
        Position index in the scan pattern (the source id in the mosaic).
    values : float32 (B, H, W)
        Apparent temperature per band, degrees C.
    pose : CameraPose
        Geometric pose (RTK-DGPS, pan/tilt, mount).
    """

    index: int
    values: np.ndarray
    pose: CameraPose


@dataclass
class ScanMosaic:
    """A scan's mosaic and how it was made.

    Attributes
    ----------
    values : float32 (B, H, W)
        Degrees C, NaN where no frame saw the ground.
    source : int32 (H, W)
        Position index of the source frame per cell, -1 where empty.
    corrections : dict[int, FrameCorrection]
        Registration correction per position index.
    seam_gains : dict[int, tuple[float, float]]
        Seam-balancing (a, b) per position when that option is on.
    """

    values: np.ndarray
    source: np.ndarray
    corrections: dict[int, FrameCorrection] = field(default_factory=dict)
    seam_gains: dict[int, tuple[float, float]] = field(default_factory=dict)

    @property
    def footprint_mask(self) -> np.ndarray:
        """Cells with data, bool (H, W)."""
        return self.source >= 0


def build_scan_mosaic(frames: Iterable[FrameInput], camera, grid: GroundGrid, n_bands: int,
                      coregister: bool = True, reference: np.ndarray | None = None,
                      max_shift_m: float = 0.25, max_angle_deg: float = 1.5,
                      seam_balance: bool = False, progress: Progress = NULL_PROGRESS,
                      ) -> ScanMosaic:
    """Mosaic one scan (paper §5: back-project, co-register, insert, optionally balance).

    Parameters
    ----------
    frames : iterable of FrameInput
        In scan-pattern order.
    camera : EquiangularCamera or PinholeCamera
    grid : GroundGrid
        The survey's mosaic grid (shared by every scan).
    n_bands : int
        Spectral bands per frame.
    coregister : bool
        Correct each frame's placement by mutual information (paper §5.2).
    reference : float32 (B, H, W), optional
        The reference scan's mosaic. When given, frames are registered to it (temporal
        co-registration frame by frame, which also follows a drifting platform); otherwise
        to the mosaic built so far.
    max_shift_m, max_angle_deg : float
        Bound of each frame's correction.
    seam_balance : bool
        Apply the paper's histogram-based linear mapping to each frame before insertion.
    progress : Progress
        Advanced once per frame.

    Returns
    -------
    ScanMosaic
    """
    canvas = MosaicCanvas(n_bands, grid.height, grid.width)
    corrections: dict[int, FrameCorrection] = {}
    seam_gains: dict[int, tuple[float, float]] = {}
    frames = list(frames)
    footprints, sigmas = frame_geometry(camera, [f.pose for f in frames], grid.pixel_size)
    projections = thread_imap(
        lambda k: project_frame(frames[k].values, camera, frames[k].pose, grid,
                                footprint=footprints[k], sigma_px=sigmas[k]),
        range(len(frames)))
    for frame, projected in zip(frames, projections, strict=True):
        progress.advance()
        if projected is None:
            continue
        if coregister:
            rs, cs = projected.window.slices
            ref = canvas.values[:, rs, cs] if reference is None else reference[:, rs, cs]
            projected, corr, _ = coregister_projected(
                projected, ref, grid.pixel_size, max_shift_m, max_angle_deg)
            corrections[frame.index] = corr
        if seam_balance:
            under = canvas.window_values(projected)
            overlap = projected.valid & np.isfinite(under[0])
            if overlap.any():
                a, b = fit_linear_histogram_mapping(under[0][overlap],
                                                    projected.values[0][overlap])
                projected.values *= np.float32(a)
                projected.values += np.float32(b)
                seam_gains[frame.index] = (a, b)
        canvas.insert(projected, frame.index)
    return ScanMosaic(canvas.values, canvas.source, corrections, seam_gains)
