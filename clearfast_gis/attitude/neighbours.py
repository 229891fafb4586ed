"""Ties between placed scans, mosaic against mosaic: each scan with its neighbours in time
and with the reference scan (the refined survey-wide adjustment)."""

from __future__ import annotations

import numpy as np
from scipy import ndimage

from clearfast_gis.attitude.scan import ReferenceMosaic
from clearfast_gis.attitude.ties import LinearTie, displacement_jacobian
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.mosaic import temporal_transform
from clearfast_gis.parallel import thread_map
from clearfast_gis.progress import Progress
from clearfast_gis.registration import ConformalTransform, register_conformal

NEIGHBOUR_OFFSETS = (-2, -1, 1, 2)
"""Scans tied to each scan in the refined adjustment, as steps in time order."""

NEIGHBOUR_SAMPLES = 40
"""Frames per scan tied to each neighbouring scan in the refined adjustment. More than a
scan's own fit takes (:data:`~clearfast_gis.attitude.scan.ATTITUDE_SAMPLES`): with a
drifting platform these ties, not the first fits, set the final attitudes. With 24 here
too, the misregistration of the drifting trial (seed 1) from the true poses grew from 0.27
/ 0.38 px (median / max) to 0.33 / 0.48; with 40 it stays at 0.26 / 0.42."""


def frame_windows(source: np.ndarray, n_samples: int, min_cells: int = 400
                  ) -> list[tuple[int, tuple[slice, slice]]]:
    """Positions to tie and the bounding window of the cells each one supplies in a mosaic.

    Parameters
    ----------
    source : int (H, W)
        Scan-pattern position seen in each cell (-1: none).
    n_samples : int
        Positions kept, spread evenly over the positions present.
    min_cells : int
        Positions supplying fewer cells are skipped.

    Returns
    -------
    list of (position, (row slice, column slice))
    """
    positions, counts = np.unique(source[source >= 0], return_counts=True)
    positions = positions[counts >= min_cells]
    if positions.size == 0:
        return []
    pick = positions[np.unique(np.linspace(0, positions.size - 1,
                                           min(n_samples, positions.size)).round().astype(int))]
    boxes = ndimage.find_objects(np.where(source >= 0, source + 1, 0), int(pick.max()) + 1)
    return [(int(p), boxes[int(p)]) for p in pick if boxes[int(p)] is not None]


def mosaic_ties(scan: ReferenceMosaic, other: ReferenceMosaic, camera, grid: GroundGrid,
                n_samples: int = NEIGHBOUR_SAMPLES, max_shift_m: float = 0.2,
                min_overlap: float = 0.5,
                windows: list[tuple[int, tuple[slice, slice]]] | None = None,
                transform: ConformalTransform | None = None) -> list[LinearTie]:
    """Ties between two placed scans, measured mosaic against mosaic.

    For a sample of ``scan``'s frames, the cells each frame supplies to ``scan``'s mosaic are
    registered (translation only, mutual information) against ``other``'s mosaic under the
    same window. Unlike a frame fitted against a reference, a tie is kept whenever the
    registration converges, even at zero shift: after an adjustment most frames are already
    in place, and keeping only those that moved would bias the sample.

    Parameters
    ----------
    scan, other : ReferenceMosaic
        The two scans' mosaics (degrees C, band 0 used), source maps and placements.
    camera : camera model
    grid : GroundGrid
        The mosaic grid (cell size in metres).
    n_samples : int
        Frames of ``scan`` tied.
    max_shift_m : float
        Largest shift searched, metres.
    min_overlap : float
        Fraction of a frame's cells that ``other`` must cover.
    windows : list, optional
        ``frame_windows(scan.source, n_samples)``, when the caller ties ``scan`` to several
        others (computed here otherwise).
    transform : ConformalTransform, optional
        The registration of the whole of ``scan``'s mosaic to ``other``'s, in mosaic pixels
        (:func:`clearfast_gis.mosaic.temporal_transform`): when given, each sample frame's
        shift is read from it at the frame's cells instead of registering the frame's window
        alone (the whole mosaics hold far more texture than one window, which matters between
        day and night).

    Returns
    -------
    list of LinearTie
        ``d_m`` moves ``scan``'s content onto ``other``'s; weight 1.
    """
    ps = grid.pixel_size
    out: list[LinearTie] = []
    if windows is None:
        windows = frame_windows(scan.source, n_samples)
    for pos, (rs, cs) in windows:
        mask = scan.source[rs, cs] == pos
        fixed = other.values[0][rs, cs]
        if np.count_nonzero(mask & np.isfinite(fixed)) < min_overlap * np.count_nonzero(mask):
            continue
        rows, cols = np.nonzero(mask)
        centre = np.array([cols.mean(), rows.mean()])
        if transform is None:
            t = register_conformal(fixed, scan.values[0][rs, cs], moving_mask=mask,
                                   max_shift_px=max_shift_m / ps, max_angle_deg=0.0, bins=24)
            if not t.converged:
                continue
            du, dv = centre - t.apply(centre[None])[0]
        else:
            whole = centre + (cs.start, rs.start)
            du, dv = whole - transform.apply(whole[None])[0]
        d = np.array([du * ps, -dv * ps])
        xc = grid.x0 + (cs.start + centre[0] + 0.5) * ps
        yc = grid.y0 - (rs.start + centre[1] + 0.5) * ps
        src = other.source[rs, cs][mask]
        src = src[src >= 0]
        if src.size == 0:
            continue
        values, counts = np.unique(src, return_counts=True)
        j = int(values[np.argmax(counts)])
        t_scan, pose = scan.frame_at(pos)
        t_other, pose_other = other.frame_at(j)
        out.append(LinearTie(
            scan.scan, float(t_scan), np.asarray(pose.attitude_rpy_deg, dtype=float),
            displacement_jacobian(camera, pose, xc, yc), d, 1.0, other.scan, float(t_other),
            np.asarray(pose_other.attitude_rpy_deg, dtype=float),
            displacement_jacobian(camera, pose_other, xc + d[0], yc + d[1])))
    return out


