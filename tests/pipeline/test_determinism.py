"""Deterministic products: the demo survey processed twice, with another thread count, gives
byte-identical products (timings aside).

The first run is the cached ``demo_products`` (default threads); the second runs here with one
thread (two when the default is one). Mosaics, source maps, the GeoPackage, the figures and the
report must be the same bytes; ``products.json`` and ``report.html`` differ only in their
timings. Run-to-run differences of the last bits of a float (a kernel whose rounding depends on
a buffer's memory alignment, or on the order in which threads finish) once moved scan
attitudes by thousandths of a degree and changed the number of suspects.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from clearfast_gis.parallel import n_threads
from clearfast_gis.pipeline.run import process_survey
from tests.product_digests import comparable_digests


@pytest.mark.slow
def test_demo_twice_with_other_threads_gives_identical_products(demo_survey, demo_products,
                                                                 tmp_path, monkeypatch):
    threads = 1 if n_threads() > 1 else 2
    monkeypatch.setenv("CLEARFAST_THREADS", str(threads))
    again = tmp_path / "again"
    process_survey(demo_survey, again, resume=False)

    first = json.loads((demo_products / "products.json").read_text())
    second = json.loads((again / "products.json").read_text())
    # the scan attitudes first: a difference there explains every later one
    assert [s.get("attitude") for s in second["scans"]] == \
        [s.get("attitude") for s in first["scans"]]
    assert second["attitude_adjustment"] == first["attitude_adjustment"]
    for name in sorted((demo_products / ".clearfast").glob("source_*.npy")):
        np.testing.assert_array_equal(np.load(again / ".clearfast" / name.name), np.load(name))
    assert comparable_digests(again) == comparable_digests(demo_products)
