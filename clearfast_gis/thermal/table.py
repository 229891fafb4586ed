"""Per-site lookup table of forward runs for the depth / diffusivity inversion."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike
from scipy.interpolate import CubicSpline, NdBSpline, make_interp_spline
from scipy.stats import rice

from clearfast_gis.errors import InvalidInput
from clearfast_gis.parallel import thread_map
from clearfast_gis.progress import Progress
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.thermal.forward import Bottom, BuriedObject, ObjectModel
from clearfast_gis.thermal.materials import MATERIALS, Material, Soil

DEFAULT_DEPTHS_M = np.array(
    [0.0, 0.005, 0.01, 0.015, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.10, 0.12, 0.15, 0.20]
)
"""Depth nodes of the table, m (the inversion's depth bounds are the first and last)."""

DEFAULT_LOG10_ALPHA = np.array([-7.5, -7.25, -7.0, -6.75, -6.5, -6.25, -6.0, -5.5, -5.0, -4.5])
"""log10 diffusivity nodes, m2 s-1 (3e-8 .. 3e-5: plastics and explosives to steel)."""

DEFAULT_HEIGHT_M = 0.08
"""Object height the inversion assumes, m: that of the mine types of the surveys (AP M2A4
8 cm, AT M6A2 9.4 cm). A 5 cm object fitted to an 8 cm mine's contrast puts it 0.3-0.5 cm
too deep (BENCHMARKS.md, "Depth bias")."""

CENTRES = ("axis", "disc")
"""What the table's contrast is taken over: the surface on the object's axis, or the mean over
the disc of the object's radius (what the chain measures: the mean over the half-maximum
footprint, whose radius is the table's)."""

OVER_RATIOS = np.array([0.25, 0.5, 0.625, 0.75, 0.875, 1.0, 1.125, 1.25, 1.5, 1.75, 2.0, 2.25,
                        2.5, 2.75, 3.0, 3.5, 4.0, 5.0, 6.0, 8.0, 10.0])
"""Radii of the discs a "disc" table also averages over, in object radii. The chain averages an
anomaly over its half-maximum footprint, whose radius is not the object's (smaller over a
shallow object, larger over a deep one, larger again after blur), and subtracts a ring around
it (1.5-2.5 blob radii) that lies in the object's thermal halo: the table gives both
(:meth:`SiteTable.contrast_for`). Between nodes the disc's integral is linear in the squared
radius (exact within a model cell); beyond the last node, past the model block's edge, it is
constant (no contrast outside the block)."""

OBJECT_RHO_C_JM3K = MATERIALS["tnt"].rho_c_jm3k
"""Volumetric heat capacity assumed for the object, J m-3 K-1. Solids span only 1.3-3.6e6
while conductivity spans 0.2-240 W/m/K, so the object is parametrised by its diffusivity at
the explosive fill's rho c (``k = alpha rho c``)."""


def object_material(alpha_m2s: float, rho_c_jm3k: float = OBJECT_RHO_C_JM3K) -> Material:
    """The homogeneous object of diffusivity ``alpha_m2s`` used by the inversion."""
    return Material("object", alpha_m2s * rho_c_jm3k, rho_c_jm3k, 0.9, 0.3,
                    "inversion parametrisation", "object")


@dataclass(frozen=True)
class SiteTable:
    """Centre-minus-background contrast for a grid of objects at one site.

    Attributes
    ----------
    radii_m : ndarray, shape (Q,)
        Object radii, m (increasing).
    depths_m : ndarray, shape (Nd,)
        Depth nodes, m.
    log10_alpha : ndarray, shape (Na,)
        log10 diffusivity nodes.
    time_s : ndarray, shape (Tg,)
        Model step times covering the scans, UTC epoch seconds.
    contrast_k : ndarray, shape (Q, Nd, Na, Tg)
        Surface temperature on the object's axis (``centre`` "axis") or its mean over the
        disc of the object's radius ("disc"), minus the undisturbed surface, K.
    background_k : ndarray, shape (Tg,)
        Modelled undisturbed surface temperature, K.
    height_m, object_rho_c_jm3k : float
        Object height and assumed volumetric heat capacity.
    centre : str
        One of :data:`CENTRES`.
    over_ratios : ndarray, shape (K,), optional
        Disc radii in object radii (:data:`OVER_RATIOS`) of ``over_k`` ("disc" tables).
    over_k : ndarray, shape (Q, K, Nd, Na, Tg), optional
        Mean surface temperature over those discs minus the undisturbed surface, K (the area
        beyond the model block counted as undisturbed).
    """

    radii_m: np.ndarray
    depths_m: np.ndarray
    log10_alpha: np.ndarray
    time_s: np.ndarray
    contrast_k: np.ndarray
    background_k: np.ndarray
    height_m: float
    object_rho_c_jm3k: float
    centre: str = "axis"
    over_ratios: np.ndarray | None = None
    over_k: np.ndarray | None = None

    def contrast_for(self, radius_m: float, time_s: ArrayLike, over_m: float | None = None,
                     ring_m: tuple[float, float] | None = None,
                     blur_m: float = 0.0) -> np.ndarray:
        """Table contrast of an object of ``radius_m`` at ``time_s``, shape (Nd, Na, S), K.

        Linear in log radius between the two nearest radii (exact on a node); up to 15 %
        outside the range the nearest radius is used. "disc" tables (:data:`OVER_RATIOS`):
        ``over_m`` (m), the mean over the disc of that radius instead of the object's;
        ``ring_m`` (inner, outer radius, m), minus the mean over that ring instead of the
        undisturbed surface; ``blur_m``, the surface seen through a Gaussian blur of that
        sigma (m; the mosaics', :func:`clearfast_gis.mosaic.blur.mosaic_blur_sigma_m`).
        """
        t = np.asarray(time_s, dtype=float)
        if t.min() < self.time_s[0] - 1.0 or t.max() > self.time_s[-1] + 1.0:
            raise InvalidInput("scan times outside the table's period", field="time_s")
        lr, lq = np.log(radius_m), np.log(self.radii_m)
        if lr < lq[0] - np.log(1.15) or lr > lq[-1] + np.log(1.15):
            raise InvalidInput(
                f"radius {radius_m:.3f} m outside the table's {self.radii_m[0]:.3f}-"
                f"{self.radii_m[-1]:.3f} m", field="radius_m")
        values = self.contrast_k
        if over_m is not None or ring_m is not None or blur_m > 0:
            if self.over_k is None:
                raise InvalidInput("this table holds no disc means", field="over_m")
            over = radius_m if over_m is None else float(over_m)
            values = self._integral(radius_m, over, blur_m) / over**2
            if ring_m is not None:
                a, b = (float(v) for v in ring_m)
                if not 0 <= a < b:
                    raise InvalidInput("ring radii must be 0 <= inner < outer", field="ring_m")
                values = values - (self._integral(radius_m, b, blur_m)
                                   - self._integral(radius_m, a, blur_m)) / (b**2 - a**2)
        if lq.size == 1 or lr <= lq[0]:
            c = values[0]
        elif lr >= lq[-1]:
            c = values[-1]
        else:
            i = int(np.searchsorted(lq, lr)) - 1
            w = (lr - lq[i]) / (lq[i + 1] - lq[i])
            c = (1 - w) * values[i] + w * values[i + 1]
        return CubicSpline(self.time_s, c, axis=-1)(t)

    def _integral(self, radius_m: float, over_m: float, blur_m: float = 0.0) -> np.ndarray:
        """``over_m**2`` times the mean contrast over the disc of ``over_m`` (m) around
        objects of ``radius_m``, per table radius: (Q, Nd, Na, Tg), K m2. Linear in the
        squared radius between the ratio nodes; below the first node the mean is the
        first node's, beyond the last the integral is the last node's.

        Through a Gaussian blur of sigma ``blur_m`` (m): each annulus between nodes (its
        contrast at its root-mean-square radius ``r``) contributes the share of it the blur
        keeps inside the disc, the Rice distribution's ``P(|r + blur| <= over_m)``.
        """
        x = np.asarray(self.over_ratios) * radius_m
        c = self.over_k * (x**2)[None, :, None, None, None]
        if blur_m > 0:
            shells = np.diff(c, axis=1, prepend=0.0)
            r = np.sqrt(0.5 * (x**2 + np.concatenate([[0.0], x[:-1]]) ** 2))
            kept = rice.cdf(over_m, r / blur_m, scale=blur_m)
            return np.einsum("qkdat,k->qdat", shells, kept)
        if over_m <= x[0]:
            return c[:, 0] * (over_m / x[0]) ** 2
        if over_m >= x[-1]:
            return c[:, -1]
        i = int(np.searchsorted(x, over_m)) - 1
        w = (over_m**2 - x[i] ** 2) / (x[i + 1] ** 2 - x[i] ** 2)
        return (1 - w) * c[:, i] + w * c[:, i + 1]


def contrast_spline(depths_m: np.ndarray, log10_alpha: np.ndarray, values: np.ndarray):
    """Tensor-product cubic interpolating spline of ``values`` (Nd, Na, S) over the grid.

    Returns an ``NdBSpline`` evaluated as ``spl(x (M, 2), nu=(i, j)) -> (M, S)``.
    """
    s1 = make_interp_spline(depths_m, values, k=3, axis=0)
    s2 = make_interp_spline(log10_alpha, s1.c, k=3, axis=1)
    return NdBSpline((s1.t, s2.t), np.moveaxis(s2.c, 0, 1), 3)


def build_site_table(
    forcing: Forcing,
    soil: Soil,
    radius_m: float | ArrayLike,
    scan_times_s: ArrayLike,
    height_m: float = DEFAULT_HEIGHT_M,
    depths_m: ArrayLike = DEFAULT_DEPTHS_M,
    log10_alpha: ArrayLike = DEFAULT_LOG10_ALPHA,
    object_rho_c_jm3k: float = OBJECT_RHO_C_JM3K,
    dt_s: float = 600.0,
    bottom: Bottom = None,
    progress: Progress | None = None,
    centre: str = "axis",
) -> SiteTable:
    """Run the forward model over a grid of depths and diffusivities for one site.

    Cost: ``len(radius) x len(depths) x len(log10_alpha)`` forward runs of ~6 ms with the
    fast kernels, ~25 ms with the reference ones (defaults: 150 runs, ~0.8 s per radius on
    one core, threads in parallel); every anomaly of those radii then inverts in
    milliseconds.

    Parameters
    ----------
    forcing : Forcing
        Weather.
    soil : Soil
        Soil with fitted diffusivity and surface parameters.
    radius_m : float or array_like, shape (Q,)
        Object radius or radii, m.
    scan_times_s : array_like
        Times the anomalies are observed at (the table covers their span), UTC epoch s.
    height_m : float
        Object height, m.
    depths_m, log10_alpha : array_like
        Grid nodes (increasing; at least 4 each for the cubic interpolation).
    object_rho_c_jm3k : float
        Assumed object volumetric heat capacity, J m-3 K-1.
    dt_s : float
        Model step, s.
    bottom : Bottom
        Bottom boundary.
    progress : Progress, optional
        Advanced once per forward run.
    centre : str
        "axis": the surface on the object's axis; "disc": its area-weighted mean over the
        disc of the object's radius (:data:`CENTRES`).

    Returns
    -------
    SiteTable
    """
    radii = np.sort(np.atleast_1d(np.asarray(radius_m, dtype=float)))
    depths = np.asarray(depths_m, dtype=float)
    la = np.asarray(log10_alpha, dtype=float)
    if np.any(radii <= 0):
        raise InvalidInput("radius must be positive", field="radius_m")
    if centre not in CENTRES:
        raise InvalidInput(f"centre must be one of {CENTRES}, got {centre!r}", field="centre")
    for name, arr in (("depths_m", depths), ("log10_alpha", la)):
        if arr.ndim != 1 or arr.size < 4 or np.any(np.diff(arr) <= 0):
            raise InvalidInput("need >= 4 increasing nodes", field=name)
    times = np.asarray(scan_times_s, dtype=float)
    span = np.array([times.min(), times.max()])
    contrast = over = None
    background = None
    disc = centre == "disc"
    if progress is not None:
        progress.start("thermal table", radii.size * depths.size * la.size)
    for q, radius in enumerate(radii):
        model = ObjectModel(soil, forcing, span, float(radius), dt_s=dt_s, bottom=bottom)
        first = model.setup.first_out - model.start
        bg_steps = model.column.surface_k[model.setup.first_out:, 0]
        weights = disc_weights(model.r_faces, float(radius) if disc else 0.0)
        # the contrast over OVER_RATIOS discs ("disc" tables), the ground beyond the block
        # undisturbed
        shares = np.column_stack([disc_share_weights(model.r_faces, x * radius)
                                  for x in OVER_RATIOS]) if disc else None
        if contrast is None:
            t_grid = model.setup.t[model.setup.first_out:]
            contrast = np.empty((radii.size, depths.size, la.size, t_grid.size))
            if disc:
                over = np.empty((radii.size, OVER_RATIOS.size, depths.size, la.size,
                                 t_grid.size))
            background = bg_steps
        def centre_series(ij: tuple[int, int], model=model, radius=radius, first=first,
                          weights=weights, shares=shares, bg_steps=bg_steps):
            obj = BuriedObject(float(radius), height_m, float(depths[ij[0]]),
                               object_material(10.0 ** la[ij[1]], object_rho_c_jm3k))
            steps = model.surface_steps(obj)[first:]
            if progress is not None:
                progress.advance(1)
            return (steps @ weights - bg_steps,
                    None if shares is None else (steps - bg_steps[:, None]) @ shares)

        cells = [(i, j) for i in range(depths.size) for j in range(la.size)]
        for (i, j), (series, discs) in zip(cells, thread_map(centre_series, cells),
                                           strict=True):
            contrast[q, i, j] = series
            if disc:
                over[q, :, i, j] = discs.T
    return SiteTable(radii, depths, la, t_grid, contrast, background, height_m,
                     object_rho_c_jm3k, centre, OVER_RATIOS.copy() if disc else None, over)


def disc_weights(r_faces: np.ndarray, radius_m: float) -> np.ndarray:
    """Area weights (Nr,) of the radial cells for the mean over the disc of ``radius_m``
    (m; 0: the axis cell alone), summing to 1."""
    if radius_m <= 0:
        w = np.zeros(r_faces.size - 1)
        w[0] = 1.0
        return w
    f = np.minimum(r_faces, radius_m)
    area = f[1:] ** 2 - f[:-1] ** 2
    return area / area.sum()


def disc_share_weights(r_faces: np.ndarray, radius_m: float) -> np.ndarray:
    """Weights (Nr,) of the radial cells' contrast in its mean over the disc of ``radius_m``
    (m, > 0) when the ground beyond the block (faces ``r_faces``) is undisturbed: each cell's
    share of the disc's area (summing to 1 within the block, to the block's share beyond)."""
    f = np.minimum(r_faces, radius_m)
    return (f[1:] ** 2 - f[:-1] ** 2) / radius_m**2
