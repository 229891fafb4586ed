"""Stop-and-go scan-mission planner (paper §2.2).

From the platform height and position, the camera (resolution, aperture, model) and the area
rectangle, the planner chooses rows of constant tilt from the far edge of the area to the near
edge, overlapping by the requested fraction along the line of sight, and pan steps within each
row overlapping by the same fraction across, in serpentine order (the pan direction alternates
from row to row, so the head never swings back). Coverage is verified by projecting the frame
footprints onto the ground: their union must contain the area rectangle.

Each frame is summarised by a conservative box in (azimuth, elevation) of the level pan/tilt
base: for the equiangular model this box is the frame itself (paper Eq. 6); for a pinhole it is
the largest such box inside the frame outline.

Area and platform share one planar metric frame (local metres or the survey CRS); pan angles
are grid azimuths in that frame (``pan_zero_azimuth_deg = 0``), tilt angles are elevations.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import shapely
from shapely.geometry import Polygon, box

from clearfast_gis.errors import InvalidInput
from clearfast_gis.geometry.cameras import Camera, EquiangularCamera, PinholeCamera
from clearfast_gis.geometry.pose import CameraPose, angles_from_direction
from clearfast_gis.geometry.projection import frame_footprint

#: clock-aligned scan intervals in minutes (divisors of an hour)
_CLOCK_MINUTES = (1, 2, 3, 4, 5, 6, 10, 12, 15, 20, 30, 60)


@dataclass(frozen=True)
class AngularBox:
    """A frame's conservative extent in the level base frame, degrees relative to its axis
    azimuth (``±half_az_deg``) and absolute elevations (``bottom_deg`` .. ``top_deg``)."""

    half_az_deg: float
    bottom_deg: float
    top_deg: float

    @property
    def height_deg(self) -> float:
        """Vertical extent, degrees."""
        return self.top_deg - self.bottom_deg


def angular_box(camera: Camera, elevation_deg: float, samples_per_edge: int = 64) -> AngularBox:
    """The (azimuth, elevation) box inside a frame whose axis is at ``elevation_deg``.

    Exact for :class:`EquiangularCamera`; for a pinhole, the horizontal half-width is the
    smallest azimuth offset along the left and right edges, the top the lowest elevation along
    the top edge and the bottom the highest along the bottom edge.
    """
    if isinstance(camera, EquiangularCamera):
        half_v = math.degrees((camera.height - 1) / 2.0 * camera.ifov_rad)
        return AngularBox(camera.aperture_deg / 2.0, elevation_deg - half_v,
                          elevation_deg + half_v)
    pose = CameraPose(np.zeros(3), 0.0, elevation_deg)
    n = samples_per_edge
    w, h = camera.width - 1.0, camera.height - 1.0
    t = np.linspace(0.0, 1.0, n)
    def angles(u: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        az, el = angles_from_direction(camera.rays(u, v, pose))
        return np.degrees(az), np.degrees(el)
    az_l, _ = angles(np.zeros(n), t * h)
    az_r, _ = angles(np.full(n, w), t * h)
    _, el_t = angles(t * w, np.zeros(n))
    _, el_b = angles(t * w, np.full(n, h))
    half = float(min(np.min(np.abs(az_l)), np.min(np.abs(az_r))))
    return AngularBox(half, float(np.max(el_b)), float(np.min(el_t)))


def default_platform_xy(area: Sequence[float], offset_m: float = 3.0) -> tuple[float, float]:
    """Beside the middle of the area's long side, ``offset_m`` outside (south or west)."""
    xmin, ymin, xmax, ymax = (float(a) for a in area)
    if xmax - xmin >= ymax - ymin:
        return ((xmin + xmax) / 2.0, ymin - offset_m)
    return (xmin - offset_m, (ymin + ymax) / 2.0)


def clock_interval_minutes(scan_minutes: float) -> float:
    """The shortest clock-aligned interval (a divisor of an hour, or whole hours) that is not
    shorter than a scan, so scans start at the same minutes every hour: 25 -> 30."""
    for m in _CLOCK_MINUTES:
        if m >= scan_minutes - 1e-9:
            return float(m)
    return float(60 * math.ceil(scan_minutes / 60.0 - 1e-9))


def _range_limits(area: tuple[float, float, float, float],
                  xy: tuple[float, float]) -> tuple[float, float]:
    xmin, ymin, xmax, ymax = area
    px, py = xy
    dx = max(xmin - px, 0.0, px - xmax)
    dy = max(ymin - py, 0.0, py - ymax)
    far = max(math.hypot(x - px, y - py) for x in (xmin, xmax) for y in (ymin, ymax))
    return math.hypot(dx, dy), far


