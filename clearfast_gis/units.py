"""Unit conversions. Names carry their units: ``_k`` kelvin, ``_c`` degrees Celsius."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

ZERO_CELSIUS_K = 273.15
"""0 degrees C in kelvin."""

STEFAN_BOLTZMANN = 5.670374419e-8
"""Stefan-Boltzmann constant, W m-2 K-4."""

STANDARD_PRESSURE_HPA = 1013.25
"""Standard sea-level pressure, hPa."""


def c_to_k(t_c: ArrayLike) -> np.ndarray:
    """Degrees Celsius to kelvin."""
    return np.asarray(t_c, dtype=float) + ZERO_CELSIUS_K


def k_to_c(t_k: ArrayLike) -> np.ndarray:
    """Kelvin to degrees Celsius."""
    return np.asarray(t_k, dtype=float) - ZERO_CELSIUS_K
