"""Reference MI registration with SimpleITK (``--kernels reference``): the registry's
reference of ``register_conformal`` (:mod:`clearfast_gis.kernels`).

The same problem as :func:`clearfast_gis.registration.register_conformal`: the starting points
come from the same polarity-blind phase correlation of gradient magnitudes, each is refined by
SimpleITK's Mattes mutual information (50 bins, 20 % random samples, linear interpolation) with
a regular-step gradient descent over a 3-level pyramid, and the result is judged by the same
acceptance test (overlap, bias-corrected normalised MI, bounds).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import SimpleITK as sitk

from clearfast_gis.registration._kernels import _bin_scale, _level_problem, _normalised_mi
from clearfast_gis.registration.conformal import MAX_LOG_SCALE
from clearfast_gis.registration.pyramid import masked_gaussian, masked_pyramid, n_levels_for
from clearfast_gis.registration.search import gradient_magnitude, rotation_candidates
from clearfast_gis.registration.transform import ConformalTransform

ANGLE_STEP_RAD = math.radians(1.0)
"""Angular step of the starting-point search, radians."""


def _image(values: np.ndarray) -> tuple[sitk.Image, sitk.Image]:
    """A float32 SimpleITK image (no-data filled with the median) and its uint8 valid mask."""
    valid = np.isfinite(values)
    fill = float(np.median(values[valid])) if valid.any() else 0.0
    img = sitk.GetImageFromArray(np.where(valid, values, fill).astype(np.float32))
    return img, sitk.GetImageFromArray(valid.astype(np.uint8))


def _to_sitk(t: ConformalTransform, translation_only: bool, scale: bool) -> sitk.Transform:
    """SimpleITK transform (fixed -> moving physical = pixel coordinates) equal to ``t``.

    Eq. 3's matrix is the standard rotation by ``-angle``, hence the sign."""
    if translation_only:
        return sitk.TranslationTransform(2, (t.tx_px, t.ty_px))
    out = sitk.Similarity2DTransform() if scale else sitk.Euler2DTransform()
    out.SetCenter(t.center_px)
    out.SetAngle(-t.angle_rad)
    out.SetTranslation((t.tx_px, t.ty_px))
    if scale:
        out.SetScale(t.scale)
    return out


def _from_sitk(tr: sitk.Transform, center: tuple[float, float], translation_only: bool,
               scale: bool) -> ConformalTransform:
    """The ConformalTransform (rotation centre ``center``) of a registration result."""
    if translation_only:
        tx, ty = sitk.TranslationTransform(tr).GetOffset()
        return ConformalTransform(0.0, float(tx), float(ty), center_px=center)
    tr = sitk.Similarity2DTransform(tr) if scale else sitk.Euler2DTransform(tr)
    a = np.array(tr.GetMatrix()).reshape(2, 2)
    c = np.array(tr.GetCenter())
    b = c + np.array(tr.GetTranslation()) - a @ c
    return ConformalTransform.from_matrix(np.hstack([a, b[:, None]]), center)


def _starts(fixed: np.ndarray, moving: np.ndarray, base: ConformalTransform,
            max_angle_rad: float, max_shift_px: float | None, keep: int = 3
            ) -> list[ConformalTransform]:
    """Up to ``keep`` distinct starting transforms from rotated phase correlation at the
    coarsest pyramid level (as the fast registration does)."""
    levels = min(n_levels_for(fixed.shape), n_levels_for(moving.shape))
    factor = 0.5 ** (levels - 1)
    fc, mc = masked_pyramid(fixed, levels)[-1], masked_pyramid(moving, levels)[-1]
    if max_angle_rad > 0:
        n = int(math.ceil(max_angle_rad / ANGLE_STEP_RAD))
        angles = base.angle_rad + np.linspace(-max_angle_rad, max_angle_rad, 2 * n + 1)
    else:
        angles = np.array([base.angle_rad])
    coarse = base.scaled(factor)
    cands = rotation_candidates(gradient_magnitude(fc), gradient_magnitude(mc), angles,
                                coarse.center_px, coarse,
                                None if max_shift_px is None else max_shift_px * factor,
                                n_peaks=1)
    out: list[ConformalTransform] = []
    for c in [*(c.scaled(1.0 / factor) for c in cands), base]:
        if all(math.hypot(c.tx_px - o.tx_px, c.ty_px - o.ty_px) > 2.0
               or abs(c.angle_rad - o.angle_rad) > ANGLE_STEP_RAD / 2 for o in out):
            out.append(c)
        if len(out) == keep:
            break
    return out


