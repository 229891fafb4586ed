"""The trial's fault: the sinking, tilting lift shifts the view by more than half a frame."""

from __future__ import annotations

import numpy as np

from clearfast_gis.evaluation.truth import read_true_poses
from clearfast_gis.geometry import camera_from_manifest
from clearfast_gis.simulate.config import preset
from clearfast_gis.simulate.platform import lift_motion
from clearfast_gis.survey import read_survey


def test_drift_shifts_view_more_than_half_a_frame(drift_survey):
    sv = read_survey(drift_survey.root)
    cam = camera_from_manifest(sv.manifest["camera"])
    poses = read_true_poses(drift_survey.root)
    last = drift_survey.n_scans - 1
    centre = np.array([[(cam.width - 1) / 2.0, (cam.height - 1) / 2.0]])
    shifts = []
    for p in range(drift_survey.n_positions):
        first, end = poses[(0, p, 0)], poses[(last, p, 0)]
        ground = cam.ground_points(centre[:, 0], centre[:, 1], first)
        shifts.append(cam.project(ground, end)[0] - centre[0])
    shifts = np.array(shifts)
    assert np.all(np.abs(shifts[:, 1]) > cam.height / 2)
    assert poses[(0, 0, 0)].position_m[2] - poses[(last, 0, 0)].position_m[2] > 1.5
    # the survey's own pan/tilt readouts are the nominal ones: only truth knows the drift
    frames = sv.frames
    sel = (frames.scan == last) & (frames.position == 0) & (frames.band == 0)
    assert np.isclose(frames.tilt_deg[sel][0], poses[(last, 0, 0)].elevation_deg, atol=1e-5)


def test_trial_drift_exceeds_half_frame():
    """The trial preset's drift (13 m lift, 320x256) also exceeds half a frame in 24 h."""
    from clearfast_gis.geometry.cameras import EquiangularCamera
    from clearfast_gis.geometry.pose import pose_from_ptu

    cfg = preset("trial")
    cam = EquiangularCamera(*cfg.resolution, cfg.aperture_deg)
    motion = lift_motion(cfg, np.array([0.0, 0.0, cfg.lift_height_m + 0.4]), 0.0, True,
                         np.random.default_rng(0))
    platform = {"antenna_to_camera_m": list(cfg.antenna_to_camera_m)}
    for tilt in (-25.0, -40.0, -60.0):
        a = pose_from_ptu(motion.antenna_m(0.0)[0], 10.0, tilt, platform,
                          motion.attitude_rpy_deg(0.0)[0])
        b = pose_from_ptu(motion.antenna_m(cfg.duration_s)[0], 10.0, tilt, platform,
                          motion.attitude_rpy_deg(cfg.duration_s)[0])
        g = cam.ground_points(np.array([159.5]), np.array([127.5]), a)
        uv = cam.project(g, b)[0]
        assert abs(uv[1] - 127.5) > 128


def test_no_drift_keeps_the_pose(demo_survey):
    poses = read_true_poses(demo_survey.root)
    z = np.array([p.position_m[2] for p in poses.values()])
    att = np.array([p.attitude_rpy_deg for p in poses.values()])
    assert np.ptp(z) < 0.01  # millimetre sway only
    assert np.all(att == 0.0)
