"""Platform attitude of a scan from ground displacements (the trial's drifting lift).

The RTK-DGPS measures where the lift's basket is, not how it is tilted. A slowly sinking,
tilting lift (paper §6) turns the whole pan/tilt base, so every frame of a scan lands
displaced on the ground, by different amounts at different ranges. Instead of correcting each
frame independently, the displacements measured on a sample of frames (mutual-information
registration against the reference scan) and on the surveyed markers are explained by one
attitude (roll, pitch, yaw) of the base per scan, fitted by robust least squares. Every frame
is then projected with that attitude.
"""

from __future__ import annotations

import numpy as np

from clearfast_gis.attitude.ties import GroundTie, moved_point
from clearfast_gis.geometry.pose import CameraPose


def _predicted(camera, poses: list[CameraPose], ties: list[GroundTie],
               attitude: np.ndarray, base: np.ndarray) -> np.ndarray:
    """Ground displacement (K, 2) that changing ``base`` to ``attitude`` causes at the ties."""
    out = np.empty((len(ties), 2))
    for k, tie in enumerate(ties):
        p0 = poses[tie.frame].with_attitude(base)
        out[k] = moved_point(camera, p0, tie.x, tie.y, attitude) - (tie.x, tie.y)
    return out


def fit_attitude(camera, poses: list[CameraPose], ties: list[GroundTie],
                 base_rpy_deg: tuple[float, float, float] = (0.0, 0.0, 0.0),
                 max_abs_deg: float = 10.0, n_iter: int = 8, huber_m: float = 0.03
                 ) -> tuple[tuple[float, float, float], float, int]:
    """Platform attitude that best explains the measured ground displacements.

    Parameters
    ----------
    camera : camera model
    poses : list of CameraPose
        The scan's frame poses (their attitude is ignored; ``base_rpy_deg`` was used to
        place the frames when the ties were measured).
    ties : list of GroundTie
    base_rpy_deg : (roll, pitch, yaw), degrees
        Attitude the frames were projected with.
    max_abs_deg : float
        Bound on each angle.
    n_iter : int
        Gauss-Newton iterations (with Huber re-weighting).
    huber_m : float
        Residual (metres) beyond which a tie is down-weighted.

    Returns
    -------
    attitude_rpy_deg : tuple of 3 floats
    rms_m : float
        Weighted RMS residual of the ties after the fit, metres.
    n_used : int
        Ties that kept more than half their weight (inliers).
    """
    base = np.asarray(base_rpy_deg, dtype=float)
    if len(ties) < 2:
        return tuple(base), float("nan"), 0
    obs = np.array([(t.dx, t.dy) for t in ties])
    w0 = np.array([t.weight for t in ties])
    a = base.copy()
    eps = 1e-3
    w = w0.copy()
    for _ in range(n_iter):
        pred = _predicted(camera, poses, ties, a, base)
        r = (obs - pred).ravel()
        jac = np.empty((r.size, 3))
        for j in range(3):
            da = a.copy()
            da[j] += eps
            jac[:, j] = ((_predicted(camera, poses, ties, da, base) - pred) / eps).ravel()
        res_norm = np.hypot(*(obs - pred).T)
        w = w0 * np.minimum(1.0, huber_m / np.maximum(res_norm, 1e-12))
        ww = np.repeat(w, 2)
        lhs = jac.T @ (jac * ww[:, None]) + 1e-6 * np.eye(3)
        step = np.linalg.solve(lhs, jac.T @ (ww * r))
        a = np.clip(a + step, -max_abs_deg, max_abs_deg)
        if np.max(np.abs(step)) < 1e-4:
            break
    pred = _predicted(camera, poses, ties, a, base)
    res = np.hypot(*(obs - pred).T)
    rms = float(np.sqrt(np.sum(w * res**2) / np.sum(w)))
    return tuple(float(v) for v in a), rms, int(np.sum(w > 0.5 * w0))
