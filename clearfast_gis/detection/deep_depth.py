"""Depth of a deep core from the shape of its contrast curve over the day.

A deep core (:mod:`clearfast_gis.detection.deep`) is a buried AP-sized object whose contrast
in any one scan is a few noise sigmas. The general inversion
(:func:`clearfast_gis.thermal.inversion.invert_anomaly`) fits depth and diffusivity together
and, on such a weak curve, trades one for the other: it runs to its depth bound with 2-3 times
the true diffusivity and is flagged. A deep core was found by matching the thermal model's
curve of the reference AP mine (:data:`clearfast_gis.thermal.daycontrast.REFERENCE_RADIUS_M`,
a TNT fill in the site's fitted soil) over the whole stack: the same curves at a fine grid of
depths make a depth profile. The later and the flatter the curve, the deeper the object (the
diurnal wave's lag grows by about 20 minutes per centimetre in sand).

With ``c_k`` the core's contrast in scan ``k`` (K), ``s_k`` its noise (K) and ``m_k(d)`` the
reference curve at depth ``d``, the profile is

    chi2(d) = min_{g, b} sum_k ((c_k - g m_k(d) - b) / s_k)**2
                        + ((g - G) / sigma_G)**2 + (b / sigma_b)**2,

the gain ``g`` (what the mosaics deliver of the modelled axis contrast as disc minus ring) and
the offset ``b`` (the ring's level) linear and free within their priors :data:`DISC_RING_GAIN`
+- :data:`DISC_RING_GAIN_SIGMA` and 0 +- :data:`clearfast_gis.thermal.error_budget.OFFSET_TERM_K`.
The noise ``s_k`` is scaled by the fit's reduced chi-square when that exceeds 1. The depth is
the profile's minimum (parabola through the best grid node and its neighbours), its fit sigma
half the width of ``chi2 <= min + 1``; the shape fit's constant terms (object height, ring,
soil terms, :data:`SHAPE_DEPTH_TERMS_M`) and :data:`SHAPE_DEPTH_RELATIVE` of the depth are
added in quadrature.

A profile whose 1-sigma interval reaches either end of :data:`PROFILE_DEPTHS_M`, or whose total
sigma exceeds :data:`MAX_DEEP_SIGMA_M`, is ``not_characterised``; so is a core larger than the
AP type (:data:`MAX_WIDE_RATIO`): the template is of the AP mine. The diffusivity is not
estimated (the fill is assumed): it is NaN.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from clearfast_gis.thermal.error_budget import OFFSET_TERM_K, model_depth_variance
from clearfast_gis.thermal.inversion import Inversion

__all__ = ["DISC_RING_GAIN", "DISC_RING_GAIN_SIGMA", "MAX_DEEP_SIGMA_M", "PROFILE_DEPTHS_M",
           "MAX_WIDE_RATIO", "SHAPE_DEPTH_RELATIVE", "SHAPE_DEPTH_TERMS_M", "DepthProfile",
           "characterise_cores", "deep_inversion", "depth_profile", "model_sigma_m",
           "wide_ratio", "with_core_depths"]

#: Depths of the profile's reference curves, m (top of the object): from the shallow end of
#: the deep search to below its deepest template.
PROFILE_DEPTHS_M = tuple(float(d) for d in np.round(np.arange(0.03, 0.1601, 0.0025), 4))

#: Prior of the gain: the core's disc-minus-ring contrast on the mosaics over the modelled
#: axis contrast of the reference mine at its true depth. The 18 AP mines at 6-8 cm of the deep
#: scenario's seeds 20-22 at their true positions gave 0.30-0.59, median 0.48, the six at
#: 5-10 cm of trial seed 5 0.47-0.55 (``benchmarks/deep_depth.py``; the thermal model's own mine
#: on an unblurred image 0.62-0.66):
#: the disc mean is below the axis value, the ring holds part of the halo, the mosaics blur.
DISC_RING_GAIN = 0.5

#: 1-sigma width of the gain's prior: 25 %, twice the spread measured, for other AP types
#: and fills than the simulated one.
DISC_RING_GAIN_SIGMA = 0.125

#: The model's depth-proportional 1-sigma term of the shape fit: the site soil's diffusivity,
#: uncertain by about 10 %, sets the diurnal wave's damping depth, which goes as its square
#: root (5 % of the depth), as in the general inversion
#: (:data:`clearfast_gis.thermal.error_budget.DEPTH_RELATIVE`).
SHAPE_DEPTH_RELATIVE = 0.05

#: The shape fit's constant 1-sigma depth terms, m. Its template is the reference AP mine's
#: axis curve, taken through the disc-ring gain's prior, not the anomaly's own object measured
#: as the chain measured it (the general inversion's :data:`~clearfast_gis.thermal.
#: error_budget.DEPTH_TERMS_M`): a mine of another height than the reference costs 0.3 cm
#: (tables for 5 and 8 cm objects against an 8 cm mine: 0.3-0.5 cm for 3 cm of height), the
#: ring's halo 0.1 cm, the soil terms 0.2 cm.
SHAPE_DEPTH_TERMS_M = {"object_height": 0.003, "background_ring": 0.001, "soil_terms": 0.002}

#: Total depth sigma above which a deep core's depth is not characterised, m: at most this,
#: a 2-sigma error stays within 2 cm.
MAX_DEEP_SIGMA_M = 0.01


#: A core whose disc-ring contrast at the largest mine type's radius is more than this times
#: (rms over the scans) its contrast at the reference radius is no AP-sized object alone: an
#: AT mine (its ring at the AP radius lies inside it: 3.6-4.8 for the AT mine at 7 cm of the
#: deep scenario's seeds 20-22, 2.8-5.6 for the AT mines at 5-15 cm of trial seed 5), or a mine
#: beside something stronger. The AP template does not give its depth. AP mines at 5-10 cm of
#: those surveys: 0.21-0.86 (23 of 24).
MAX_WIDE_RATIO = 1.5


def wide_ratio(contrast_k: np.ndarray, wide_contrast_k: np.ndarray) -> float:
    """RMS over the scans with both of the wide disc-ring contrast over the reference one
    (both (N,), K); NaN without a common scan."""
    c = np.asarray(contrast_k, dtype=np.float64)
    w = np.asarray(wide_contrast_k, dtype=np.float64)
    ok = np.isfinite(c) & np.isfinite(w)
    if not ok.any() or not np.any(c[ok]):
        return math.nan
    return float(np.sqrt(np.mean(w[ok] ** 2) / np.mean(c[ok] ** 2)))


@dataclass(frozen=True)
class DepthProfile:
    """Output of :func:`depth_profile`.

    Attributes
    ----------
    depths_m : float (D,)
        The profile's depths, m.
    chi2 : float (D,)
        Profile chi-square at each depth (noise scaled, priors included).
    depth_m : float
        Best depth, m.
    fit_sigma_m : float
        Half width of ``chi2 <= min + 1``, m (inf when the interval reaches an end).
    gain, offset_k : float
        Best gain and offset (K) at ``depth_m``'s grid node.
    noise_scale : float
        Factor the noise was scaled by (>= 1).
    residual_rms_k : float
        Root-mean-square misfit at the best node, K.
    model_k : float (S,)
        Best-fit contrast at the scans (NaN where the input has none), K.
    at_end : bool
        The 1-sigma interval reaches the first or last depth.
    """

    depths_m: np.ndarray
    chi2: np.ndarray
    depth_m: float
    fit_sigma_m: float
    gain: float
    offset_k: float
    noise_scale: float
    residual_rms_k: float
    model_k: np.ndarray
    at_end: bool


def _fit_node(c: np.ndarray, w: np.ndarray, m: np.ndarray) -> tuple[float, float, float]:
    """Gain and offset (priors included) of one reference curve; returns (chi2 of the data,
    gain, offset). ``c``, ``m``: (S,) K; ``w``: (S,) inverse noise sigmas, 1/K."""
    design = np.vstack([np.stack([m * w, w], axis=1),
                        [[1.0 / DISC_RING_GAIN_SIGMA, 0.0], [0.0, 1.0 / OFFSET_TERM_K]]])
    target = np.concatenate([c * w, [DISC_RING_GAIN / DISC_RING_GAIN_SIGMA, 0.0]])
    beta = np.linalg.lstsq(design, target, rcond=None)[0]
    return float(np.sum(((c - beta[0] * m - beta[1]) * w) ** 2)), float(beta[0]), float(beta[1])


def _profile(c, w, templates) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Data chi2, gain and offset per template."""
    fits = np.array([_fit_node(c, w, m) for m in templates])
    return fits[:, 0], fits[:, 1], fits[:, 2]


