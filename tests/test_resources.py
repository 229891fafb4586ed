"""Per-stage resource meter."""

from __future__ import annotations

import numpy as np

from clearfast_gis.resources import StageMeter, cpu_seconds


def test_stage_meter_measures_time_cpu_and_its_own_peak():
    meter = StageMeter()
    with meter.stage("big"):
        a = np.ones(40_000_000)  # 305 MiB touched
        a.sum()
        del a
    with meter.stage("small"):
        c0 = cpu_seconds()
        while cpu_seconds() - c0 < 0.05:  # 50 ms of CPU, however busy the machine
            pass
    big, small = meter.stages["big"], meter.stages["small"]
    assert big["peak_rss_mb"] > small["peak_rss_mb"] + 250 or not meter.peak_is_stage
    assert small["cpu_s"] >= 0.05 and small["wall_s"] >= 0.9 * small["cpu_s"]
    with meter.stage("small"):  # accumulates
        pass
    assert meter.stages["small"]["wall_s"] >= small["wall_s"]
    s = meter.summary(1.0, 0.5)
    assert s["total"]["peak_rss_mb"] == round(big["peak_rss_mb"], 1)
    assert set(s["stages"]) == {"big", "small"}
