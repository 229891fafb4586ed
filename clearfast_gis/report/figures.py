"""Report figures (matplotlib, Agg backend): mosaics with detections, contrast curves."""

from __future__ import annotations

import io
import warnings
from collections.abc import Sequence
from dataclasses import dataclass

import matplotlib
import numpy as np
from affine import Affine

from clearfast_gis.timeutil import format_utc

matplotlib.use("Agg")


def _pyplot():
    """matplotlib.pyplot, imported on first use.

    A venv that also sees Debian's packages (the QGIS set-up) finds Debian's mpl_toolkits
    beside its own matplotlib, which makes pyplot warn that the (unused) 3-D projection is
    unavailable; the warning is silenced here.
    """
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Unable to import Axes3D")
        import matplotlib.pyplot as plt
    return plt


def _png(fig) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    _pyplot().close(fig)
    return buf.getvalue()


def _extent(transform: Affine, shape: tuple[int, int]) -> tuple[float, float, float, float]:
    h, w = shape
    x0, y0 = transform.c, transform.f
    return (x0, x0 + w * transform.a, y0 + h * transform.e, y0)


def mosaic_panel_png(mosaics: Sequence[np.ndarray], times_s: Sequence[float],
                     transform: Affine, outlines: Sequence[np.ndarray],
                     labels: Sequence[str], colours: Sequence[str], epsg: int) -> bytes:
    """The paper's Fig. 7/8 layout: two mosaics (day, night) and the detections between them.

    Parameters
    ----------
    mosaics : sequence of float32 (H, W)
        Two mosaics, degrees C (NaN = no data).
    times_s : sequence of float
        Their scan times (UTC epoch seconds).
    transform : Affine
        Mosaic grid transform (survey CRS).
    outlines : sequence of (K, 2) arrays
        Anomaly outlines in map coordinates.
    labels, colours : sequences of str
        Label and colour per outline.
    epsg : int
        Survey CRS, for the axis labels.
    """
    fig, axes = _pyplot().subplots(1, 3, figsize=(15, 5.2), sharex=True, sharey=True)
    ext = _extent(transform, mosaics[0].shape)
    for ax, m, t in ((axes[0], mosaics[0], times_s[0]), (axes[2], mosaics[1], times_s[1])):
        finite = m[np.isfinite(m)]
        lo, hi = (np.percentile(finite, [1, 99]) if finite.size else (0.0, 1.0))
        im = ax.imshow(m, extent=ext, cmap="inferno", vmin=lo, vmax=hi, interpolation="nearest")
        ax.set_title(f"Mosaic {format_utc(t, 'minutes')}")
        fig.colorbar(im, ax=ax, shrink=0.8, label="apparent temperature (°C)")
    base = mosaics[0]
    axes[1].imshow(np.isfinite(base), extent=ext, cmap="Greys", vmin=0, vmax=3,
                   interpolation="nearest")
    for xy, lab, col in zip(outlines, labels, colours, strict=True):
        for ax in axes:
            ax.plot(xy[:, 0], xy[:, 1], color=col, lw=1.2)
        axes[1].text(xy[:, 0].mean(), xy[:, 1].max(), lab, color=col, fontsize=8,
                     ha="center", va="bottom")
    axes[1].set_title("Detected anomalies")
    for ax in axes:
        ax.set_xlabel(f"easting (m, EPSG:{epsg})")
        ax.ticklabel_format(useOffset=False, style="plain")
        ax.tick_params(labelsize=7)
    axes[0].set_ylabel(f"northing (m, EPSG:{epsg})")
    return _png(fig)


LEGEND_HEADROOM = 0.22
"""Headroom added above a contrast curve's data for its legend, a fraction of the data's
vertical range (the one-row legend takes about 8 % of the axes' height)."""