def azimuth_interval(area: tuple[float, float, float, float], xy: tuple[float, float],
                     rho_min: float, rho_max: float) -> tuple[float, float] | None:
    """Azimuth range (degrees, unwrapped around the area's centre direction) of the points of
    the area rectangle whose horizontal distance from ``xy`` is in [rho_min, rho_max].

    Exact: the extremes lie at rectangle corners inside the annulus or where the rectangle's
    edges cross the annulus circles. None when no point of the area is in the annulus. The
    platform must be outside the area.
    """
    xmin, ymin, xmax, ymax = area
    px, py = xy
    corners = np.array([[xmin, ymin], [xmax, ymin], [xmax, ymax], [xmin, ymax]])
    rel = corners - [px, py]
    cand = [c for c in rel if rho_min - 1e-9 <= math.hypot(*c) <= rho_max + 1e-9]
    for k in range(4):
        a, b = rel[k], rel[(k + 1) % 4]
        d = b - a
        qa, qb = float(d @ d), 2.0 * float(a @ d)
        for rho in (rho_min, rho_max):
            if not math.isfinite(rho):
                continue
            qc = float(a @ a) - rho * rho
            disc = qb * qb - 4.0 * qa * qc
            if disc < 0.0:
                continue
            for s in ((-qb - math.sqrt(disc)) / (2 * qa), (-qb + math.sqrt(disc)) / (2 * qa)):
                if -1e-12 <= s <= 1.0 + 1e-12:
                    cand.append(a + min(max(s, 0.0), 1.0) * d)
    if not cand:
        return None
    pts = np.array(cand)
    centre = math.degrees(math.atan2((xmin + xmax) / 2 - px, (ymin + ymax) / 2 - py))
    az = np.degrees(np.arctan2(pts[:, 0], pts[:, 1]))
    az = centre + (az - centre + 180.0) % 360.0 - 180.0
    return float(az.min()), float(az.max())


@dataclass
class ScanRow:
    """One row of constant tilt: its tilt, vertical extent and pan positions (in order)."""

    tilt_deg: float
    box: AngularBox
    azimuth_range_deg: tuple[float, float]
    pans_deg: list[float] = field(default_factory=list)


def _solve_elevation(camera: Camera, fn, lo: float = -90.0, hi: float = 90.0) -> float:
    """Root of ``fn(angular_box(camera, E))`` in E, by Brent's method."""
    from scipy.optimize import brentq

    try:
        return float(brentq(lambda e: fn(angular_box(camera, e)), lo, hi, xtol=1e-9))
    except ValueError:
        raise InvalidInput(
            "the pinhole frames cannot reach the near edge of the area this close to the nadir;"
            " move the platform farther from the area or plan with the equiangular model",
            None, "platform") from None


def _chain(camera: Camera, first_deg: float, n_rows: int, overlap: float) -> list[float]:
    """Axis elevations of ``n_rows`` rows, each overlapping the previous by ``overlap`` of its
    own vertical extent (far to near)."""
    rows = [first_deg]
    for _ in range(n_rows - 1):
        prev = angular_box(camera, rows[-1])
        target = prev.bottom_deg
        if isinstance(camera, EquiangularCamera):
            b = angular_box(camera, 0.0)
            rows.append(target + overlap * b.height_deg - b.top_deg)
        else:
            rows.append(_solve_elevation(
                camera, lambda bx, t=target: bx.top_deg - t - overlap * bx.height_deg,
                -90.0, rows[-1]))
    return rows


def _rows_elevations(camera: Camera, far_deg: float, near_deg: float,
                     overlap: float) -> list[float]:
    """Axis elevations from the far edge (top of the first frame at ``far_deg``) to the near
    edge (bottom of the last frame at or below ``near_deg``), evenly spread: the overlap is
    raised from ``overlap`` until the last frame's bottom is exactly at ``near_deg``."""
    if isinstance(camera, EquiangularCamera):
        first = far_deg - angular_box(camera, 0.0).top_deg
    else:
        first = _solve_elevation(camera, lambda bx: bx.top_deg - far_deg, -90.0, far_deg)
    if angular_box(camera, first).bottom_deg <= near_deg:
        return [first]
    n = 1
    rows = [first]
    while angular_box(camera, rows[-1]).bottom_deg > near_deg:
        n += 1
        rows = _chain(camera, first, n, overlap)
        if n > 10000:
            raise InvalidInput("more than 10000 rows: the aperture is too small or the overlap "
                               "too large", None, "overlap")

    def end(o: float) -> float:
        return angular_box(camera, _chain(camera, first, n, o)[-1]).bottom_deg - near_deg

    # end() rises with the overlap: greedy rows end at or below the near edge (end <= 0)
    lo, hi = overlap, 0.999
    if end(hi) <= 0.0:
        return rows
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if end(mid) <= 0.0:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-7:
            break
    return _chain(camera, first, n, lo)


