"""Tabulated band radiance and its fast inverse (paper Eq. 5, apparent temperature).

:class:`BandTable` holds, for one spectral band,

- a forward table on a uniform temperature grid with exact radiances and exact derivatives,
  evaluated by cubic Hermite interpolation (error ~1e-12 relative);
- an inverse table uniform in *radiance* (65,536 nodes by default) with exact temperatures at
  the nodes, evaluated by index arithmetic and linear interpolation: no search, one memory
  gather per pixel. Its interpolation error is bounded at construction against the exact inverse
  at every interval midpoint and the table is refined until the bound is below
  ``max_error_k`` (default 1 mK).

:func:`apparent_temperature_paper` is the paper's own scheme (radiances at 0.1 K steps, the two
nearest points, linear interpolation), kept as the reference path. The compiled table look-ups
are in :mod:`clearfast_gis.radiometry._kernels`, the reference in
:mod:`clearfast_gis.radiometry._reference`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis import kernels
from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry._kernels import _uniform_hermite
from clearfast_gis.radiometry.planck import (
    band_radiance,
    band_radiance_derivative,
    band_temperature,
)


class BandTable:
    """Band radiance and apparent temperature for one spectral band, tabulated.

    Parameters
    ----------
    lambda_min_um, lambda_max_um : float
        Band limits, micrometres.
    t_min_k, t_max_k : float
        Temperature range of the tables, kelvin. Radiances outside ``[L(t_min), L(t_max)]``
        invert to NaN; temperatures outside the range are evaluated by the closed form.
    n_inverse : int
        Initial number of nodes of the radiance-uniform inverse table.
    max_error_k : float
        Bound on the inverse table's interpolation error, kelvin; the table is refined
        (doubled) until its midpoint error is below this.
    forward_step_k : float
        Step of the forward (temperature-uniform, cubic Hermite) table, kelvin.

    Attributes
    ----------
    t_grid_k, radiance_grid : ndarray
        The forward table (uniform in temperature).
    inverse_radiance0, inverse_step : float
        First radiance and step of the inverse table, W m-2 sr-1.
    inverse_t_k : ndarray
        Temperatures at the inverse table's nodes, kelvin.
    inverse_error_k : float
        Largest interpolation error of the inverse table found at construction, kelvin.
    """

    def __init__(
        self,
        lambda_min_um: float,
        lambda_max_um: float,
        t_min_k: float = 200.0,
        t_max_k: float = 400.0,
        n_inverse: int = 65536,
        max_error_k: float = 1e-3,
        forward_step_k: float = 0.05,
    ) -> None:
        if not (0 < t_min_k < t_max_k):
            raise InvalidInput(f"need 0 < t_min_k < t_max_k, got {t_min_k}, {t_max_k}",
                               field="t_min_k")
        self.lambda_min_um = float(lambda_min_um)
        self.lambda_max_um = float(lambda_max_um)
        self.t_min_k = float(t_min_k)
        self.t_max_k = float(t_max_k)
        n_fwd = int(np.ceil((t_max_k - t_min_k) / forward_step_k)) + 1
        self.t_grid_k = np.linspace(t_min_k, t_max_k, n_fwd)
        self._dt_k = float(self.t_grid_k[1] - self.t_grid_k[0])
        self.radiance_grid = band_radiance(self.t_grid_k, lambda_min_um, lambda_max_um)
        self._dradiance_grid = band_radiance_derivative(self.t_grid_k, lambda_min_um,
                                                        lambda_max_um)
        self._build_inverse(int(n_inverse), float(max_error_k))

    def _exact_inverse(self, radiance: np.ndarray) -> np.ndarray:
        return band_temperature(radiance, self.lambda_min_um, self.lambda_max_um,
                                self.t_min_k - 1.0, self.t_max_k + 1.0)

    def _build_inverse(self, n: int, max_error_k: float) -> None:
        l0, l1 = float(self.radiance_grid[0]), float(self.radiance_grid[-1])
        for _ in range(6):
            rad = np.linspace(l0, l1, n)
            t_nodes = self._exact_inverse(rad)
            t_nodes[0], t_nodes[-1] = self.t_min_k, self.t_max_k
            mid = 0.5 * (rad[:-1] + rad[1:])
            err = float(np.max(np.abs(0.5 * (t_nodes[:-1] + t_nodes[1:])
                                      - self._exact_inverse(mid))))
            if err <= max_error_k:
                break
            n = 2 * n
        self.inverse_radiance0 = l0
        self.inverse_step = (l1 - l0) / (n - 1)
        self.inverse_t_k = t_nodes
        self.inverse_error_k = err

    def radiance(self, t_k: ArrayLike) -> np.ndarray:
        """Band radiance of a blackbody at ``t_k`` (Eq. 2).

        Parameters
        ----------
        t_k : array_like
            Temperature, kelvin, any shape.

        Returns
        -------
        ndarray of float64
            Band radiance, W m-2 sr-1, shape of ``t_k``.
        """
        t = np.asarray(t_k, dtype=np.float64)
        flat = np.ascontiguousarray(t).ravel()
        out = np.empty(flat.shape, dtype=np.float64)
        _uniform_hermite(flat, self.t_min_k, self._dt_k, self.radiance_grid,
                         self._dradiance_grid, out)
        outside = np.isnan(out) & ~np.isnan(flat)
        if np.any(outside):
            out[outside] = band_radiance(flat[outside], self.lambda_min_um, self.lambda_max_um)
        return out.reshape(t.shape)

    def temperature(self, radiance: ArrayLike, dtype: type = np.float32) -> np.ndarray:
        """Apparent temperature of a band radiance (Eq. 5), fast path.

        Parameters
        ----------
        radiance : array_like
            Band radiance, W m-2 sr-1, any shape (float32 or float64).
        dtype : numpy dtype
            Output dtype (default float32).

        Returns
        -------
        ndarray
            Apparent temperature, kelvin, shape of ``radiance``; NaN for NaN input or a
            radiance outside the table's temperature range. With ``--kernels reference``:
            :func:`apparent_temperature_paper` (the paper's 0.1 K table and ``np.interp``).
        """
        return kernels.kernel("inverse_planck")(self, np.asarray(radiance), dtype)

    def temperature_exact(self, radiance: ArrayLike) -> np.ndarray:
        """Apparent temperature by Newton iteration on the closed form (slow reference).

        Parameters
        ----------
        radiance : array_like
            Band radiance, W m-2 sr-1.

        Returns
        -------
        ndarray of float64
            Temperature, kelvin; NaN outside ``[t_min_k, t_max_k]``.
        """
        return band_temperature(radiance, self.lambda_min_um, self.lambda_max_um,
                                self.t_min_k, self.t_max_k)


def paper_table(table: BandTable, step_k: float = 0.1) -> tuple[np.ndarray, np.ndarray]:
    """The paper's inversion table: temperatures at ``step_k`` steps and their radiances.

    Parameters
    ----------
    table : BandTable
        Band and temperature range.
    step_k : float
        Temperature step, kelvin (the paper uses 0.1 K).

    Returns
    -------
    t_k, radiance : ndarray of float64, shape (N,)
        Computed once per table and step, then cached on ``table``.
    """
    cache = table.__dict__.setdefault("_paper_tables", {})
    if step_k not in cache:
        n = int(round((table.t_max_k - table.t_min_k) / step_k)) + 1
        t_k = np.linspace(table.t_min_k, table.t_min_k + (n - 1) * step_k, n)
        cache[step_k] = (t_k, band_radiance(t_k, table.lambda_min_um, table.lambda_max_um))
    return cache[step_k]


def apparent_temperature_paper(
    radiance: ArrayLike, table: BandTable, step_k: float = 0.1
) -> np.ndarray:
    """Apparent temperature by the paper's scheme (Eq. 5, section 3.6).

    Radiances are tabulated at ``step_k`` (0.1 K) steps; for each radiance the two nearest
    table points are found (binary search, :func:`numpy.interp`) and interpolated linearly.

    Parameters
    ----------
    radiance : array_like
        Band radiance, W m-2 sr-1, any shape.
    table : BandTable
        Band and temperature range.
    step_k : float
        Table step, kelvin.

    Returns
    -------
    ndarray of float64
        Apparent temperature, kelvin; NaN outside the table.
    """
    t_k, rad = paper_table(table, step_k)
    return np.interp(np.asarray(radiance, dtype=np.float64), rad, t_k,
                     left=np.nan, right=np.nan)


