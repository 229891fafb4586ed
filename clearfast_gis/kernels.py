"""Which implementation the chain's heavy kernels run: ours or the reference libraries.

``fast`` (the default) runs the project's kernels (numba, OpenCV); ``reference`` runs the
same chain on the mature reference implementations each kernel is checked against. Every
kernel that has both is one entry of :data:`REGISTRY` (``{name: KernelPair(fast,
reference)}``); a public function runs ``kernel(name)(...)``, the active set's implementation,
and holds no branch of its own. Each domain keeps its implementations beside its public
functions, in two private modules: ``clearfast_gis/<domain>/_kernels.py`` (fast) and
``clearfast_gis/<domain>/_reference.py`` (reference), each function named after its entry.
The table in ``docs/performance.md`` is :func:`markdown_table`
(``tests/kernels/test_registry.py`` checks it, and runs both implementations of every entry on
the same input).

The thermal inversion itself is the same in both sets: every anomaly is inverted on one site
table of forward runs (``benchmarks/thermal_inversion.py`` compares it with a model run per
anomaly); the kernel sets differ in how each forward run steps the heat equation.

The choice is process-wide (``clearfast process --kernels``); :func:`use` sets it for a block.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass

KERNELS = ("fast", "reference")
"""The kernel sets."""

_active = "fast"


def active() -> str:
    """The kernel set in use, ``"fast"`` or ``"reference"``."""
    return _active


def reference() -> bool:
    """True when the reference kernels are in use."""
    return _active == "reference"


@contextmanager
def use(name: str) -> Iterator[None]:
    """Run a block with the kernel set ``name`` (restored afterwards).

    Raises
    ------
    ValueError
        ``name`` is not one of :data:`KERNELS`.
    """
    global _active
    if name not in KERNELS:
        raise ValueError(f"unknown kernel set {name!r} (expected one of {', '.join(KERNELS)})")
    before, _active = _active, name
    try:
        yield
    finally:
        _active = before


@dataclass(frozen=True)
class KernelPair:
    """The two implementations of one kernel.

    Attributes
    ----------
    fast, reference : str
        ``module:function`` of each implementation (imported on first use); both take the
        same arguments and return the same kind of result.
    fast_text, reference_text : str
        What each one is, for the documentation table.
    """

    fast: str
    reference: str
    fast_text: str
    reference_text: str

    @property
    def domain(self) -> str:
        """The package that holds both implementations (``"detection"``, ...)."""
        return self.fast.split(":")[0].split(".")[1]

    def implementation(self, kernel_set: str) -> Callable:
        """The implementation of ``kernel_set`` (``"fast"`` or ``"reference"``)."""
        if kernel_set not in KERNELS:
            raise ValueError(f"unknown kernel set {kernel_set!r}")
        module, name = getattr(self, kernel_set).split(":")
        return getattr(importlib.import_module(module), name)


REGISTRY: dict[str, KernelPair] = {
    "top_hat_by_reconstruction": KernelPair(
        "clearfast_gis.detection._kernels:top_hat_by_reconstruction",
        "clearfast_gis.detection._reference:top_hat_by_reconstruction",
        "disk erosion by chords (numba) + hybrid-queue reconstruction (numba)",
        "scikit-image erosion and `reconstruction`"),
    "bottom_hat_by_reconstruction": KernelPair(
        "clearfast_gis.detection._kernels:bottom_hat_by_reconstruction",
        "clearfast_gis.detection._reference:bottom_hat_by_reconstruction",
        "disk dilation by chords (numba) + hybrid-queue reconstruction (numba)",
        "scikit-image dilation and `reconstruction`"),
    "binary_opening_by_reconstruction": KernelPair(
        "clearfast_gis.detection._kernels:binary_opening_by_reconstruction",
        "clearfast_gis.detection._reference:binary_opening_by_reconstruction",
        "OpenCV disk erosion + binary reconstruction (numba)",
        "scikit-image erosion and `reconstruction` (8-connected)"),
    "order_statistics": KernelPair(
        "clearfast_gis.detection._kernels:order_statistics",
        "clearfast_gis.detection._reference:order_statistics",
        "radix selection on the values' bits (numba), no copy",
        "`np.partition`"),
    "box_mean": KernelPair(
        "clearfast_gis.detection._kernels:box_mean",
        "clearfast_gis.detection._reference:box_mean",
        "running sums along each axis (numba), scipy's arithmetic",
        "scipy `uniform_filter` (mode nearest)"),
    "register_conformal": KernelPair(
        "clearfast_gis.registration._kernels:register_conformal",
        "clearfast_gis.registration._reference:register_conformal",
        "Parzen-window Mattes MI with its analytic gradient (numba), bounded L-BFGS",
        "SimpleITK Mattes MI, regular-step gradient"),
    "ground_maps": KernelPair(
        "clearfast_gis.geometry._kernels:ground_maps",
        "clearfast_gis.geometry._reference:ground_maps",
        "cell-centre maps over the seen window (numba)",
        "`Camera.project` of every cell (numpy)"),
    "resample": KernelPair(
        "clearfast_gis.mosaic._kernels:resample",
        "clearfast_gis.mosaic._reference:resample",
        "`cv2.GaussianBlur` + `cv2.remap`",
        "scipy `gaussian_filter` + `map_coordinates`"),
    "inverse_planck": KernelPair(
        "clearfast_gis.radiometry._kernels:inverse_planck",
        "clearfast_gis.radiometry._reference:inverse_planck",
        "radiance-uniform table (numba)",
        "the paper's 0.1 K table + `np.interp`"),
    "apparent_frames": KernelPair(
        "clearfast_gis.radiometry._kernels:apparent_frames",
        "clearfast_gis.radiometry._reference:apparent_frames",
        "calibration, atmosphere and inverse Planck fused per pixel, a block of frames row "
        "by row (numba)",
        "`raw_to_apparent` step by step (numpy)"),
    "heat_equation": KernelPair(
        "clearfast_gis.thermal._kernels:heat_equation",
        "clearfast_gis.thermal._reference:heat_equation",
        "band Cholesky, whole time loop compiled (numba, GIL released)",
        "scipy sparse LU, time loop in Python"),
}
"""Every kernel with a fast and a reference implementation."""


def kernel(name: str) -> Callable:
    """The active set's implementation of kernel ``name`` (:data:`REGISTRY`).

    Examples
    --------
    >>> with use("reference"):
    ...     kernel("heat_equation").__module__
    'clearfast_gis.thermal._reference'
    """
    return REGISTRY[name].implementation(_active)


def markdown_table() -> str:
    """The registry as the Markdown table of ``docs/performance.md``."""
    rows = ["| kernel | package | fast (default), `_kernels.py` | reference, `_reference.py` |",
            "|---|---|---|---|"]
    rows += [f"| `{name}` | `{k.domain}` | {k.fast_text} | {k.reference_text} |"
             for name, k in REGISTRY.items()]
    return "\n".join(rows)