def _pan_centres(a0: float, a1: float, half: float, overlap: float) -> list[float]:
    span = a1 - a0
    if span <= 2.0 * half:
        return [0.5 * (a0 + a1)]
    step = 2.0 * half * (1.0 - overlap)
    n = int(math.ceil((span - 2.0 * half) / step - 1e-9)) + 1
    return list(np.linspace(a0 + half, a1 - half, n))


@dataclass
class MissionPlan:
    """A planned scan mission: the mission.json content, rows and checks.

    Attributes
    ----------
    mission : dict
        mission.json content (docs/contracts.md §2).
    camera : camera model used for planning
    rows : list of ScanRow
        Rows far to near, pans in acquisition order.
    coverage_fraction : float
        Fraction of the area rectangle inside the union of the frame footprints.
    scan_minutes : float
        Duration of one scan, minutes.
    range_m : tuple
        Smallest and largest horizontal distance from the platform to the area, metres.
    """

    mission: dict
    camera: Camera
    rows: list[ScanRow]
    coverage_fraction: float
    scan_minutes: float
    range_m: tuple[float, float]

    def poses(self) -> list[CameraPose]:
        """Camera pose of every position, in mission order."""
        p = self.mission["platform"]
        c = (p["x_m"], p["y_m"], p["height_m"])
        return [CameraPose(c, q["pan_deg"], q["tilt_deg"]) for q in self.mission["positions"]]

    def summary(self) -> dict:
        """Figures for people: counts, angles, pixel sizes, timing, coverage."""
        m = self.mission
        tilts = [r.tilt_deg for r in self.rows]
        pans = [q["pan_deg"] for q in m["positions"]]
        return {
            "model": "equiangular" if isinstance(self.camera, EquiangularCamera) else "pinhole",
            "platform_x_m": m["platform"]["x_m"], "platform_y_m": m["platform"]["y_m"],
            "height_m": m["platform"]["height_m"],
            "range_min_m": round(self.range_m[0], 3), "range_max_m": round(self.range_m[1], 3),
            "rows": len(self.rows),
            "positions_per_row": [len(r.pans_deg) for r in self.rows],
            "tilt_min_deg": round(min(tilts), 3), "tilt_max_deg": round(max(tilts), 3),
            "pan_min_deg": round(min(pans), 3), "pan_max_deg": round(max(pans), 3),
            "images_per_scan": m["images_per_scan"], "n_scans": m["n_scans"],
            "images_total": m["images_total"],
            "scan_minutes": self.scan_minutes,
            "scan_interval_min": m["scan_interval_s"] / 60.0,
            "seconds_per_position": round(self.scan_minutes * 60.0 / m["images_per_scan"], 2),
            "ground_resolution_m": dict(m["ground_resolution_m"]),
            "coverage_fraction": round(self.coverage_fraction, 6),
        }


def _check(condition: bool, message: str, field: str) -> None:
    if not condition:
        raise InvalidInput(message, None, field)


def _ground_resolution(camera: Camera, poses: list[CameraPose], area_poly: Polygon,
                       special: np.ndarray, lattice: int = 24) -> dict[str, float]:
    """Smallest/largest ground distance between neighbouring pixels, across (along a row) and
    along (down a column), over the pixels whose ground point lies in the area."""
    nu = lattice + 1
    nv = max(2, int(round(lattice * camera.height / camera.width))) + 1
    uu, vv = np.meshgrid(np.linspace(0.0, camera.width - 2.0, nu),
                         np.linspace(0.0, camera.height - 2.0, nv))
    base_u, base_v = uu.ravel(), vv.ravel()
    across, along = [], []
    for pose in poses:
        uv = camera.project(np.column_stack([special, np.zeros(len(special))]), pose)
        inside = camera.in_frame(uv) & (uv[:, 0] <= camera.width - 2) \
            & (uv[:, 1] <= camera.height - 2)
        u = np.concatenate([base_u, uv[inside, 0]])
        v = np.concatenate([base_v, uv[inside, 1]])
        g0 = camera.ground_points(u, v, pose)
        gu = camera.ground_points(u + 1.0, v, pose)
        gv = camera.ground_points(u, v + 1.0, pose)
        ok = np.isfinite(g0[:, 0]) & shapely.contains_xy(area_poly.buffer(1e-9), g0[:, 0],
                                                         g0[:, 1])
        across.append(np.linalg.norm(gu - g0, axis=1)[ok])
        along.append(np.linalg.norm(gv - g0, axis=1)[ok])
    a = np.concatenate(across)
    b = np.concatenate(along)
    a, b = a[np.isfinite(a)], b[np.isfinite(b)]
    if a.size == 0 or b.size == 0:
        return {"across_min": 0.0, "across_max": 0.0, "along_min": 0.0, "along_max": 0.0}
    return {"across_min": round(float(a.min()), 5), "across_max": round(float(a.max()), 5),
            "along_min": round(float(b.min()), 5), "along_max": round(float(b.max()), 5)}


