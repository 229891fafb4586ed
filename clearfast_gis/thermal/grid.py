"""Finite-volume grids for the soil: depth faces and radial faces."""

from __future__ import annotations

import numpy as np


def depth_faces(
    bottom_m: float = 0.5,
    dz_top_m: float = 0.001,
    dz_fine_m: float = 0.005,
    fine_to_m: float = 0.30,
    growth: float = 1.2,
) -> np.ndarray:
    """Cell faces in depth, fine at the surface and through the layer objects occupy.

    Cells grow geometrically (``growth``) from ``dz_top_m`` to ``dz_fine_m``, stay at
    ``dz_fine_m`` down to ``fine_to_m`` and grow again to ``bottom_m``.

    Returns
    -------
    ndarray, shape (Nz + 1,)
        Face depths, metres, from 0 to ``bottom_m``.
    """
    faces = [0.0]
    dz = dz_top_m
    while faces[-1] < fine_to_m - 1e-12:
        faces.append(min(faces[-1] + dz, fine_to_m))
        dz = min(dz * growth, dz_fine_m)
    dz = dz_fine_m
    while faces[-1] < bottom_m - 1e-12:
        dz *= growth
        nxt = faces[-1] + dz
        if bottom_m - nxt < 0.5 * dz * growth:
            nxt = bottom_m
        faces.append(min(nxt, bottom_m))
    return np.asarray(faces)


def radial_faces(
    radius_m: float, outer_m: float = 0.5, n_inside: int = 8, growth: float = 1.25
) -> np.ndarray:
    """Radial cell faces with one face exactly on the object's rim.

    ``n_inside`` equal cells across the object, then cells growing by ``growth`` out to
    ``radius_m + outer_m`` (the side boundary, no flux).

    Returns
    -------
    ndarray, shape (Nr + 1,)
        Face radii, metres, from 0.
    """
    inside = np.linspace(0.0, radius_m, n_inside + 1)
    faces = list(inside)
    dr = radius_m / n_inside
    end = radius_m + outer_m
    while faces[-1] < end - 1e-12:
        dr *= growth
        faces.append(faces[-1] + dr)
    return np.asarray(faces)


def bisect(faces: np.ndarray) -> np.ndarray:
    """Faces with every cell split in two (the twice-finer grid)."""
    mid = 0.5 * (faces[1:] + faces[:-1])
    out = np.empty(2 * faces.size - 1)
    out[0::2] = faces
    out[1::2] = mid
    return out


def centres(faces: np.ndarray) -> np.ndarray:
    """Cell centres (mid-points of adjacent faces)."""
    return 0.5 * (faces[1:] + faces[:-1])
