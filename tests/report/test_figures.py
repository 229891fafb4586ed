"""The report's contrast curves: PNG bytes that do not depend on the batch or the process
that drew them (the products are byte-identical with any number of processes)."""

from __future__ import annotations

import io

import numpy as np
from PIL import Image

from clearfast_gis.parallel import ProcessChunks
from clearfast_gis.report.figures import CurveInput, contrast_curves_png


def _curves(n: int) -> list[CurveInput]:
    rng = np.random.default_rng(4)
    t = 1.79e9 + 1800.0 * np.arange(48)
    out = []
    for i in range(n):
        c = rng.normal(0.0, 10.0 ** rng.uniform(-2, 1), 48)
        model = None if i % 3 == 0 else 0.9 * c
        out.append(CurveInput(t, c, None if model is None else t, model,
                              f"CF-{i:03d}  mine  status confident"))
    return out


def test_each_curve_is_the_same_bytes_alone_in_a_batch_and_in_worker_processes():
    curves = _curves(9)
    batch = contrast_curves_png(curves)
    alone = [contrast_curves_png([c])[0] for c in curves]
    assert batch == alone
    with ProcessChunks(contrast_curves_png, curves, processes=2) as drawing:
        assert drawing.result() == batch
    img = Image.open(io.BytesIO(batch[0]))
    assert img.format == "PNG" and img.size == (572, 330)
    assert len(set(batch)) == len(batch)  # each curve drew its own data and title
