"""Speed of ground-projection maps and of the planner; prints markdown tables.

Run: .venv/bin/python benchmarks/geometry_maps.py
"""

from __future__ import annotations

import time

import numpy as np
from _timing import median_ms

from clearfast_gis.geometry import (
    CameraPose,
    EquiangularCamera,
    GroundGrid,
    PinholeCamera,
    build_plan,
    ground_maps,
)


def _numpy_maps(camera, pose, grid):
    x, y = grid.cell_centres()
    uv = camera.project(np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)]), pose)
    seen = camera.in_frame(uv)
    uv[~seen] = -1.0
    return uv[:, 0].reshape(grid.shape).astype(np.float32)


def main() -> None:
    grid = GroundGrid.from_bounds(-15.0, 0.0, 15.0, 30.0, 0.03)  # 1000 x 1000
    pose = CameraPose([0.0, -3.0, 13.5], 10.0, -40.0, (0.3, -0.2, 0.5))
    cams = {"equiangular 640x512": EquiangularCamera(640, 512, 16.0),
            "pinhole 640x512 (distortion)": PinholeCamera(
                640, 512, 2300.0, 2300.0, 320.0, 256.0, (-0.2, 0.05, 0.001, -0.001, 0.0))}
    print(f"ground_maps on a {grid.width}x{grid.height} grid (median of 15, ms)\n")
    print("| camera | seen cells | numba kernel (window) | numpy project() |")
    print("|---|---|---|---|")
    for name, cam in cams.items():
        mx, _ = ground_maps(cam, pose, grid)
        fast = median_ms(lambda c=cam: ground_maps(c, pose, grid))
        slow = median_ms(lambda c=cam: _numpy_maps(c, pose, grid), repeat=3)
        print(f"| {name} | {100 * np.mean(mx >= 0):.1f} % | {fast:.1f} | {slow:.0f} |")
    print("\nplanner, 30 m x 20 m, platform 3 m off the long side, 13.5 m high, 30 % overlap\n")
    print("| camera | aperture deg | images/scan | rows | across m | along m | plan s |")
    print("|---|---|---|---|---|---|---|")
    for res, ap in [((320, 240), 24.0), ((320, 240), 12.0), ((320, 240), 8.0),
                    ((640, 512), 16.0), ((640, 512), 8.0)]:
        t0 = time.perf_counter()
        plan = build_plan(13.5, ap, res, (0, 0, 30, 20))
        dt = time.perf_counter() - t0
        g = plan.mission["ground_resolution_m"]
        print(f"| {res[0]}x{res[1]} | {ap:g} | {plan.mission['images_per_scan']} | "
              f"{len(plan.rows)} | {g['across_min']:.4f}-{g['across_max']:.4f} | "
              f"{g['along_min']:.4f}-{g['along_max']:.4f} | {dt:.2f} |")


if __name__ == "__main__":
    main()
