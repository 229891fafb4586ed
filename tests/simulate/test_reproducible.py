"""Same seed, same bytes; another seed, other data."""

from __future__ import annotations

import hashlib
from dataclasses import replace

from clearfast_gis.simulate import simulate_survey


def _digests(root) -> dict[str, str]:
    return {str(p.relative_to(root)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(root.rglob("*")) if p.is_file()}


def test_same_seed_identical_files(tmp_path, small_config):
    cfg = replace(small_config, n_scans=2)
    a = _digests(simulate_survey(tmp_path / "a", cfg, seed=11).root)
    b = _digests(simulate_survey(tmp_path / "b", cfg, seed=11).root)
    assert len(a) > 15
    assert a == b
    c = _digests(simulate_survey(tmp_path / "c", cfg, seed=12).root)
    assert a.keys() == c.keys()
    for name in ("frames/scan_000_b0.tif", "blackbody/event_001_b1.tif", "gnss.nmea",
                 "weather.dat", "soil.csv", "truth/objects.csv",
                 "truth/apparent_temperature/scan_001.tif"):
        assert a[name] != c[name], name
    # the planner's mission does not depend on the seed
    assert a["mission.json"] == c["mission.json"]
