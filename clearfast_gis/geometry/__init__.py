"""Camera geometry: camera models, pan/tilt pose, GNSS to UTM, ground projection, planning.

Conventions are those of docs/contracts.md §1 (world = easting, northing, height above the
ground plane; azimuth clockwise from grid north; elevation negative down; OpenCV camera frame;
pixel centres at integers).
"""

from clearfast_gis.geometry.cameras import (
    Camera,
    EquiangularCamera,
    PinholeCamera,
    camera_from_manifest,
    distort_normalized,
    intersect_ground,
    undistort_normalized,
)
from clearfast_gis.geometry.gnss import (
    RTK_FIXED,
    PlatformTrack,
    crs_to_lonlat,
    lonlat_to_crs,
    platform_track,
    utm_epsg_for,
)
from clearfast_gis.geometry.grid import GroundGrid
from clearfast_gis.geometry.planner import (
    MissionPlan,
    build_plan,
    default_platform_xy,
    format_summary,
    plan_mission,
)
from clearfast_gis.geometry.pose import (
    CameraPose,
    angles_from_direction,
    attitude_matrix,
    direction_from_angles,
    pose_from_ptu,
)
from clearfast_gis.geometry.projection import (
    NOT_SEEN,
    frame_footprint,
    frame_footprints,
    ground_maps,
    incidence_angle_map,
    off_axis_angle_map,
    slant_range_map,
)

__all__ = [
    "NOT_SEEN", "RTK_FIXED", "Camera", "CameraPose", "EquiangularCamera", "GroundGrid",
    "MissionPlan", "PinholeCamera", "PlatformTrack", "angles_from_direction",
    "attitude_matrix", "build_plan", "camera_from_manifest", "crs_to_lonlat",
    "default_platform_xy", "direction_from_angles", "distort_normalized", "format_summary",
    "frame_footprint", "frame_footprints", "ground_maps", "incidence_angle_map", "intersect_ground",
    "lonlat_to_crs", "off_axis_angle_map", "plan_mission", "platform_track", "pose_from_ptu",
    "slant_range_map", "undistort_normalized", "utm_epsg_for",
]
