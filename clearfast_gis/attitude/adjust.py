"""Joint adjustment of the platform attitude over the whole survey.

Each scan's attitude fitted on its own (:mod:`clearfast_gis.attitude.fit`) is only as good
as the evidence seen during that scan: at night the heated markers do not show, the cold
markers may leave the view of a sinking lift, and the ties measured against the reference
scan inherit that scan's own error. The lift, however, moves smoothly. This module fits the
attitude of all scans at once:

- the attitude is a smooth function of time, piecewise linear between one node per scan
  (at the scan's mean time), so it also changes *during* a scan;
- a marker tie says where one frame's content must move (absolute ground control);
- an image tie says how far one frame's content must move relative to the content of a
  reference mosaic at the same place, whose own placement is also being adjusted;
- a penalty on the angular acceleration keeps the attitude smooth over time, and a weak prior
  keeps scans without evidence at their own fit.

Every tie is linearised once around the attitude its frames were placed with (the ground
displacement is practically linear over the few tenths of a degree involved), so the
adjustment is one small weighted linear least-squares problem, re-weighted (Huber) a few
times.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from clearfast_gis.attitude.ties import LinearTie


def interpolation_weights(time_s: np.ndarray, node_times_s: np.ndarray
                          ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Piecewise-linear interpolation between nodes (linear extrapolation past the ends).

    Parameters
    ----------
    time_s : float (N,)
    node_times_s : float (S,), strictly increasing

    Returns
    -------
    i0, i1 : int (N,)
        Nodes on either side.
    w1 : float (N,)
        Weight of node ``i1`` (``1 - w1`` for ``i0``); outside [0, 1] when extrapolating.
    """
    t = np.atleast_1d(np.asarray(time_s, dtype=float))
    nodes = np.asarray(node_times_s, dtype=float)
    if nodes.size == 1:
        z = np.zeros(t.size, dtype=np.int64)
        return z, z, np.zeros(t.size)
    i1 = np.clip(np.searchsorted(nodes, t), 1, nodes.size - 1)
    i0 = i1 - 1
    w1 = (t - nodes[i0]) / (nodes[i1] - nodes[i0])
    return i0, i1, w1


def attitude_at(time_s: np.ndarray, node_times_s: np.ndarray, nodes_rpy_deg: np.ndarray
                ) -> np.ndarray:
    """Platform attitude (N, 3), degrees, at ``time_s`` (N,) from the adjusted nodes (S, 3):
    linear between the nodes, extrapolated linearly past the ends.

    Examples
    --------
    >>> import numpy as np
    >>> attitude_at(np.array([150.0]), np.array([100.0, 200.0]),
    ...             np.array([[0.0, 0.2, 0.0], [0.0, 0.4, 1.0]]))
    array([[0. , 0.3, 0.5]])
    """
    i0, i1, w1 = interpolation_weights(time_s, node_times_s)
    nodes = np.asarray(nodes_rpy_deg, dtype=float)
    return nodes[i0] * (1.0 - w1)[:, None] + nodes[i1] * w1[:, None]


@dataclass(frozen=True)
class Adjustment:
    """Result of :func:`adjust_attitudes`.

    Attributes
    ----------
    node_times_s : float (S,)
    nodes_rpy_deg : float (S, 3)
        Adjusted attitude at each scan's mean time, degrees.
    rms_m : float
        Weighted RMS of the tie residuals after adjustment, metres.
    rms_before_m : float
        The same for the scans' own attitudes, metres.
    n_ties, n_used : int
        Ties, and those that kept more than half their weight (inliers: residual below
        ``huber_m``).
    """

    node_times_s: np.ndarray
    nodes_rpy_deg: np.ndarray
    rms_m: float
    rms_before_m: float
    n_ties: int
    n_used: int


def _design(ties: list[LinearTie], scans: list[int], node_times: np.ndarray
            ) -> tuple[np.ndarray, np.ndarray]:
    """Rows (2K, 3S) and right-hand side (2K,) of the tie equations."""
    col = {s: k for k, s in enumerate(scans)}
    a = np.zeros((2 * len(ties), 3 * len(scans)))
    b = np.zeros(2 * len(ties))

    def add(row: slice, jac: np.ndarray, t: float, sign: float) -> None:
        i0, i1, w1 = interpolation_weights(np.array([t]), node_times)
        for node, w in ((int(i0[0]), 1.0 - float(w1[0])), (int(i1[0]), float(w1[0]))):
            a[row, 3 * node:3 * node + 3] += sign * w * jac

    for k, tie in enumerate(ties):
        row = slice(2 * k, 2 * k + 2)
        if tie.scan not in col:
            continue
        add(row, tie.jac, tie.time_s, 1.0)
        rhs = tie.d_m + tie.jac @ tie.base_rpy_deg
        if tie.ref_scan is not None:
            add(row, tie.ref_jac, tie.ref_time_s, -1.0)
            rhs = rhs - tie.ref_jac @ tie.ref_base_rpy_deg
        b[row] = rhs
    return a, b


