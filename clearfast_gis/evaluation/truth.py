"""Scoring products against a simulated survey's ground truth (``truth/objects.csv``).

Used by ``clearfast demo``, the end-to-end tests and the accuracy benchmarks. The processing
chain itself never reads ``truth/``.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from clearfast_gis.simulate.objects import MINE_KINDS

MINE_CUES = ("at_mine", "ap_mine")

MATCH_MARGIN_M = 0.05
"""A suspect matches a mine within the mine's radius plus this margin (m)."""


def mine_match_radius_m(mine: dict) -> float:
    """The distance (m) within which a suspect matches ``mine`` (a truth record): its radius
    plus :data:`MATCH_MARGIN_M`."""
    return 0.5 * mine["diameter_m"] + MATCH_MARGIN_M


def nearest_match(x: np.ndarray, y: np.ndarray, mine: dict) -> int | None:
    """Index of the point (``x``, ``y``: (N,) m, the truth's CRS) nearest ``mine`` if it lies
    within :func:`mine_match_radius_m`, else None (also for no points)."""
    if not len(x):
        return None
    d = np.hypot(np.asarray(x, float) - mine["x"], np.asarray(y, float) - mine["y"])
    j = int(np.argmin(d))
    return j if d[j] <= mine_match_radius_m(mine) else None


@dataclass
class TruthScore:
    """How the suspects compare with the true mines.

    Attributes
    ----------
    n_mines, n_detected : int
        True mines (of the scored depths) and how many a suspect matched.
    n_suspects, n_false_alarms : int
        Suspects cued as mines, and those that match no mine.
    footprint_m2 : float
        Area of the mosaic footprint.
    centre_errors_m, diameter_rel_errors, depth_errors_m : list of float
        Per matched mine.
    missed : list of str
        Ids of the missed mines.
    """

    n_mines: int
    n_detected: int
    n_suspects: int
    n_false_alarms: int
    footprint_m2: float
    centre_errors_m: list[float] = field(default_factory=list)
    diameter_rel_errors: list[float] = field(default_factory=list)
    depth_errors_m: list[float] = field(default_factory=list)
    missed: list[str] = field(default_factory=list)

    @property
    def detection_probability(self) -> float:
        return self.n_detected / self.n_mines if self.n_mines else math.nan

    @property
    def false_alarms_per_m2(self) -> float:
        return self.n_false_alarms / self.footprint_m2 if self.footprint_m2 else math.nan

    def summary(self) -> str:
        """Human-readable one-paragraph summary."""
        def rms(v):
            return float(np.sqrt(np.mean(np.square(v)))) if v else math.nan

        lines = [
            f"ground truth: {self.n_detected} of {self.n_mines} mines detected "
            f"(Pd {self.detection_probability:.2f}); {self.n_false_alarms} false alarms among "
            f"{self.n_suspects} mine-cued suspects "
            f"({self.false_alarms_per_m2:.3f} per m2 of {self.footprint_m2:.0f} m2)",
            f"centre error RMS {100 * rms(self.centre_errors_m):.1f} cm; diameter error RMS "
            f"{100 * rms(self.diameter_rel_errors):.0f} %; depth error RMS "
            f"{100 * rms(self.depth_errors_m):.1f} cm over {len(self.depth_errors_m)} "
            "characterised mines",
        ]
        if self.missed:
            lines.append("missed: " + ", ".join(self.missed))
        return "\n".join(lines)


