"""The linear conformal transform of the paper's Eq. 3 (rotation, translation, optional scale).

Pixel coordinates are (u, v) = (column, row) with pixel centres at integers. A transform maps a
point ``x`` of the *fixed* image to the point of the *moving* image that shows the same ground:

    x_moving = s * R(angle) @ (x - c) + c + t,   R(a) = [[cos a, sin a], [-sin a, cos a]]

with ``c`` the rotation centre (the fixed image centre for registrations), ``t = (tx, ty)`` and
``s`` the isotropic scale. ``R`` is Eq. 3's matrix as written in the paper (row vector times
matrix), which is also the layout of :func:`cv2.getRotationMatrix2D`: a positive angle turns the
sampling grid counter-clockwise as seen on screen (rows growing downwards).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np


@dataclass(frozen=True)
class ConformalTransform:
    """A conformal map from fixed to moving pixel coordinates, with its registration record.

    Parameters
    ----------
    angle_rad : float
        Rotation angle of Eq. 3, radians.
    tx_px, ty_px : float
        Translation (columns, rows), pixels.
    scale : float
        Isotropic scale (moving pixels per fixed pixel), 1 for Eq. 3 proper.
    metric : float
        Mutual information at the solution, nats (NaN when not from a registration).
    n_samples : int
        Number of fixed samples that overlapped the moving image at the solution.
    converged : bool
        True when the registration reached a trustworthy optimum (see
        :func:`clearfast_gis.registration.register_conformal`).
    center_px : tuple of float
        Rotation centre ``(u, v)`` in fixed pixel coordinates.
    """

    angle_rad: float = 0.0
    tx_px: float = 0.0
    ty_px: float = 0.0
    scale: float = 1.0
    metric: float = math.nan
    n_samples: int = 0
    converged: bool = True
    center_px: tuple[float, float] = (0.0, 0.0)

    @classmethod
    def identity(cls, center_px: tuple[float, float] = (0.0, 0.0)) -> ConformalTransform:
        """The identity map with rotation centre ``center_px``."""
        return cls(center_px=(float(center_px[0]), float(center_px[1])))

    @classmethod
    def from_matrix(
        cls, matrix: np.ndarray, center_px: tuple[float, float] = (0.0, 0.0), **record: object
    ) -> ConformalTransform:
        """The conformal transform closest to a 2x3 (or 3x3) affine ``matrix``.

        The linear part is projected on ``s R(angle)`` (least squares); ``record`` sets
        ``metric``, ``n_samples`` or ``converged``.
        """
        m = np.asarray(matrix, dtype=np.float64)
        if m.shape not in ((2, 3), (3, 3)):
            raise ValueError(f"expected a 2x3 or 3x3 matrix, got shape {m.shape}")
        a = m[:2, :2]
        # s R(angle) = [[p, q], [-q, p]] with p = s cos, q = s sin (least-squares projection)
        p = 0.5 * (a[0, 0] + a[1, 1])
        q = 0.5 * (a[0, 1] - a[1, 0])
        scale = math.hypot(p, q)
        angle = math.atan2(q, p)
        c = np.asarray(center_px, dtype=np.float64)
        lin = np.array([[p, q], [-q, p]])
        t = m[:2, 2] - c + lin @ c
        return cls(angle, float(t[0]), float(t[1]), float(scale),
                   center_px=(float(c[0]), float(c[1])), **record)  # type: ignore[arg-type]

    def linear(self) -> np.ndarray:
        """The 2x2 linear part ``s R(angle)``."""
        cs = self.scale * math.cos(self.angle_rad)
        sn = self.scale * math.sin(self.angle_rad)
        return np.array([[cs, sn], [-sn, cs]])

    def matrix(self) -> np.ndarray:
        """2x3 float64 matrix ``[A | b]`` with ``x_moving = A x_fixed + b``.

        This is the matrix :func:`cv2.warpAffine` wants with ``WARP_INVERSE_MAP`` to resample
        the moving image onto the fixed grid.
        """
        a = self.linear()
        c = np.asarray(self.center_px, dtype=np.float64)
        b = c + np.array([self.tx_px, self.ty_px]) - a @ c
        return np.hstack([a, b[:, None]])

    def apply(self, points: np.ndarray) -> np.ndarray:
        """Map fixed pixel coordinates to moving pixel coordinates.

        Parameters
        ----------
        points : array_like, shape (N, 2) or (2,)
            ``(u, v)`` fixed pixel coordinates.

        Returns
        -------
        ndarray, float64, same shape
            ``(u, v)`` moving pixel coordinates.
        """
        p = np.asarray(points, dtype=np.float64)
        m = self.matrix()
        return p @ m[:, :2].T + m[:, 2]

    def inverse(self) -> ConformalTransform:
        """The map from moving to fixed coordinates (same centre, same registration record)."""
        if self.scale <= 0 or not math.isfinite(self.scale):
            raise ValueError(f"transform with scale {self.scale} has no inverse")
        inv_s = 1.0 / self.scale
        a_inv = ConformalTransform(-self.angle_rad, scale=inv_s).linear()
        t = -a_inv @ np.array([self.tx_px, self.ty_px])
        return replace(self, angle_rad=-self.angle_rad, tx_px=float(t[0]), ty_px=float(t[1]),
                       scale=inv_s)

    def compose(self, other: ConformalTransform) -> ConformalTransform:
        """``self o other``: the map ``x -> self.apply(other.apply(x))``.

        If ``other`` maps image A to image B and ``self`` maps B to C, the result maps A to C.
        It keeps ``other``'s rotation centre; ``converged`` is the conjunction of both, the
        metric is NaN and ``n_samples`` 0.
        """
        ms = np.vstack([self.matrix(), [0.0, 0.0, 1.0]])
        mo = np.vstack([other.matrix(), [0.0, 0.0, 1.0]])
        return ConformalTransform.from_matrix(
            ms @ mo, other.center_px, converged=bool(self.converged and other.converged))

    def with_center(self, center_px: tuple[float, float]) -> ConformalTransform:
        """The same map expressed with another rotation centre."""
        out = ConformalTransform.from_matrix(self.matrix(), center_px)
        return replace(out, metric=self.metric, n_samples=self.n_samples,
                       converged=self.converged)

    def scaled(self, factor: float) -> ConformalTransform:
        """The same map on images resampled by ``factor`` (new pixel = old pixel * factor).

        Used between pyramid levels: ``factor = 0.5`` goes one level coarser.
        """
        c = self.center_px
        return replace(self, tx_px=self.tx_px * factor, ty_px=self.ty_px * factor,
                       center_px=(c[0] * factor, c[1] * factor))