def build_plan(height_m: float, aperture_deg: float, resolution: Sequence[int],
               area: Sequence[float], platform_xy: Sequence[float] | None = None,
               overlap: float = 0.3, scan_minutes: float = 25.0, hours: float = 24.0,
               camera_model: str = "equiangular",
               interval_minutes: float | None = None) -> MissionPlan:
    """Plan a stop-and-go mission; see :func:`plan_mission` for the parameters."""
    _check(isinstance(height_m, (int, float)) and math.isfinite(height_m) and height_m > 0,
           "expected a positive height in metres", "height")
    _check(isinstance(aperture_deg, (int, float)) and 0.0 < aperture_deg < 180.0,
           "expected a horizontal aperture in degrees, 0 to 180", "aperture")
    _check(len(resolution) == 2 and all(int(r) == r and r >= 2 for r in resolution),
           "expected 2 integers of at least 2 (WxH)", "resolution")
    _check(len(area) == 4 and all(math.isfinite(float(a)) for a in area),
           "expected 4 numbers XMIN,YMIN,XMAX,YMAX", "area")
    xmin, ymin, xmax, ymax = (float(a) for a in area)
    _check(xmax > xmin and ymax > ymin, "expected XMIN < XMAX and YMIN < YMAX", "area")
    _check(0.0 <= overlap <= 0.9, "expected an overlap fraction from 0 to 0.9", "overlap")
    _check(scan_minutes > 0, "expected a positive number of minutes", "scan-minutes")
    _check(hours > 0, "expected a positive number of hours", "hours")
    _check(interval_minutes is None or interval_minutes >= scan_minutes,
           "the interval between scans must not be shorter than a scan", "interval-minutes")
    width, height = int(resolution[0]), int(resolution[1])
    if camera_model == "equiangular":
        camera: Camera = EquiangularCamera(width, height, float(aperture_deg))
    elif camera_model == "pinhole":
        camera = PinholeCamera.from_aperture(width, height, float(aperture_deg))
    else:
        raise InvalidInput("expected \"equiangular\" or \"pinhole\"", None, "model")
    rect = (xmin, ymin, xmax, ymax)
    xy = default_platform_xy(rect) if platform_xy is None else \
        (float(platform_xy[0]), float(platform_xy[1]))
    _check(all(math.isfinite(c) for c in xy), "expected 2 numbers X,Y", "platform")
    rho_min, rho_max = _range_limits(rect, xy)
    _check(rho_min > 0.0, "the platform must stand outside the area (it is a hazardous area)",
           "platform")
    h = float(height_m)
    far_deg = -math.degrees(math.atan2(h, rho_max))
    near_deg = -math.degrees(math.atan2(h, rho_min))
    elevations = _rows_elevations(camera, far_deg, near_deg, float(overlap))

    rows: list[ScanRow] = []
    for k, e in enumerate(elevations):
        bx = angular_box(camera, e)
        r_far = math.inf if bx.top_deg >= 0.0 else h / math.tan(math.radians(-bx.top_deg))
        r_near = h / math.tan(math.radians(min(89.999999, -bx.bottom_deg))) \
            if bx.bottom_deg < 0.0 else math.inf
        interval = azimuth_interval(rect, xy, r_near, r_far)
        if interval is None:
            continue
        pans = _pan_centres(interval[0], interval[1], bx.half_az_deg, float(overlap))
        if k % 2 == 1:
            pans = pans[::-1]
        rows.append(ScanRow(round(e, 4), bx, interval, [round(p, 4) for p in pans]))

    positions = []
    for row in rows:
        for pan in row.pans_deg:
            positions.append({"index": len(positions), "pan_deg": pan, "tilt_deg": row.tilt_deg})
    poses = [CameraPose((xy[0], xy[1], h), p["pan_deg"], p["tilt_deg"]) for p in positions]
    area_poly = box(*rect)
    footprints = [frame_footprint(camera, p, samples_per_edge=64) for p in poses]
    union = shapely.unary_union(footprints)
    coverage = 1.0 - area_poly.difference(union).area / area_poly.area

    nearest = (min(max(xy[0], xmin), xmax), min(max(xy[1], ymin), ymax))
    special = np.array([nearest, (xmin, ymin), (xmin, ymax), (xmax, ymin), (xmax, ymax)])
    resolution_m = _ground_resolution(camera, poses, area_poly, special)

    interval_min = clock_interval_minutes(scan_minutes) if interval_minutes is None \
        else float(interval_minutes)
    n_scans = max(1, int(math.floor(hours * 60.0 / interval_min + 1e-9)))
    mission = {
        "format": "clearfast-mission",
        "format_version": 1,
        "platform": {"x_m": xy[0], "y_m": xy[1], "height_m": h},
        "area": [xmin, ymin, xmax, ymax],
        "camera": {"resolution": [width, height], "aperture_deg": float(aperture_deg)},
        "overlap": float(overlap),
        "n_scans": n_scans,
        "scan_interval_s": interval_min * 60.0,
        "duration_h": float(hours),
        "images_per_scan": len(positions),
        "images_total": n_scans * len(positions),
        "ground_resolution_m": resolution_m,
        "positions": positions,
    }
    return MissionPlan(mission, camera, rows, float(coverage), float(scan_minutes),
                       (rho_min, rho_max))


