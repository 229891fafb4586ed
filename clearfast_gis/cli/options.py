"""Options shared by several subcommands (defined once, as rasterio's ``rio`` does)."""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator

import click

from clearfast_gis.pipeline.options import ProcessOptions
from clearfast_gis.progress import Progress

progress_opt = click.option(
    "--progress",
    "progress_mode",
    type=click.Choice(["bar", "json", "none"]),
    default="bar",
    show_default=True,
    help="Progress display: a bar for people, JSON lines on stdout for programs.",
)

resume_opt = click.option(
    "--resume/--no-resume",
    default=True,
    show_default=True,
    help="Skip stages whose products are already complete and up to date.",
)

seed_opt = click.option("--seed", type=int, default=0, show_default=True,
                        help="Random seed (identical seeds give identical files).")

overwrite_opt = click.option("--overwrite", is_flag=True, help="Replace existing outputs.")

survey_arg = click.argument(
    "survey", type=click.Path(exists=True, file_okay=False, dir_okay=True, readable=True)
)

station_profile_opt = click.option(
    "--station-profile", "station_profile", default=None,
    type=click.Path(exists=True, file_okay=True, dir_okay=False, readable=True),
    help="Station profile (JSON) mapping the weather/soil logger's columns and units "
         "(default: the file survey.json names in files.station_profile; docs/acquire.md).",
)

products_opt = click.option(
    "-o", "--output", "products", required=True,
    type=click.Path(file_okay=False, dir_okay=True, writable=True),
    help="Products folder (created if missing).",
)


def make_progress(mode: str) -> Progress:
    """The progress reporter for ``--progress MODE``."""
    return Progress(mode)


DEFAULTS = ProcessOptions()
"""The defaults of ``process``, ``detect``, ``batch`` and the QGIS plugin (one source:
:class:`~clearfast_gis.pipeline.options.ProcessOptions`; ``clearfast options --json``)."""


def _fraction(value: float | None) -> str:
    return {0.25: "a quarter", 0.5: "half"}.get(value, f"{value:g}")


def mosaic_options(f):
    """Mosaicking options of ``process`` (pixel size, co-registration, seam balancing)."""
    f = click.option("--pixel-size", "pixel_size_m", type=click.FloatRange(min=0.001),
                     default=DEFAULTS.pixel_size_m, help="Mosaic cell size in metres (default: "
                     "from the mission's ground resolution).")(f)
    f = click.option("--no-coregister", "no_coregister", is_flag=True,
                     help="Keep the geometric placement of every frame (no MI correction).")(f)
    f = click.option("--seam-balance", is_flag=True,
                     help="Apply the paper's histogram seam balancing (changes temperatures; "
                     "recorded in the products).")(f)
    f = click.option("--reference-scan", type=click.IntRange(min=0),
                     default=DEFAULTS.reference_scan,
                     help="Scan the others are co-registered to (default: the scan nearest "
                     "local solar noon).")(f)
    f = click.option("--no-atmosphere", is_flag=True,
                     help="Skip the atmospheric correction.")(f)
    f = click.option("--kernels", type=click.Choice(["fast", "reference"]),
                     default=DEFAULTS.kernels, show_default=True,
                     help="Run the chain on our kernels or on the reference libraries "
                     "(scikit-image, SimpleITK, scipy, np.interp) for comparison.")(f)
    return f


def detection_options(f):
    """The morphological detector's parameters (paper §4), in metres on mosaics."""
    f = click.option("--d1", "d1_m", type=click.FloatRange(min=0.0, min_open=True),
                     default=DEFAULTS.d1_m, show_default=True,
                     help="Top-hat disk D1, metres (larger than the largest mine).")(f)
    f = click.option("--d2", "d2_m", type=click.FloatRange(min=0.0, min_open=True),
                     default=DEFAULTS.d2_m, show_default=True,
                     help="Opening disk D2 < D1, metres (removes smaller clutter).")(f)
    f = click.option("--epsilon", type=click.FloatRange(0.0, 0.5, min_open=True),
                     default=DEFAULTS.epsilon, show_default=True,
                     help="Histogram stretching percentile fraction.")(f)
    f = click.option("--threshold-snr", type=click.FloatRange(min=0.0, min_open=True),
                     default=DEFAULTS.threshold_snr, show_default=True,
                     help="Cap of the stretch's cut at this many times each image's clutter "
                     "(1-sigma, K).")(f)
    f = click.option("--level", type=click.IntRange(min=1), default=DEFAULTS.level,
                     help="Majority-voting level l, images (default: "
                     f"{_fraction(DEFAULTS.level_fraction)} of the images covering each "
                     "pixel).")(f)
    f = click.option("--gamma", type=click.FloatRange(min=0.0), default=DEFAULTS.gamma,
                     help="Combination threshold on the sum of the reconstructed images "
                     f"(default: {_fraction(DEFAULTS.gamma_fraction)} of the images covering "
                     "each pixel; 1 = binary OR).")(f)
    f = click.option("--max-anomalies", type=click.IntRange(min=1),
                     default=DEFAULTS.max_anomalies, show_default=True,
                     help="Characterise and write at most this many of the detector's "
                     "anomalies (highest scores first); the deep cores of the stack's "
                     "matched filter come on top.")(f)
    return f


def build_options(params: dict, invert: bool = True):
    """ProcessOptions from the click parameters of ``process`` / ``detect``."""
    if params.get("d2_m") is not None and params.get("d1_m") is not None \
            and params["d2_m"] >= params["d1_m"]:
        raise click.UsageError("D2 must be smaller than D1")
    kw = {k: v for k, v in params.items()
          if k in ("pixel_size_m", "seam_balance", "reference_scan", "d1_m", "d2_m", "epsilon",
                   "threshold_snr", "level", "gamma", "max_anomalies", "kernels") and v is not None}
    if params.get("no_coregister"):
        kw["coregister"] = False
    if params.get("no_atmosphere"):
        kw["atmosphere"] = False
    return ProcessOptions(invert=invert, **kw)


@contextlib.contextmanager
def stop_on_signals() -> Iterator[threading.Event]:
    """An event set by Ctrl-C or SIGTERM during the block (the previous handlers come back
    after it): long-running commands stop cleanly at their next check."""
    stop = threading.Event()
    previous = {}

    def request_stop(signum, frame) -> None:
        stop.set()

    for sig in (signal.SIGINT, signal.SIGTERM):
        previous[sig] = signal.signal(sig, request_stop)
    try:
        yield stop
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)


no_invert_opt = click.option(
    "--no-invert", is_flag=True,
    help="Skip the depth/diffusivity estimation and the deep search (both run the thermal "
    "model).")
"""The ``--no-invert`` switch of ``process``, ``detect`` and ``batch``."""
