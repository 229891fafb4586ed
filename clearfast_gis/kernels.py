"""Which implementation the chain's heavy kernels run: ours or the reference libraries.

``fast`` (the default) runs the project's kernels (numba, OpenCV); ``reference`` runs the
same chain on the mature reference implementations each kernel is checked against:

=====================  =========================================  ===========================
kernel                 fast                                       reference
=====================  =========================================  ===========================
reconstruction         OpenCV disk erosion + hybrid queue (numba)  scikit-image erosion and
                                                                   ``reconstruction``
MI registration        Parzen-window Mattes MI with its analytic   SimpleITK Mattes MI,
                       gradient (numba), bounded L-BFGS            regular-step gradient
ground projection      cell-centre maps (numba) + ``cv2.remap``    ``Camera.project`` (numpy)
                                                                   + scipy ``map_coordinates``
inverse Planck         radiance-uniform table (numba)              the paper's 0.1 K table +
                                                                   ``np.interp``
heat-equation steps    band Cholesky, whole time loop compiled     scipy sparse LU, time loop
                       (numba, GIL released)                       in Python
=====================  =========================================  ===========================

The thermal inversion itself is the same in both: every anomaly is inverted on one site
table of forward runs (``benchmarks/thermal_inversion.py`` compares it with a model run per
anomaly); the kernel sets differ in how each forward run steps the heat equation.

The choice is process-wide (``clearfast process --kernels``); :func:`use` sets it for a block.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

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