def neighbour_pairs(order: list[int], offsets: tuple[int, ...] = NEIGHBOUR_OFFSETS
                    ) -> list[tuple[int, int]]:
    """(scan, neighbour) pairs to tie: each scan with the scans ``offsets`` away in time order.

    Parameters
    ----------
    order : list of int
        Scans in time order.
    offsets : tuple of int
        Steps along ``order`` (e.g. -1: the previous scan).

    Examples
    --------
    >>> neighbour_pairs([3, 5, 9], offsets=(-1, 1))
    [(3, 5), (5, 3), (5, 9), (9, 5)]
    """
    return [(s, order[k + o]) for k, s in enumerate(order) for o in offsets
            if 0 <= k + o < len(order)]


def neighbour_ties(job, order: list[int], scan_records: dict[int, dict],
                   model: tuple[np.ndarray, np.ndarray] | None,
                   offsets: tuple[int, ...] = NEIGHBOUR_OFFSETS,
                   progress: Progress | None = None,
                   reference_scan: int | None = None) -> list[LinearTie]:
    """Ties of every scan to its neighbours in time, measured on the placed mosaics; and to
    the reference scan, from the registration of the two whole mosaics.

    Neighbours are close in time and alike, so a frame's window registers well against them;
    but a chain of neighbours drifts over the hours between a night scan and the noon
    reference. Against the reference each scan's whole mosaic is registered at once
    (:func:`clearfast_gis.mosaic.temporal_transform`, as the residual is measured), which stays
    precise across the day/night contrast inversion where a single window does not.

    Parameters
    ----------
    job : the pipeline's scan job (``reference``, ``ctx``, ``grid``, ``options``)
    order : list of int
        Scans in time order.
    scan_records : dict
        Per-scan run-state records (how each mosaic was placed).
    model : (node_times_s (S,), nodes_rpy_deg (S, 3)) or None
        The attitude the adjusted scans were placed with.
    offsets : tuple of int
        Neighbours tied, as steps along ``order``.
    progress : Progress, optional
    reference_scan : int, optional
        The scan the temporal mosaics are co-registered to; None: no ties to it beyond the
        neighbours'.

    Returns
    -------
    list of LinearTie
    """
    reach = max(abs(o) for o in offsets)
    reference = None if reference_scan is None else \
        job.reference(reference_scan, scan_records[reference_scan], model)
    loaded: dict[int, object] = {}
    ties: list[LinearTie] = []
    pairs = neighbour_pairs(order, offsets)
    if progress is not None:
        progress.start("attitude ties between neighbouring scans", len(order))
    for k, s in enumerate(order):
        keep = set(order[max(0, k - reach):k + reach + 1])
        loaded = {n: m for n, m in loaded.items() if n in keep}
        for n in keep - set(loaded):
            loaded[n] = reference if n == reference_scan else \
                job.reference(n, scan_records[n], model)
        others = [n for m, n in pairs if m == s]
        windows = frame_windows(loaded[s].source, NEIGHBOUR_SAMPLES)  # shared by the neighbours
        for found in thread_map(lambda other, here=loaded[s], near=loaded, w=windows:
                                mosaic_ties(here, near[other], job.ctx.camera, job.grid,
                                            windows=w), others):
            ties += found
        if reference is not None and s != reference_scan:
            whole = temporal_transform(reference.values[0], loaded[s].values[0])
            if whole.converged:
                ties += mosaic_ties(loaded[s], reference, job.ctx.camera, job.grid,
                                    windows=windows, transform=whole)
        if progress is not None:
            progress.advance(1, scan=s)
    if progress is not None:
        progress.close()
    return ties