class ContrastCurves:
    """Renders anomalies' contrast curves on one reused figure (the axes, labels and fonts
    are laid out once; each curve only updates the data and the title: about three times
    faster than a new figure per anomaly)."""

    def __init__(self) -> None:
        from matplotlib.figure import Figure

        self.fig = Figure(figsize=(5.2, 3.0))
        ax = self.ax = self.fig.add_subplot()
        (self.measured,) = ax.plot([], [], "o", ms=3.5, color="#c0392b", label="measured")
        (self.model,) = ax.plot([], [], "-", color="#2c3e50", lw=1.2, label="thermal model")
        ax.axhline(0.0, color="grey", lw=0.6)
        ax.set_ylabel("contrast (K)")
        self.title = ax.set_title("", fontsize=9, y=1.0, pad=6.0)  # fixed: no re-layout per curve
        self.fig.subplots_adjust(left=0.14, right=0.97, bottom=0.16, top=0.89)

    def png(self, times_s: np.ndarray, contrast_k: np.ndarray,
            model_times_s: np.ndarray | None, model_k: np.ndarray | None, title: str) -> bytes:
        """One anomaly's centre-minus-background contrast over the scans (K, one value per
        scan time, UTC epoch seconds), with the model fit when given; PNG bytes."""
        ax = self.ax
        t0 = float(times_s[0])
        self.measured.set_data((np.asarray(times_s) - t0) / 3600.0, contrast_k)
        has_model = model_times_s is not None and model_k is not None
        self.model.set_visible(has_model)
        self.model.set_data(((np.asarray(model_times_s) - t0) / 3600.0, model_k)
                            if has_model else ([], []))
        ax.set_xlabel(f"hours after {format_utc(t0, 'minutes')}")
        self.title.set_text(title)
        legend = ax.get_legend()
        if legend is not None:
            legend.remove()
        ax.relim(visible_only=True)
        ax.set_autoscaley_on(True)  # the last curve's headroom fixed the limits
        ax.autoscale_view()
        # the legend sits in a band of headroom above the data: where matplotlib's "best"
        # corner was used, measured points and the model line that filled the axes were
        # hidden under it
        lo, hi = ax.get_ylim()
        ax.set_ylim(lo, hi + LEGEND_HEADROOM * (hi - lo))
        ax.legend(handles=[self.measured, self.model] if has_model else [self.measured],
                  fontsize=7, loc="upper right", ncol=2, borderaxespad=0.3)
        buf = io.BytesIO()
        self.fig.savefig(buf, format="png", dpi=110)
        return buf.getvalue()


@dataclass(frozen=True)
class CurveInput:
    """One anomaly's curve for :func:`contrast_curves_png` (the arguments of
    :meth:`ContrastCurves.png`)."""

    times_s: np.ndarray
    contrast_k: np.ndarray
    model_times_s: np.ndarray | None
    model_k: np.ndarray | None
    title: str


def contrast_curves_png(curves: list[CurveInput]) -> list[bytes]:
    """Many anomalies' contrast curves, PNG bytes each, on one reused figure (each image is
    the same, byte for byte, whatever curves were drawn before it: tested)."""
    plotter = ContrastCurves()
    return [plotter.png(c.times_s, c.contrast_k, c.model_times_s, c.model_k, c.title)
            for c in curves]


def contrast_curve_png(times_s: np.ndarray, contrast_k: np.ndarray,
                       model_times_s: np.ndarray | None, model_k: np.ndarray | None,
                       title: str) -> bytes:
    """One anomaly's centre-minus-background contrast over the scans, with the model fit
    (see :class:`ContrastCurves` for many)."""
    return ContrastCurves().png(times_s, contrast_k, model_times_s, model_k, title)


def operating_curve_png(curve: dict) -> bytes:
    """The planner's expected operating curve (``evaluation.operating.expected_operating_curve``):
    expected mines found against expected false alarms per m2 going down the ranked list, with
    the priority of every fifth suspect marked; PNG bytes."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(5.2, 3.4))
    ax = fig.add_subplot()
    fa = np.concatenate([[0.0], np.asarray(curve["expected_false_alarms_per_m2"], float)])
    found = np.concatenate([[0.0], np.asarray(curve["expected_mines"], float)])
    ax.step(fa, found, where="post", color="#c0392b", lw=1.4)
    for k in range(4, len(fa) - 1, 5):
        ax.annotate(str(k + 1), (fa[k + 1], found[k + 1]), fontsize=6, color="#555",
                    xytext=(2, -8), textcoords="offset points")
    ax.axvline(0.01, color="grey", lw=0.6, ls="--")
    ax.text(0.01, 0.02, " 0.01 per m²", transform=ax.get_xaxis_transform(), fontsize=7,
            color="grey")
    ax.set_xlabel("expected false alarms per m² (cumulative)")
    ax.set_ylabel("expected mines found")
    ax.set_title("going down the list by p_mine (numbers: priority)", fontsize=9)
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    fig.subplots_adjust(left=0.14, right=0.97, bottom=0.16, top=0.9)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110)
    return buf.getvalue()
