"""Material cue: how close an estimated diffusivity is to explosive, stone, metal or soil."""

from __future__ import annotations

import numpy as np
from scipy.special import logsumexp

from clearfast_gis.thermal.materials import MATERIALS

CLASS_MEMBERS: dict[str, tuple[str, ...]] = {
    "explosive": ("tnt", "plastic"),
    "soil": ("dry_sand", "moist_sand"),
    "stone": ("stone",),
    "metal": ("steel", "aluminium"),
}
"""Cue classes and the materials that represent them (an explosive-filled object is the
fill inside a plastic casing, so both count as explosive-like)."""

CLASS_SPREAD_DEX = 0.15
"""Natural spread of a class's diffusivity in log10 units (about a factor 1.4)."""


def material_cue(alpha_m2s: float, sigma: float) -> dict[str, float | str]:
    """Likelihood-style closeness of a diffusivity to each material class.

    Each class is a mixture of its members' diffusivities in log10 space, each widened by
    :data:`CLASS_SPREAD_DEX` and by the estimate's own uncertainty
    ``sigma / (alpha ln 10)``; the likelihoods are normalised to sum to 1 (equal priors).

    Parameters
    ----------
    alpha_m2s : float
        Estimated diffusivity, m2 s-1.
    sigma : float
        Its 1-sigma uncertainty, m2 s-1.

    Returns
    -------
    dict
        ``explosive``, ``soil``, ``stone``, ``metal``: probabilities in [0, 1];
        ``best``: the most likely class, or ``"unknown"`` for a missing or invalid estimate
        (all probabilities 0.25 then).
    """
    names = list(CLASS_MEMBERS)
    if not (np.isfinite(alpha_m2s) and alpha_m2s > 0):
        return {**dict.fromkeys(names, 0.25), "best": "unknown"}
    x = np.log10(alpha_m2s)
    s_meas = sigma / (alpha_m2s * np.log(10.0)) if np.isfinite(sigma) and sigma > 0 else 0.0
    width2 = CLASS_SPREAD_DEX**2 + s_meas**2
    log_like = np.empty(len(names))
    for i, cls in enumerate(names):
        mu = np.log10([MATERIALS[m].alpha_m2s for m in CLASS_MEMBERS[cls]])
        log_like[i] = logsumexp(-0.5 * (x - mu) ** 2 / width2) - np.log(mu.size)
    p = np.exp(log_like - logsumexp(log_like))
    probs = {n: float(v) for n, v in zip(names, p, strict=True)}
    return {**probs, "best": max(probs, key=probs.get)}