def read_truth_objects(survey: str | Path) -> list[dict]:
    """Rows of ``<survey>/truth/objects.csv`` with numeric fields converted (``survey`` is any
    folder holding ``truth/``: a simulated survey, or the device simulators' folder)."""
    with open(Path(survey) / "truth" / "objects.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    for r in rows:
        for k in ("x", "y", "depth_m", "diameter_m", "diffusivity_m2s"):
            r[k] = float(r[k]) if r.get(k) not in (None, "") else math.nan
    return rows


def score_against_truth(survey: str | Path, products: str | Path, max_depth_m: float = 0.05,
                        match_radius_m: float | None = None,
                        truth: str | Path | None = None) -> TruthScore:
    """Match suspects to true mines.

    A mine counts as detected when a suspect of any class lies within ``match_radius_m``
    (default: the mine's radius plus 5 cm) of its centre. False alarms are suspects cued
    ``at_mine``/``ap_mine`` that match no mine (buried or not).

    Parameters
    ----------
    survey, products : path
    max_depth_m : float
        Only mines surface-laid or buried at most this deep are scored for detection.
    truth : path, optional
        The folder holding ``truth/`` when it is not the survey (an acquisition from the
        device simulators: their folder).
    """
    import geopandas as gpd

    truth = read_truth_objects(survey if truth is None else truth)
    mines = [r for r in truth if r["kind"] in MINE_KINDS]
    gpkg = Path(products) / "anomalies.gpkg"
    sus = gpd.read_file(gpkg, layer="suspects")
    fp = gpd.read_file(gpkg, layer="footprint")
    footprint = fp.geometry.union_all() if len(fp) else None
    area = float(footprint.area) if footprint is not None else 0.0
    sx, sy = sus["x"].to_numpy(float), sus["y"].to_numpy(float)
    cue = sus["class_cue"].to_numpy(str)
    from shapely.geometry import Point

    score = TruthScore(0, 0, int(np.isin(cue, MINE_CUES).sum()), 0, area)
    matched_suspects = set()
    for m in mines:
        inside = footprint is None or footprint.contains(Point(m["x"], m["y"]))
        radius = match_radius_m if match_radius_m is not None else mine_match_radius_m(m)
        d = np.hypot(sx - m["x"], sy - m["y"]) if len(sx) else np.array([])
        hits = np.flatnonzero(d <= radius)
        matched_suspects.update(hits.tolist())
        if not inside or m["depth_m"] > max_depth_m + 1e-9:
            continue
        score.n_mines += 1
        if hits.size == 0:
            score.missed.append(f"{m['id']} ({m['kind']}, {100 * m['depth_m']:.0f} cm)")
            continue
        score.n_detected += 1
        j = hits[np.argmin(d[hits])]
        score.centre_errors_m.append(float(d[j]))
        score.diameter_rel_errors.append(float(sus["diameter_m"].iloc[j] / m["diameter_m"] - 1))
        if sus["status"].iloc[j] == "ok" and np.isfinite(sus["depth_m"].iloc[j]):
            score.depth_errors_m.append(float(sus["depth_m"].iloc[j] - m["depth_m"]))
    fa = [i for i in range(len(sus)) if cue[i] in MINE_CUES and i not in matched_suspects]
    score.n_false_alarms = len(fa)
    return score


@dataclass
class PlacementScore:
    """How the chain placed the thermal content on the mosaic grid, against the true poses.

    For a lattice of mosaic cells, the ground point whose radiance each cell actually holds is
    traced back through the cell's source frame: the chain put the cell's value from frame
    pixel (u, v) of that frame, placed with its pose; the true pose says which ground point
    that pixel saw. The difference is the content's displacement at the cell.

    Attributes
    ----------
    scans : list of int
        Scans in the products, in order.
    reference_scan : int
        The scan the temporal mosaics were co-registered to.
    pixel_size_m : float
        Mosaic cell size, metres.
    abs_rms_m : list of float
        Per scan, RMS displacement of the content over its cells, metres (absolute placement).
    relative_px : list of float
        Per scan, RMS over the cells both scans cover of the difference between the scan's
        displacement and the reference scan's, mosaic pixels: the scan-to-reference
        misregistration, cell by cell. NaN for the reference scan and for a scan that
        overlaps it nowhere.
    relative_rigid_px : list of float
        The rotation-and-shift part of that difference (:func:`rigid_residual_px`), the
        quantity :func:`clearfast_gis.mosaic.temporal_residual` estimates from the images.
    """

    scans: list[int]
    reference_scan: int
    pixel_size_m: float
    abs_rms_m: list[float]
    relative_px: list[float]
    relative_rigid_px: list[float]


def read_true_poses(folder: str | Path) -> dict[tuple[int, int, int], object]:
    """True camera poses of a simulated survey's ``truth/poses.csv``.

    Returns
    -------
    dict (scan, position, band) -> CameraPose
        Camera centre in the survey CRS (metres), pan/tilt angles and platform attitude in
        degrees.
    """
    from clearfast_gis.geometry.pose import CameraPose

    out = {}
    with open(Path(folder) / "truth" / "poses.csv", newline="") as fh:
        for r in csv.DictReader(fh):
            out[(int(r["scan"]), int(r["position"]), int(r["band"]))] = CameraPose(
                np.array([float(r["e_m"]), float(r["n_m"]), float(r["z_m"])]),
                float(r["azimuth_deg"]), float(r["elevation_deg"]),
                (float(r["roll_deg"]), float(r["pitch_deg"]), float(r["yaw_deg"])))
    return out


def rigid_residual_px(points_m: np.ndarray, displacement_m: np.ndarray,
                      pixel_size_m: float) -> float:
    """RMS displacement (pixels) of the rotation and shift that best explains a field.

    Parameters
    ----------
    points_m : float (N, 2)
        Ground positions, metres.
    displacement_m : float (N, 2)
        Displacement at those positions, metres.
    pixel_size_m : float

    Returns
    -------
    float
        RMS over the N points of the fitted (small-angle) rigid motion's displacement, pixels;
        NaN for fewer than 3 points.
    """
    x = np.asarray(points_m, dtype=float)
    d = np.asarray(displacement_m, dtype=float)
    if len(x) < 3:
        return math.nan
    xc = x - x.mean(axis=0)
    a = np.zeros((2 * len(x), 3))
    a[0::2, 0] = 1.0
    a[1::2, 1] = 1.0
    a[0::2, 2] = -xc[:, 1]
    a[1::2, 2] = xc[:, 0]
    p = np.linalg.lstsq(a, d.ravel(), rcond=None)[0]
    fit = (a @ p).reshape(-1, 2)
    return float(np.sqrt(np.mean(np.sum(fit * fit, axis=1)))) / pixel_size_m


def content_displacement(camera, cells_xy: np.ndarray, placed, true) -> np.ndarray:
    """Displacement (N, 2), metres, of the content a frame put at ground cells.

    Parameters
    ----------
    camera : EquiangularCamera or PinholeCamera
    cells_xy : float (N, 2)
        Cell centres (metres, survey CRS) that took their value from this frame.
    placed, true : CameraPose
        The pose the frame was projected with, and the pose it was taken from.

    Returns
    -------
    float (N, 2)
        Cell minus the ground point the true pose saw at the frame pixel the cell was
        sampled from (NaN where that pixel sees no ground).
    """
    pts = np.column_stack([cells_xy, np.zeros(len(cells_xy))])
    uv = camera.project(pts, placed)
    seen = camera.ground_points(uv[:, 0], uv[:, 1], true)[:, :2]
    return cells_xy - seen


def placement_errors(survey: str | Path, products: str | Path, step_px: int = 8,
                     reference_scan: int | None = None) -> PlacementScore:
    """Score where the chain put the thermal content of a processed simulated survey against
    its true poses (``truth/poses.csv``), cell by cell (:class:`PlacementScore`).

    Every ``step_px``-th cell of each scan's mosaic (both directions) is traced through its
    source frame (``.clearfast/source_NNN.npy``), placed as the chain placed it: GNSS track,
    pan/tilt, mount calibration and the attitude recorded in the run state (the scan's own fit
    or the survey-wide adjustment it was projected with).

    Parameters
    ----------
    survey, products : path
        The simulated survey and its processed products (mosaics stage at least).
    step_px : int
        Cell sampling step.
    reference_scan : int, optional
        The scan to compute the relative residuals against; default: the reference scan
        recorded in ``products.json``.

    Returns
    -------
    PlacementScore
    """
    import json

    import rasterio

    from clearfast_gis.attitude.placement import placement_attitude
    from clearfast_gis.attitude.survey import REFINED
    from clearfast_gis.export.layout import STATE_DIR, mosaic_rel, source_rel
    from clearfast_gis.mosaic.frames import frame_poses
    from clearfast_gis.pipeline.inputs import open_context
    from clearfast_gis.pipeline.stages import ADJUSTMENT

    products = Path(products)
    manifest = json.loads((products / "products.json").read_text())
    units = json.loads((products / STATE_DIR / "state.json").read_text())["units"]
    models = {level: (np.array(units[u]["node_times_s"], dtype=float),
                      np.array(units[u]["nodes_rpy_deg"], dtype=float))
              for level, u in ((1, ADJUSTMENT), (2, f"{ADJUSTMENT}/{REFINED}"))
              if u in units}
    scans = [int(r["scan"]) for r in manifest["scans"]]
    if reference_scan is None:
        refs = {r.get("reference_scan") for r in manifest["scans"]} - {None}
        if len(refs) != 1:
            raise ValueError(f"{products / 'products.json'}: no single reference scan recorded")
        reference_scan = int(refs.pop())
    ref = int(reference_scan)
    with rasterio.open(products / mosaic_rel(ref)) as ds:
        transform, shape = ds.transform, ds.shape
    pixel = float(transform.a)
    rows, cols = np.mgrid[step_px // 2:shape[0]:step_px, step_px // 2:shape[1]:step_px]
    cells = np.column_stack([transform.c + (cols.ravel() + 0.5) * transform.a,
                             transform.f + (rows.ravel() + 0.5) * transform.e])
    ctx, _, _ = open_context(survey)
    truth = read_true_poses(survey)
    cam, fr = ctx.camera, ctx.survey.frames
    disp = {}
    for s in scans:
        source = np.load(products / source_rel(s))[rows, cols].ravel()
        rec = units[f"mosaics/scan_{s:03d}"]
        frame_rows = ctx.survey.scan_rows(s, 0)
        frame_rows = frame_rows[np.isin(fr.position[frame_rows], np.unique(source))]
        t = fr.time_s[frame_rows]
        att = placement_attitude(rec, models.get(int(rec.get("adjusted") or 0)), t)
        d = np.full((len(cells), 2), np.nan)
        for r, pose, a in zip(frame_rows, frame_poses(ctx, t, fr.pan_deg[frame_rows],
                                                       fr.tilt_deg[frame_rows]), att,
                              strict=True):
            position = int(fr.position[r])
            sel = source == position
            d[sel] = content_displacement(cam, cells[sel], pose.with_attitude(tuple(a)),
                                          truth[(s, position, 0)])
        disp[s] = d
    abs_rms, rel, rigid = [], [], []
    for s in scans:
        d = disp[s][np.all(np.isfinite(disp[s]), axis=1)]
        abs_rms.append(float(np.sqrt(np.mean(np.sum(d * d, axis=1)))) if len(d) else math.nan)
        diff = disp[s] - disp[ref]
        ok = np.all(np.isfinite(diff), axis=1)
        if s == ref or not ok.any():
            rel.append(math.nan)
            rigid.append(math.nan)
            continue
        rel.append(float(np.sqrt(np.mean(np.sum(diff[ok] ** 2, axis=1)))) / pixel)
        rigid.append(rigid_residual_px(cells[ok], diff[ok], pixel))
    return PlacementScore(scans, ref, pixel, abs_rms, rel, rigid)