def register_reference(fixed: np.ndarray, moving: np.ndarray, base: ConformalTransform,
                       search: bool, scale: bool, max_shift_px: float | None,
                       max_angle_deg: float, seed: int = 2026) -> tuple[ConformalTransform,
                                                                         float]:
    """Register ``moving`` to ``fixed`` with SimpleITK's Mattes MI.

    Parameters
    ----------
    fixed, moving : float (Hf, Wf), (Hm, Wm)
        Temperature images, NaN = no-data (masked out of the metric).
    base : ConformalTransform
        Prior transform, rotation centre at the fixed image centre.
    search : bool
        Search starting points by phase correlation (else start at ``base`` only).
    scale : bool
        Also estimate an isotropic scale.
    max_shift_px : float or None
        Results further than this from ``base`` are flagged unconverged by the caller.
    max_angle_deg : float
        0: translation only.
    seed : int
        Seed of the random metric sampling.

    Returns
    -------
    (ConformalTransform, float)
        The result and its Mattes MI, nats (NaN when SimpleITK found too few samples).
    """
    translation_only = max_angle_deg <= 0 and not scale
    f_img, f_mask = _image(fixed)
    m_img, m_mask = _image(moving)
    starts = (_starts(fixed, moving, base, math.radians(max_angle_deg), max_shift_px)
              if search else [base])
    best: tuple[float, ConformalTransform] | None = None
    for start in starts:  # each start optimised, the best final MI kept
        reg = _method(f_mask, m_mask, seed)
        reg.SetInitialTransform(_to_sitk(start, translation_only, scale), inPlace=False)
        try:
            out = reg.Execute(f_img, m_img)
        except RuntimeError:  # too few samples inside both masks
            continue
        inner = sitk.CompositeTransform(out).GetNthTransform(0) \
            if out.GetName() == "CompositeTransform" else out
        mi = -float(reg.GetMetricValue())
        if best is None or mi > best[0]:
            best = (mi, _from_sitk(inner, base.center_px, translation_only, scale))
    if best is None:
        return replace(base, converged=False), math.nan
    return best[1], best[0]


def _method(f_mask: sitk.Image, m_mask: sitk.Image, seed: int) -> sitk.ImageRegistrationMethod:
    """Mattes MI (50 bins, 20 % random samples inside the masks), linear interpolation,
    regular-step gradient descent, 3-level pyramid: the SimpleITK examples' settings."""
    reg = sitk.ImageRegistrationMethod()
    reg.SetMetricAsMattesMutualInformation(numberOfHistogramBins=50)
    reg.SetMetricSamplingStrategy(reg.RANDOM)
    reg.SetMetricSamplingPercentage(0.20, seed)
    reg.SetMetricFixedMask(f_mask)
    reg.SetMetricMovingMask(m_mask)
    reg.SetInterpolator(sitk.sitkLinear)
    reg.SetOptimizerAsRegularStepGradientDescent(learningRate=1.0, minStep=1e-3,
                                                 numberOfIterations=200,
                                                 gradientMagnitudeTolerance=1e-8)
    reg.SetOptimizerScalesFromPhysicalShift()
    reg.SetShrinkFactorsPerLevel([4, 2, 1])
    reg.SetSmoothingSigmasPerLevel([2, 1, 0])
    reg.SmoothingSigmasAreSpecifiedInPhysicalUnitsOn()
    return reg


def register_conformal(f0: np.ndarray, m0: np.ndarray, base: ConformalTransform, search: bool,
               scale: bool, max_shift_px: float | None, shift_bound: float,
               max_angle_rad: float, bins: int, max_samples: int, smooth_px: float,
               min_overlap: float, min_metric: float, polish_samples: int = 0
               ) -> ConformalTransform:
    """:func:`register_conformal` by SimpleITK (``--kernels reference``), judged by the same
    acceptance test (overlap, normalised MI at the finest level, bounds); SimpleITK has no
    separate polish (``polish_samples`` is not used)."""
    result, _ = register_reference(f0, m0, base, search, scale, max_shift_px,
                                   math.degrees(max_angle_rad))
    fl, ml = masked_gaussian(f0, smooth_px), masked_gaussian(m0, smooth_px)
    problem = _level_problem(fl, ml, _bin_scale(f0[np.isfinite(f0)]),
                             _bin_scale(m0[np.isfinite(m0)]), bins, max_samples, 1.0)
    mi, n_overlap, _ = problem.evaluate(result, False)
    inside = (max(abs(result.tx_px - base.tx_px), abs(result.ty_px - base.ty_px))
              <= shift_bound
              and abs(result.angle_rad - base.angle_rad) <= max_angle_rad + 1e-9
              and abs(math.log(result.scale)) <= MAX_LOG_SCALE)
    converged = (n_overlap >= max(64, min_overlap * problem.us.size)
                 and _normalised_mi(mi, problem.hist) >= min_metric and inside)
    return replace(result, metric=float(mi), n_samples=int(n_overlap),
                   converged=bool(converged))