def adjust_attitudes(ties: list[LinearTie], scans: list[int], node_times_s: np.ndarray,
                     prior_rpy_deg: np.ndarray, sigma_tie_m: float = 0.02,
                     smooth_deg_h2: float = 0.03, prior_deg: float = 1.0,
                     huber_m: float = 0.03, n_iter: int = 8) -> Adjustment:
    """Attitude of every scan from all the ties of the survey at once.

    Parameters
    ----------
    ties : list of LinearTie
    scans : list of int
        Scan numbers, in time order (one node each).
    node_times_s : float (S,)
        Mean time of each scan, UTC epoch seconds, increasing.
    prior_rpy_deg : float (S, 3)
        Each scan's own fitted attitude (the weak prior), degrees.
    sigma_tie_m : float
        Standard error of a unit-weight tie, metres.
    smooth_deg_h2 : float
        Standard deviation of the platform's angular acceleration, degrees per hour squared:
        how fast the rate of a slow drift may change (the trial's sinking lift changes its
        roll rate by about 0.04 deg/h per hour at the start). Scans hours apart are thus
        barely tied together, scans half an hour apart strongly. On the simulated trial with
        the drifting lift, 0.02-0.05 place every frame within 1.0-1.1 cm RMS; 0.01 is too
        stiff (1.3 cm) and 0.005 much too stiff (1.4-2.7 cm).
    prior_deg : float
        Standard deviation of the prior, degrees.
    huber_m : float
        Tie residual scale, metres: Huber re-weighting beyond it for two iterations, then
        Cauchy weights ``1 / (1 + (r / huber_m)^2)`` so that gross outliers (a registration
        locked on the wrong texture) stop pulling.
    n_iter : int
        Re-weighting iterations (at most).

    Returns
    -------
    Adjustment
    """
    node_times = np.asarray(node_times_s, dtype=float)
    prior = np.asarray(prior_rpy_deg, dtype=float).reshape(len(scans), 3)
    a_tie, b_tie = _design(ties, scans, node_times)
    w0 = np.array([t.weight for t in ties], dtype=float)
    n = 3 * len(scans)
    rows, rhs = [np.eye(n) / prior_deg], [prior.ravel() / prior_deg]
    if len(scans) >= 3:
        dt_h = np.diff(node_times) / 3600.0
        sm = np.zeros((3 * (len(scans) - 2), n))
        for s in range(1, len(scans) - 1):
            # change of the angular rate (deg/h) across node s, over its expected size
            scale = 1.0 / (smooth_deg_h2 * 0.5 * (dt_h[s] + dt_h[s - 1]))
            for c in range(3):
                r = 3 * (s - 1) + c
                sm[r, 3 * (s + 1) + c] += scale / dt_h[s]
                sm[r, 3 * s + c] -= scale / dt_h[s] + scale / dt_h[s - 1]
                sm[r, 3 * (s - 1) + c] += scale / dt_h[s - 1]
        rows.append(sm)
        rhs.append(np.zeros(sm.shape[0]))
    prior_rows, prior_rhs = np.vstack(rows), np.concatenate(rhs)

    def residual_norms(x: np.ndarray) -> np.ndarray:
        r = (a_tie @ x - b_tie).reshape(-1, 2)
        return np.hypot(r[:, 0], r[:, 1])

    def weighted_rms(x: np.ndarray, w: np.ndarray) -> float:
        if not len(ties) or w.sum() <= 0:
            return float("nan")
        return float(np.sqrt(np.sum(w * residual_norms(x) ** 2) / np.sum(w)))

    def robust_weights(x: np.ndarray, k: int) -> np.ndarray:
        # Huber while the fit settles, then Cauchy: a gross outlier loses its pull entirely
        r = residual_norms(x)
        if k < 2:
            return w0 * np.minimum(1.0, huber_m / np.maximum(r, 1e-12))
        return w0 / (1.0 + (r / huber_m) ** 2)

    x = prior.ravel().copy()
    w = w0.copy()
    for k in range(n_iter if len(ties) else 1):
        if len(ties):
            w = robust_weights(x, k)
        sw = np.sqrt(np.repeat(w, 2)) / sigma_tie_m
        lhs = np.vstack([a_tie * sw[:, None], prior_rows])
        x_new = np.linalg.lstsq(lhs, np.concatenate([b_tie * sw, prior_rhs]), rcond=None)[0]
        converged = np.max(np.abs(x_new - x)) < 1e-5
        x = x_new
        if converged and k >= 2:
            break
    if len(ties):
        w = robust_weights(x, n_iter)
    return Adjustment(node_times, x.reshape(-1, 3), weighted_rms(x, w),
                      weighted_rms(prior.ravel(), w0), len(ties),
                      int(np.sum(w > 0.5 * w0)) if len(ties) else 0)
