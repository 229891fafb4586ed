"""Band co-registration: the filter wheel shifts the spectral bands against each other.

The offsets are estimated once per survey (median over many frames of an MI registration of
each band against band 0, so a few bad frames do not matter) and applied to every frame.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from clearfast_gis.errors import InvalidInput
from clearfast_gis.parallel import thread_imap
from clearfast_gis.progress import NULL_PROGRESS, Progress
from clearfast_gis.registration.conformal import register_conformal
from clearfast_gis.registration.transform import ConformalTransform
from clearfast_gis.registration.warp import warp_conformal


def _as_frame_list(stack: np.ndarray | Sequence[np.ndarray], band: int) -> list[np.ndarray]:
    frames = [np.asarray(f) for f in stack] if not isinstance(stack, np.ndarray) else (
        [stack] if stack.ndim == 2 else list(stack))
    for f in frames:
        if f.ndim != 2:
            raise InvalidInput(f"expected (P, H, W) frames, got a frame of shape {f.shape}",
                               field=f"band {band}")
    return frames


def estimate_band_offsets(
    frames_by_band: Sequence[np.ndarray | Sequence[np.ndarray]],
    conformal: bool = False,
    max_shift_px: float = 16.0,
    max_angle_deg: float = 2.0,
    bins: int = 32,
    progress: Progress | None = None,
) -> list[ConformalTransform]:
    """Offsets of every band against band 0, robust over many frames.

    Parameters
    ----------
    frames_by_band : sequence of B stacks
        ``frames_by_band[b]`` is a (P, H, W) array or a list of P (H, W) images of band ``b``
        (temperature or radiance, NaN = no-data); frame ``p`` of every band shows the same
        scene (same scan position).
    conformal : bool
        Estimate rotation too (Eq. 3); default translation only, as a filter wheel shifts.
    max_shift_px : float
        Largest offset searched, pixels.
    max_angle_deg : float
        Largest rotation searched when ``conformal``, degrees.
    bins : int
        Histogram bins of the MI registration.
    progress : Progress, optional
        Advanced once per registered frame.

    Returns
    -------
    list of ConformalTransform, length B
        ``offsets[b]`` maps band-0 pixel coordinates to band-``b`` pixel coordinates (the
        parameter-wise median over the frames whose registration converged); ``offsets[0]`` is
        the identity. ``metric`` is the median MI, ``n_samples`` the number of frames used and
        ``converged`` False when fewer than half the frames (or none) registered.

    Raises
    ------
    InvalidInput
        Fewer than one band, bands with different frame counts or shapes.
    """
    if len(frames_by_band) == 0:
        raise InvalidInput("no bands given", field="frames_by_band")
    stacks = [_as_frame_list(s, b) for b, s in enumerate(frames_by_band)]
    n_frames = len(stacks[0])
    for b, s in enumerate(stacks):
        if len(s) != n_frames or n_frames == 0:
            raise InvalidInput(f"band {b} has {len(s)} frames, band 0 has {n_frames}",
                               field=f"band {b}")
        if any(f.shape != stacks[0][0].shape for f in s):
            raise InvalidInput("frames differ in shape between bands", field=f"band {b}")
    h, w = stacks[0][0].shape
    center = ((w - 1) / 2.0, (h - 1) / 2.0)
    progress = progress or NULL_PROGRESS
    progress.start("band co-registration", (len(stacks) - 1) * n_frames)
    offsets = [replace(ConformalTransform.identity(center), n_samples=n_frames)]
    pairs = [(b, p) for b in range(1, len(stacks)) for p in range(n_frames)]

    def register(pair: tuple[int, int]) -> ConformalTransform:
        b, p = pair
        return register_conformal(stacks[0][p], stacks[b][p], max_shift_px=max_shift_px,
                                  max_angle_deg=max_angle_deg if conformal else 0.0, bins=bins)

    # the pairs registered on threads (the MI kernels release the GIL), results in pair order
    results = []
    for (b, p), t in zip(pairs, thread_imap(register, pairs), strict=True):
        results.append(t)
        progress.advance(1, band=b, frame=p)
    for b in range(1, len(stacks)):
        offsets.append(_median_transform(results[(b - 1) * n_frames:b * n_frames], center))
    progress.close()
    return offsets


def _median_transform(results: list[ConformalTransform],
                      center: tuple[float, float]) -> ConformalTransform:
    good = [r for r in results if r.converged]
    if not good:
        return replace(ConformalTransform.identity(center), n_samples=0, converged=False)
    params = np.array([[r.angle_rad, r.tx_px, r.ty_px, math.log(r.scale)] for r in good])
    med = np.median(params, axis=0)
    return ConformalTransform(
        float(med[0]), float(med[1]), float(med[2]), float(math.exp(med[3])),
        metric=float(np.median([r.metric for r in good])), n_samples=len(good),
        converged=2 * len(good) >= len(results), center_px=center)


def apply_band_offsets(
    images_by_band: Sequence[np.ndarray] | np.ndarray,
    offsets: Sequence[ConformalTransform],
    order: int = 1,
) -> list[np.ndarray]:
    """Resample every band onto band 0's pixel grid.

    Parameters
    ----------
    images_by_band : sequence of B arrays, each (H, W) or (P, H, W)
        One frame's bands, or each band's stack of frames; a (B, H, W) or (B, P, H, W) array
        also works.
    offsets : sequence of B ConformalTransform
        From :func:`estimate_band_offsets`.
    order : {0, 1, 3}
        Interpolation order.

    Returns
    -------
    list of B float32 arrays
        Same shapes as the inputs, NaN where band ``b`` does not cover band 0's pixel.
    """
    if len(images_by_band) != len(offsets):
        raise InvalidInput(f"{len(images_by_band)} bands but {len(offsets)} offsets",
                           field="offsets")
    out = []
    for img, t in zip(images_by_band, offsets, strict=True):
        arr = np.asarray(img)
        if arr.ndim == 2:
            out.append(warp_conformal(arr, t, arr.shape, order))
        elif arr.ndim == 3:
            out.append(np.stack([warp_conformal(f, t, f.shape, order) for f in arr]))
        else:
            raise InvalidInput(f"expected (H, W) or (P, H, W), got shape {arr.shape}",
                               field="images_by_band")
    return out