def _priors(g: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Chi-square of the gain and offset priors."""
    return ((g - DISC_RING_GAIN) / DISC_RING_GAIN_SIGMA) ** 2 + (b / OFFSET_TERM_K) ** 2


def _interval(depths: np.ndarray, chi2: np.ndarray, best: int) -> tuple[float, float, bool]:
    """Ends of ``chi2 <= min + 1`` around ``best`` (linear between nodes), and whether it
    reaches an end of the grid."""
    level = chi2[best] + 1.0
    ends = []
    for step in (-1, 1):
        i = best
        while 0 <= i + step < depths.size and chi2[i + step] <= level:
            i += step
        if not 0 <= i + step < depths.size:
            return float(depths[0]), float(depths[-1]), True
        j = i + step
        t = (level - chi2[i]) / (chi2[j] - chi2[i])
        ends.append(float(depths[i] + t * (depths[j] - depths[i])))
    return ends[0], ends[1], False


def depth_profile(contrast_k: np.ndarray, noise_k: np.ndarray, templates_k: np.ndarray,
                  depths_m=PROFILE_DEPTHS_M) -> DepthProfile:
    """The depth profile of one deep core (module notes).

    Parameters
    ----------
    contrast_k : float (S,)
        The core's disc-minus-ring contrast per scan, K (NaN = no data).
    noise_k : float (S,)
        Its 1-sigma noise per scan, K (non-finite or <= 0: the median of the others).
    templates_k : float (D, S)
        The reference mine's modelled contrast at ``depths_m`` and the scan times, K
        (:func:`clearfast_gis.thermal.daycontrast.reference_curves`).
    depths_m : float (D,)
        Increasing depths, m.

    Returns
    -------
    DepthProfile
    """
    c = np.asarray(contrast_k, dtype=np.float64)
    s = np.asarray(noise_k, dtype=np.float64)
    templates = np.asarray(templates_k, dtype=np.float64)
    depths = np.asarray(depths_m, dtype=np.float64)
    if templates.shape != (depths.size, c.size) or s.shape != c.shape:
        raise ValueError(f"templates {templates.shape}, contrast {c.shape}, noise {s.shape}, "
                         f"{depths.size} depths")
    ok = np.isfinite(c) & np.all(np.isfinite(templates), axis=0)
    good = ok & np.isfinite(s) & (s > 0)
    if ok.sum() < 4 or not good.any():
        raise ValueError("a depth profile needs at least 4 scans with data and noise")
    s = np.where(good, s, np.median(s[good]))
    w, cc, mm = 1.0 / s[ok], c[ok], templates[:, ok]
    data, g, b = _profile(cc, w, mm)
    scale = math.sqrt(max(1.0, float(np.min(data)) / max(int(ok.sum()) - 2, 1)))
    if scale > 1.0:
        data, g, b = _profile(cc, w / scale, mm)
    chi2 = data + _priors(g, b)
    best = int(np.argmin(chi2))
    lo, hi, at_end = _interval(depths, chi2, best)
    depth = float(depths[best])
    if 0 < best < depths.size - 1:
        y0, y1, y2 = chi2[best - 1:best + 2]
        curvature = y0 - 2.0 * y1 + y2
        if curvature > 0:
            step = 0.5 * (y0 - y2) / curvature
            depth += step * 0.5 * (depths[best + 1] - depths[best - 1])
    model = np.full(c.shape, np.nan)
    model[ok] = g[best] * mm[best] + b[best]
    rms = float(np.sqrt(np.mean((cc - model[ok]) ** 2)))
    return DepthProfile(depths, chi2, float(depth), math.inf if at_end else 0.5 * (hi - lo),
                        float(g[best]), float(b[best]), scale, rms, model, at_end)


def model_sigma_m(depth_m: float) -> float:
    """The model's 1-sigma depth terms at ``depth_m`` (m), in quadrature, m
    (:mod:`clearfast_gis.thermal.error_budget`)."""
    return math.sqrt(model_depth_variance(depth_m, SHAPE_DEPTH_RELATIVE, SHAPE_DEPTH_TERMS_M))


def deep_inversion(profile: DepthProfile, noise_k: float, ratio: float = 0.0) -> Inversion:
    """A deep core's characterisation from its depth profile: depth and total sigma (fit and
    model terms), status ``ok`` or ``not_characterised`` (module notes; also when ``ratio``,
    :func:`wide_ratio`, exceeds :data:`MAX_WIDE_RATIO` or is NaN); the diffusivity is not
    estimated (NaN).

    Parameters
    ----------
    profile : DepthProfile
    noise_k : float
        The contrast's typical 1-sigma noise, K (the median of the scans').
    ratio : float
        The core's :func:`wide_ratio`.
    """
    sigma = math.hypot(profile.fit_sigma_m, model_sigma_m(profile.depth_m))
    status = "not_characterised" if (profile.at_end or sigma > MAX_DEEP_SIGMA_M
                                     or not ratio <= MAX_WIDE_RATIO) else "ok"
    seen = profile.model_k[np.isfinite(profile.model_k)] - profile.offset_k
    return Inversion(depth_m=profile.depth_m, depth_sigma_m=sigma, alpha_m2s=math.nan,
                     alpha_sigma_m2s=math.nan, log10_alpha_sigma=math.nan, status=status,
                     residual_rms_k=profile.residual_rms_k, noise_k=float(noise_k),
                     peak_contrast_k=float(np.max(np.abs(seen))) if seen.size else 0.0,
                     correlation=math.nan, model_contrast_k=profile.model_k)


def with_core_depths(inversions: dict[int, Inversion], cores: dict[int, Inversion]
                     ) -> dict[int, Inversion]:
    """The characterisation with each deep core's depth (``cores``, from
    :func:`characterise_cores`) in place of the general inversion's (``inversions``), unless
    the core's is flagged and the general one is ``ok`` (an AT mine found as a core: the
    inversion models the object by its footprint, the profile by the AP type). Both by
    feature id; a new dict."""
    out = dict(inversions)
    for key, inv in cores.items():
        general = inversions.get(key)
        if inv.status == "ok" or general is None or general.status != "ok":
            out[key] = inv
    return out


def characterise_cores(features: list, templates_k: np.ndarray,
                       depths_m=PROFILE_DEPTHS_M) -> dict[int, Inversion]:
    """Depth of every deep core among ``features`` (those with ``core_contrast_k``) from its
    depth profile (:func:`depth_profile`, :func:`deep_inversion`).

    Parameters
    ----------
    features : list of AnomalyFeatures
    templates_k : float (D, N)
        The reference mine's modelled contrast at ``depths_m`` and the N scan times, K.
    depths_m : float (D,)

    Returns
    -------
    dict[int, Inversion]
        By feature id; cores seen in fewer than 4 scans are left out.
    """
    out: dict[int, Inversion] = {}
    for f in features:
        if f.core_contrast_k is None:
            continue
        contrast = np.asarray(f.core_contrast_k, dtype=np.float64)
        noise = np.asarray(f.core_noise_k, dtype=np.float64)
        if np.sum(np.isfinite(contrast)) < 4:
            continue
        ratio = math.nan if f.core_wide_contrast_k is None \
            else wide_ratio(contrast, f.core_wide_contrast_k)
        out[f.id] = deep_inversion(depth_profile(contrast, noise, templates_k, depths_m),
                                   float(np.nanmedian(noise)), ratio)
    return out
