"""Wall time, CPU time and peak memory of the chain's stages (``products.json`` ``resources``).

Peak memory is the resident-set high-water mark of the process (Linux ``VmHWM``), reset at the
start of each stage through ``/proc/self/clear_refs`` so that each stage reports its own peak;
where that is not possible the lifetime peak (``ru_maxrss``) is reported instead and
``peak_is_stage`` is false.
"""

from __future__ import annotations

import resource
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

_STATUS = Path("/proc/self/status")
_CLEAR_REFS = Path("/proc/self/clear_refs")


def cpu_seconds() -> float:
    """User + system CPU time of this process, all its threads and the worker processes it has
    waited for (:class:`clearfast_gis.parallel.ProcessChunks`), seconds."""
    return sum(ru.ru_utime + ru.ru_stime for ru in (resource.getrusage(resource.RUSAGE_SELF),
                                                    resource.getrusage(resource.RUSAGE_CHILDREN)))


def peak_rss_mb() -> float:
    """Resident-set high-water mark of this process, MiB (since the last reset)."""
    try:
        for line in _STATUS.read_text().splitlines():
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024.0
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def reset_peak() -> bool:
    """Reset the high-water mark (Linux >= 4.0); False when not possible."""
    try:
        _CLEAR_REFS.write_text("5")
        return True
    except OSError:
        return False


@dataclass
class StageMeter:
    """Measures named stages; ``stages`` maps a name to ``{wall_s, cpu_s, peak_rss_mb}``.

    A stage measured twice (e.g. resumed pieces) accumulates times and keeps the larger peak.
    """

    stages: dict[str, dict] = field(default_factory=dict)
    peak_is_stage: bool = True

    @contextmanager
    def stage(self, name: str) -> Iterator[None]:
        """Measure the block as stage ``name``."""
        self.peak_is_stage &= reset_peak()
        w0, c0 = time.perf_counter(), cpu_seconds()
        try:
            yield
        finally:
            rec = self.stages.setdefault(name, {"wall_s": 0.0, "cpu_s": 0.0,
                                                "peak_rss_mb": 0.0})
            rec["wall_s"] += time.perf_counter() - w0
            rec["cpu_s"] += cpu_seconds() - c0
            rec["peak_rss_mb"] = max(rec["peak_rss_mb"], peak_rss_mb())

    def wall(self, name: str) -> float:
        """Wall time of a stage so far, seconds (0 if not measured)."""
        return self.stages.get(name, {}).get("wall_s", 0.0)

    def summary(self, total_wall_s: float, total_cpu_s: float) -> dict:
        """The ``resources`` record: per stage, rounded, and the totals."""
        stages = {k: {"wall_s": round(v["wall_s"], 3), "cpu_s": round(v["cpu_s"], 3),
                      "peak_rss_mb": round(v["peak_rss_mb"], 1)}
                  for k, v in self.stages.items()}
        peak = max((v["peak_rss_mb"] for v in self.stages.values()), default=peak_rss_mb())
        return {"stages": stages, "total": {"wall_s": round(total_wall_s, 3),
                                            "cpu_s": round(total_cpu_s, 3),
                                            "peak_rss_mb": round(peak, 1)},
                "peak_is_stage": self.peak_is_stage}
