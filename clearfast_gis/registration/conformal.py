"""Mutual-information registration with the linear conformal model (paper §3.4, Eq. 3).

Coarse to fine over a masked image pyramid:

1. at the coarsest level, unless ``init`` is given, a global search: for a grid of angles the
   translation comes from phase correlation of gradient magnitudes (polarity-blind), and the
   candidates are ranked by bias-corrected mutual information;
2. at every level, the best candidates are refined by maximising a Parzen-windowed mutual
   information (Mattes et al. 2003) with its analytic gradient (numba kernel), by a bounded
   quasi-Newton method; the samples are the fixed pixels of steepest gradient;
3. a short final polish at the finest level with more samples;
4. the result records the final MI, the number of overlapping samples and whether the
   optimum is trustworthy.

:func:`register_conformal` checks its input and runs the registry's ``register_conformal``
(:mod:`clearfast_gis.kernels`): the steps above are in :mod:`clearfast_gis.registration._kernels`,
the SimpleITK reference in :mod:`clearfast_gis.registration._reference`.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from clearfast_gis import kernels
from clearfast_gis.errors import InvalidInput
from clearfast_gis.registration.pyramid import apply_mask
from clearfast_gis.registration.transform import ConformalTransform

MAX_LOG_SCALE = math.log(1.25)
"""Largest scale change searched when ``scale=True`` (a factor 1.25 either way)."""


def _check_inputs(fixed: np.ndarray, moving: np.ndarray, bins: int,
                  max_angle_deg: float, max_shift_px: float | None) -> None:
    for name, img in (("fixed", fixed), ("moving", moving)):
        if img.ndim != 2:
            raise InvalidInput(f"expected a 2-D image, got shape {img.shape}", field=name)
        if min(img.shape) < 8:
            raise InvalidInput(f"image too small for registration: {img.shape}", field=name)
        if np.count_nonzero(np.isfinite(img)) < 64:
            raise InvalidInput("fewer than 64 valid pixels", field=name)
    if bins < 8:
        raise InvalidInput(f"bins must be at least 8, got {bins}", field="bins")
    if not (0.0 <= max_angle_deg <= 90.0):
        raise InvalidInput(f"max_angle_deg must be in [0, 90], got {max_angle_deg}",
                           field="max_angle_deg")
    if max_shift_px is not None and not max_shift_px >= 0:
        raise InvalidInput(f"max_shift_px must be >= 0, got {max_shift_px}",
                           field="max_shift_px")


def register_conformal(
    fixed: np.ndarray,
    moving: np.ndarray,
    fixed_mask: np.ndarray | None = None,
    moving_mask: np.ndarray | None = None,
    scale: bool = False,
    max_shift_px: float | None = None,
    max_angle_deg: float = 10.0,
    init: ConformalTransform | None = None,
    bins: int = 32,
    *,
    min_overlap: float = 0.1,
    min_metric: float = 0.05,
    max_samples: int = 30_000,
    polish_samples: int = 120_000,
    smooth_px: float = 0.7,
) -> ConformalTransform:
    """Register ``moving`` to ``fixed`` by maximising mutual information over Eq. 3.

    Parameters
    ----------
    fixed, moving : ndarray, shape (Hf, Wf) and (Hm, Wm)
        Temperature images (K or degrees C, any real dtype); NaN marks no-data. The two may
        differ in shape.
    fixed_mask, moving_mask : ndarray of bool, optional
        ``True`` where a pixel may be used (combined with the finite pixels).
    scale : bool
        Also estimate an isotropic scale (within a factor 1.25 of the start).
    max_shift_px : float, optional
        Largest translation, fixed pixels, away from ``init`` (identity when ``init`` is None).
        None: any translation that leaves an overlap.
    max_angle_deg : float
        Largest rotation away from ``init``, degrees; 0 estimates a translation only.
    init : ConformalTransform, optional
        Starting transform (e.g. from the geometric pose). When given, the global search is
        skipped and the optimisation starts from it.
    bins : int
        Histogram bins per image at the finest level (fewer on small coarse levels).
    min_overlap : float
        Fraction of the fixed image's valid samples that must overlap the moving image's
        valid area for the result to count as converged.
    min_metric : float
        Smallest normalised MI, ``(MI - bias) / min(H(fixed), H(moving))`` in [0, 1] (bias:
        the Miller-Madow estimate of the plug-in MI's small-sample bias), for the result to
        count as converged. Unrelated images score below 0.03, aligned views of one scene
        above 0.15 even with 1 K of noise.
    max_samples : int
        Fixed samples per level; above this, the pixels of steepest gradient are used.
    polish_samples : int
        Samples of a last short refinement at the finest level (skipped when it would not
        add samples); more samples average the image noise down.
    smooth_px : float
        Gaussian smoothing (pixels of each level) applied to both images before matching,
        which suppresses the noise-driven interpolation artefacts of MI at sub-pixel shifts.

    Returns
    -------
    ConformalTransform
        Maps fixed pixel coordinates to moving ones, rotation centre at the fixed image centre
        ``((Wf - 1) / 2, (Hf - 1) / 2)``. ``metric`` is the final MI in nats (Parzen estimate
        at the finest level), ``n_samples`` the number of overlapping fixed samples there and
        ``converged`` is False when the optimum sits on a bound, the overlap is below
        ``min_overlap`` or the normalised MI below ``min_metric``: callers should then keep
        their prior (geometric) alignment.

    Raises
    ------
    InvalidInput
        Images that are not 2-D, too small or almost all no-data; bad bounds.
    """
    try:
        f0 = apply_mask(fixed, fixed_mask)
    except ValueError as exc:
        raise InvalidInput(str(exc), field="fixed") from None
    try:
        m0 = apply_mask(moving, moving_mask)
    except ValueError as exc:
        raise InvalidInput(str(exc), field="moving") from None
    _check_inputs(f0, m0, bins, max_angle_deg, max_shift_px)
    hf, wf = f0.shape
    center = ((wf - 1) / 2.0, (hf - 1) / 2.0)
    base = (ConformalTransform.identity(center) if init is None
            else replace(init.with_center(center), metric=math.nan, n_samples=0,
                         converged=True))
    max_angle_rad = math.radians(max_angle_deg)
    shift_bound = (float(max_shift_px) if max_shift_px is not None
                   else float(max(hf, wf) + max(m0.shape)))

    return kernels.kernel("register_conformal")(
        f0, m0, base, init is None, scale, max_shift_px, shift_bound, max_angle_rad, bins,
        max_samples, smooth_px, min_overlap, min_metric, polish_samples)