def plan_mission(height_m: float, aperture_deg: float, resolution: Sequence[int],
                 area: Sequence[float], platform_xy: Sequence[float] | None = None,
                 overlap: float = 0.3, scan_minutes: float = 25.0, hours: float = 24.0,
                 camera_model: str = "equiangular",
                 interval_minutes: float | None = None) -> dict:
    """Plan a stop-and-go pan/tilt scanning mission (mission.json content).

    Parameters
    ----------
    height_m : float
        Camera height above the ground, metres.
    aperture_deg : float
        Horizontal aperture (2 alpha), degrees.
    resolution : (int, int)
        Frame width and height in pixels.
    area : (xmin, ymin, xmax, ymax)
        Area rectangle, metres.
    platform_xy : (x, y), optional
        Platform position in the area's frame (outside the area); default
        :func:`default_platform_xy`.
    overlap : float
        Overlap between neighbouring frames, fraction of a frame, along and across.
    scan_minutes : float
        Duration of one scan, minutes.
    hours : float
        Duration of the diurnal survey, hours.
    camera_model : {"equiangular", "pinhole"}
        Projection model (pinhole: distortion-free with the same horizontal aperture).
    interval_minutes : float, optional
        Time between scan starts; default :func:`clock_interval_minutes` of ``scan_minutes``.

    Returns
    -------
    dict
        mission.json content following ``schemas/mission.schema.json``.

    Raises
    ------
    InvalidInput
        For invalid parameters, naming the parameter.
    """
    return build_plan(height_m, aperture_deg, resolution, area, platform_xy, overlap,
                      scan_minutes, hours, camera_model, interval_minutes).mission


def format_summary(summary: dict) -> str:
    """The summary as a two-column text table."""
    res = summary["ground_resolution_m"]
    rows = [
        ("camera model", summary["model"]),
        ("platform (x, y, height) m", f"{summary['platform_x_m']:g}, "
                                      f"{summary['platform_y_m']:g}, {summary['height_m']:g}"),
        ("range to area m", f"{summary['range_min_m']:.2f} .. {summary['range_max_m']:.2f}"),
        ("tilt rows", f"{summary['rows']} ({summary['tilt_max_deg']:.2f} .. "
                      f"{summary['tilt_min_deg']:.2f} deg)"),
        ("pan range deg", f"{summary['pan_min_deg']:.2f} .. {summary['pan_max_deg']:.2f}"),
        ("positions per row", " ".join(str(n) for n in summary["positions_per_row"])),
        ("images per scan", str(summary["images_per_scan"])),
        ("scans", f"{summary['n_scans']} (every {summary['scan_interval_min']:g} min)"),
        ("images in total", str(summary["images_total"])),
        ("time per position s", f"{summary['seconds_per_position']:.2f}"),
        ("pixel across m", f"{res['across_min']:.4f} .. {res['across_max']:.4f}"),
        ("pixel along m", f"{res['along_min']:.4f} .. {res['along_max']:.4f}"),
        ("area covered", f"{100.0 * summary['coverage_fraction']:.4f} %"),
    ]
    w = max(len(k) for k, _ in rows)
    return "\n".join(f"{k.ljust(w)}  {v}" for k, v in rows)
