"""The simulated survey's scan mission, from the project's planner (paper §2.2)."""

from __future__ import annotations

from clearfast_gis.geometry.planner import plan_mission
from clearfast_gis.simulate.config import SimConfig


def plan_for(config: SimConfig, origin_m: tuple[float, float], lift_xy_m: tuple[float, float],
             interval_s: float) -> dict:
    """mission.json content for ``config``: area and lift in the survey CRS.

    Parameters
    ----------
    config : SimConfig
        Area size, lift height, camera, overlap, number of scans, duration.
    origin_m : (float, float)
        Survey-CRS coordinates of the area's south-west corner, metres.
    lift_xy_m : (float, float)
        Survey-CRS position of the lift (below the camera), metres.
    interval_s : float
        Time between scan starts, seconds.
    """
    area = [origin_m[0], origin_m[1], origin_m[0] + config.area_width_m,
            origin_m[1] + config.area_length_m]
    interval_min = interval_s / 60.0
    return plan_mission(config.lift_height_m, config.aperture_deg, list(config.resolution), area,
                        platform_xy=list(lift_xy_m), overlap=config.overlap,
                        scan_minutes=min(25.0, 0.9 * interval_min),
                        hours=config.duration_s / 3600.0, camera_model=config.camera_model,
                        interval_minutes=interval_min)
