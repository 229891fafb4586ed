"""Ties: measured ground displacements of a frame, and their linearisation in the
platform attitude (metres per degree) for the fits and the survey-wide adjustment."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from clearfast_gis.geometry.pose import CameraPose


@dataclass(frozen=True)
class GroundTie:
    """A measured ground displacement of one frame.

    Attributes
    ----------
    frame : int
        Index into the scan's pose list.
    x, y : float
        Ground point (survey CRS, metres) where the frame's content was placed with the
        current attitude.
    dx, dy : float
        Shift (metres) that moves that content to where it belongs.
    weight : float
        Relative weight (markers are surveyed: heavier than image registrations).
    """

    frame: int
    x: float
    y: float
    dx: float
    dy: float
    weight: float = 1.0


def moved_point(camera, pose: CameraPose, x: float, y: float,
                attitude_rpy_deg) -> np.ndarray:
    """Where the ground content placed at (x, y) with ``pose`` lands with another attitude.

    Parameters
    ----------
    camera : camera model
    pose : CameraPose
        Pose the content was placed with.
    x, y : float
        Ground point, survey CRS metres.
    attitude_rpy_deg : (roll, pitch, yaw), degrees
        The other platform attitude (the camera turns about the antenna: see
        :meth:`CameraPose.with_attitude`).

    Returns
    -------
    float (2,)
        The moved ground point, metres (NaN if the ray misses the ground).
    """
    uv = camera.project(np.array([[x, y, 0.0]]), pose)
    other = pose.with_attitude(attitude_rpy_deg)
    return camera.ground_points(uv[:, 0], uv[:, 1], other)[0, :2]


def displacement_jacobian(camera, pose: CameraPose, x: float, y: float,
                          eps_deg: float = 0.01) -> np.ndarray:
    """Ground displacement of the content at (x, y) per degree of attitude change.

    Parameters
    ----------
    camera : camera model
    pose : CameraPose
        Pose (with its attitude) the content was placed with.
    x, y : float
        Ground point, survey CRS metres.
    eps_deg : float
        Central-difference step, degrees.

    Returns
    -------
    float (2, 3)
        d(x, y) / d(roll, pitch, yaw), metres per degree.
    """
    base = np.asarray(pose.attitude_rpy_deg, dtype=float)
    jac = np.empty((2, 3))
    for j in range(3):
        step = np.zeros(3)
        step[j] = eps_deg
        jac[:, j] = (moved_point(camera, pose, x, y, base + step)
                     - moved_point(camera, pose, x, y, base - step)) / (2.0 * eps_deg)
    return jac


@dataclass(frozen=True)
class LinearTie:
    """A measured displacement, linearised for the joint adjustment.

    The displacement predicted by the attitudes ``a(t)`` is
    ``jac @ (a(time_s) - base) - ref_jac @ (a(ref_time_s) - ref_base)``; the second term is
    absent for a marker (``ref_scan`` None).

    Attributes
    ----------
    scan : int
    time_s : float
        Time of the frame, UTC epoch seconds.
    base_rpy_deg : float (3,)
        Attitude the frame was placed with, degrees.
    jac : float (2, 3)
        Metres per degree (:func:`displacement_jacobian`).
    d_m : float (2,)
        Measured shift (dx, dy) that moves the frame's content to where it belongs, metres.
    weight : float
        Relative weight (markers heavier than image registrations).
    ref_scan : int or None
        Scan of the reference mosaic the shift was measured against (None for a marker).
    ref_time_s, ref_base_rpy_deg, ref_jac :
        The same for the reference frame that supplied the mosaic at the tie.
    """

    scan: int
    time_s: float
    base_rpy_deg: np.ndarray
    jac: np.ndarray
    d_m: np.ndarray
    weight: float
    ref_scan: int | None = None
    ref_time_s: float = float("nan")
    ref_base_rpy_deg: np.ndarray | None = None
    ref_jac: np.ndarray | None = None

    def as_list(self) -> list:
        """JSON-friendly record (see :meth:`from_list`)."""
        out = [self.scan, self.time_s, *map(float, self.base_rpy_deg),
               *map(float, np.ravel(self.jac)), *map(float, self.d_m), self.weight]
        if self.ref_scan is not None:
            out += [self.ref_scan, self.ref_time_s, *map(float, self.ref_base_rpy_deg),
                    *map(float, np.ravel(self.ref_jac))]
        return out

    @classmethod
    def from_list(cls, v: list) -> LinearTie:
        """Inverse of :meth:`as_list`."""
        base = dict(scan=int(v[0]), time_s=float(v[1]), base_rpy_deg=np.array(v[2:5], float),
                    jac=np.array(v[5:11], float).reshape(2, 3), d_m=np.array(v[11:13], float),
                    weight=float(v[13]))
        if len(v) > 14:
            base.update(ref_scan=int(v[14]), ref_time_s=float(v[15]),
                        ref_base_rpy_deg=np.array(v[16:19], float),
                        ref_jac=np.array(v[19:25], float).reshape(2, 3))
        return cls(**base)
