"""Scene objects (mines, clutter, markers) and their placement from a seed.

Object positions here are *local* metres (x east, y north from the survey area's south-west
corner); :mod:`clearfast_gis.simulate.truth` adds the area origin to write them in the survey
CRS.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from clearfast_gis.simulate.config import SimConfig

KINDS = ("at_mine", "ap_mine", "stone", "metal", "vegetation", "disturbed_soil", "marker")
"""Object kinds, as written in ``truth/objects.csv``."""

MINE_KINDS = ("at_mine", "ap_mine")
"""The kinds that are mines (whose body can be any of the mine fills)."""

#: Nominal sizes (diameter, height), metres. AT M6A2: 33.7 cm; AP M2A4: 10.4 cm.
AT_DIAMETER_M = 0.337
AT_HEIGHT_M = 0.094
AP_DIAMETER_M = 0.104
AP_HEIGHT_M = 0.08

#: Burial depths (top of the object below the surface) a preset draws mines from, metres.
MINE_DEPTHS_M = (0.0, 0.01, 0.02, 0.03, 0.05, 0.08, 0.10, 0.15)


@dataclass(frozen=True)
class SceneObject:
    """One object of the scene.

    Attributes
    ----------
    id : str
        Identifier, unique in the scene (``AT01``, ``ST03``, ...).
    kind : str
        One of :data:`KINDS`.
    x_m, y_m : float
        Centre in local metres (east, north of the area's south-west corner).
    depth_m : float
        Depth of the object's top below the surface (0 = surface-laid), metres.
    diameter_m : float
        Diameter (equivalent diameter of patches), metres.
    height_m : float
        Height of the object body (mines, stones, debris), metres; 0 for patches.
    variant : str
        Kind-specific variant: ``hot``/``cold`` plates for markers, ``""`` otherwise.
    aspect : float
        Minor/major axis ratio of elliptic patches (1 for discs).
    angle_deg : float
        Orientation of the patch's major axis, degrees counter-clockwise from east.
    material : str
        The body's material (:data:`clearfast_gis.thermal.materials.MATERIALS` name) where
        it is not the kind's (:data:`clearfast_gis.simulate.surface.OBJECT_MATERIAL`): a
        mine's fill (:data:`clearfast_gis.thermal.materials.MINE_FILLS`); ``""`` for the
        kind's.
    """

    id: str
    kind: str
    x_m: float
    y_m: float
    depth_m: float
    diameter_m: float
    height_m: float = 0.0
    variant: str = ""
    aspect: float = 1.0
    angle_deg: float = 0.0
    material: str = ""

    @property
    def radius_m(self) -> float:
        """Radius, metres."""
        return 0.5 * self.diameter_m


def default_height_m(kind: str, diameter_m: float) -> float:
    """Body height of an object of ``kind`` and ``diameter_m`` (metres)."""
    if kind == "at_mine":
        return AT_HEIGHT_M
    if kind == "ap_mine":
        return AP_HEIGHT_M
    if kind == "stone":
        return 0.5 * diameter_m
    if kind == "metal":
        return 0.01
    return 0.0


_PREFIX = {"at_mine": "AT", "ap_mine": "AP", "stone": "ST", "metal": "MD",
           "vegetation": "VG", "disturbed_soil": "DS", "marker": "MK"}


def draw_objects(config: SimConfig, rng: np.random.Generator) -> list[SceneObject]:
    """Draw the preset's objects from ``rng``: non-overlapping, inside the area.

    Markers go near the area's corners (surveyed reference points), patches (vegetation,
    disturbed soil) first, then mines, stones and debris on free ground. Mine depths cycle
    through :data:`MINE_DEPTHS_M` so every preset holds surface-laid and buried mines. With
    ``config.mine_fills`` each mine's body is then drawn from those materials (after every
    placement, so the layout is the same as without).

    Parameters
    ----------
    config : SimConfig
        Area size and object counts.
    rng : numpy.random.Generator
        The survey's random generator.

    Returns
    -------
    list of SceneObject
    """
    w, h = config.area_width_m, config.area_length_m
    counts = config.objects
    placed: list[SceneObject] = []

    def free(x: float, y: float, r: float) -> bool:
        for o in placed:
            if np.hypot(o.x_m - x, o.y_m - y) < o.radius_m + r + 0.25:
                return False
        return True

    def place(kind: str, n: int, diam_fn, depth_fn, variant_fn=lambda i: "",
              patch: bool = False, margin: float = 0.4) -> None:
        for i in range(n):
            d = float(diam_fn())
            for _ in range(200):
                x = float(rng.uniform(margin + d / 2, w - margin - d / 2))
                y = float(rng.uniform(margin + d / 2, h - margin - d / 2))
                if free(x, y, d / 2):
                    break
            else:
                continue
            aspect = float(rng.uniform(0.5, 0.9)) if patch else 1.0
            angle = float(rng.uniform(0.0, 180.0)) if patch else 0.0
            placed.append(SceneObject(
                id=f"{_PREFIX[kind]}{i + 1:02d}", kind=kind, x_m=round(x, 3), y_m=round(y, 3),
                depth_m=float(depth_fn(i)), diameter_m=round(d, 3),
                height_m=default_height_m(kind, d), variant=variant_fn(i), aspect=aspect,
                angle_deg=angle))

    corners = [(0.6, 0.6), (w - 0.6, h - 0.6), (w - 0.6, 0.6), (0.6, h - 0.6)]
    for i in range(min(counts.marker, 8)):
        cx, cy = corners[i % 4]
        if i >= 4:
            cx, cy = w / 2 + (-1) ** i * w / 4, h / 2
        placed.append(SceneObject(id=f"MK{i + 1:02d}", kind="marker", x_m=cx, y_m=cy,
                                  depth_m=0.0, diameter_m=0.3, height_m=0.0,
                                  variant="hot" if i % 2 == 0 else "cold"))
    place("vegetation", counts.vegetation, lambda: rng.uniform(0.6, 1.4), lambda i: 0.0,
          patch=True)
    place("disturbed_soil", counts.disturbed_soil, lambda: rng.uniform(0.5, 1.0),
          lambda i: 0.0, patch=True)
    at_depths = (0.0, 0.0, 0.05, 0.10, 0.02, 0.15)
    place("at_mine", counts.at_mine, lambda: AT_DIAMETER_M,
          lambda i: at_depths[i % len(at_depths)])
    place("ap_mine", counts.ap_mine, lambda: AP_DIAMETER_M,
          lambda i: MINE_DEPTHS_M[(i + 1) % len(MINE_DEPTHS_M)])
    place("stone", counts.stone, lambda: np.round(rng.uniform(0.06, 0.24), 2), lambda i: 0.0)
    place("metal", counts.metal, lambda: np.round(rng.uniform(0.04, 0.12), 2),
          lambda i: 0.0 if i % 2 == 0 else 0.02)
    if config.mine_fills:
        fills = config.mine_fills
        placed = [replace(o, material=fills[int(rng.integers(len(fills)))])
                  if o.kind in MINE_KINDS else o for o in placed]
    return placed
