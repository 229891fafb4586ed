"""The report's contrast curves: PNG bytes that do not depend on the batch or the process
that drew them (the products are byte-identical with any number of processes)."""

from __future__ import annotations

import io

import numpy as np
import pytest
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


@pytest.mark.parametrize("shape", ["sine", "ramp", "flat", "spiky", "fills"])
def test_contrast_curve_legend_covers_no_measured_point(shape):
    """The legend sits in headroom above the data, whatever the curve fills (matplotlib's
    "best" corner hid points of a curve that filled the axes)."""
    from clearfast_gis.report.figures import ContrastCurves

    t = 1.7e9 + np.arange(0.0, 86400.0, 1800.0)
    x = (t - t[0]) / 86400.0
    c = {"sine": 2.5 * np.sin(2 * np.pi * x), "ramp": np.linspace(-1.0, 3.0, t.size),
         "flat": np.full(t.size, 0.4), "spiky": np.where(np.arange(t.size) % 2, 3.0, -3.0),
         "fills": 2.5 * np.sin(2 * np.pi * 7.3 * x)}[shape]  # no free corner in the axes
    plotter = ContrastCurves()
    plotter.png(t, c, t, c, "a title")
    ax = plotter.ax
    box = ax.get_legend().get_window_extent()
    pts = ax.transData.transform(np.column_stack([(t - t[0]) / 3600.0, c]))
    inside = ((pts[:, 0] >= box.x0 - 3.5) & (pts[:, 0] <= box.x1 + 3.5)
              & (pts[:, 1] >= box.y0 - 3.5) & (pts[:, 1] <= box.y1 + 3.5))  # marker radius
    assert not inside.any()
    assert ax.get_ylim()[1] > c.max()  # the data's top is still on the axes
