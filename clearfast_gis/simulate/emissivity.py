"""Spectral emissivity of the scene's surfaces, per material and band.

Values are smooth curves through typical laboratory spectra (ASTER/ECOSTRESS spectral library
shapes): quartz-rich sandy soil shows its reststrahlen dip at 8-9.5 um (lower emissivity), which
moisture fills in; freshly disturbed soil brings coarse quartz grains to the surface and deepens
the dip; limestone has its carbonate feature near 11.2 um; vegetation is close to a black body;
painted mine casings ~0.9; rusty steel debris ~0.3; the cold marker is polished aluminium.
A band's emissivity is the curve at the band's centre wavelength (linear interpolation).
"""

from __future__ import annotations

import numpy as np

#: Wavelength nodes of the curves, micrometres.
WAVELENGTH_UM = np.array([7.5, 8.5, 9.2, 10.0, 11.0, 11.5, 12.5, 14.0])

#: Surface material -> emissivity at :data:`WAVELENGTH_UM`.
SPECTRA: dict[str, np.ndarray] = {
    "dry_soil": np.array([0.90, 0.84, 0.85, 0.93, 0.96, 0.965, 0.97, 0.97]),
    "moist_soil": np.array([0.95, 0.93, 0.935, 0.96, 0.975, 0.975, 0.98, 0.98]),
    "disturbed_soil": np.array([0.88, 0.80, 0.82, 0.91, 0.95, 0.96, 0.965, 0.965]),
    "vegetation": np.array([0.97, 0.975, 0.975, 0.98, 0.98, 0.98, 0.98, 0.98]),
    "stone": np.array([0.94, 0.95, 0.955, 0.96, 0.95, 0.93, 0.96, 0.96]),
    "mine_casing": np.array([0.90, 0.90, 0.90, 0.91, 0.91, 0.91, 0.91, 0.91]),
    "metal_debris": np.array([0.28, 0.29, 0.30, 0.30, 0.31, 0.31, 0.32, 0.32]),
    "marker_hot": np.array([0.95, 0.95, 0.95, 0.95, 0.95, 0.95, 0.95, 0.95]),
    "marker_cold": np.array([0.07, 0.07, 0.07, 0.08, 0.08, 0.08, 0.08, 0.08]),
}


def band_emissivity(material: str, lambda_min_um: float, lambda_max_um: float) -> float:
    """Emissivity of ``material`` in the band ``[lambda_min_um, lambda_max_um]`` (0-1).

    Parameters
    ----------
    material : str
        A key of :data:`SPECTRA`.
    lambda_min_um, lambda_max_um : float
        Band edges, micrometres.
    """
    centre = 0.5 * (lambda_min_um + lambda_max_um)
    return float(np.interp(centre, WAVELENGTH_UM, SPECTRA[material]))
