"""The kernel registry: every kernel's fast and reference implementations, run on one input
each, give the same answer within the kernel's stated tolerance; the docs table is the
registry's."""

from __future__ import annotations

from pathlib import Path

import cv2
import numpy as np
import pytest

from clearfast_gis import kernels
from tests.kernels.scenes import scene

DOCS = Path(__file__).resolve().parents[2] / "docs" / "performance.md"


def _geometry():
    from clearfast_gis.geometry import CameraPose, EquiangularCamera, GroundGrid

    cam = EquiangularCamera(160, 128, aperture_deg=9.0)
    pose = CameraPose(np.array([0.0, 0.0, 12.0]), azimuth_deg=20.0, elevation_deg=-35.0)
    grid = GroundGrid.from_bounds(-5.0, 5.0, 20.0, 25.0, 0.05, epsg=32636)
    return cam, pose, grid


def _same_image(a, b, atol: float = 0.0) -> None:
    assert np.array_equal(np.isnan(a), np.isnan(b))
    ok = ~np.isnan(a)
    np.testing.assert_allclose(a[ok], b[ok], rtol=0, atol=atol)


def _hat():
    return (scene(), 15), lambda a, b: _same_image(a, b)  # identical


def _opening():
    return (np.nan_to_num(scene(3)) > 0.2, 5), np.testing.assert_array_equal


def _order_statistics():
    rng = np.random.default_rng(11)
    values = rng.normal(0.0, 1.0, 50_001).astype(np.float32)
    values[:20_000] = 0.0  # a hat image: mostly zeros
    ranks = [0, 500, 25_000, 49_500, 50_000]
    return (values, ranks), np.testing.assert_array_equal  # the same values, bit for bit


def _box_mean():
    rng = np.random.default_rng(12)
    image = rng.normal(20.0, 3.0, (97, 131))
    return (image, 15), np.testing.assert_array_equal  # scipy's values, bit for bit


def _registration():
    import math

    from clearfast_gis.registration import ConformalTransform, register_conformal
    from clearfast_gis.registration.synthetic import make_pair, rms_displacement

    shape = (256, 320)
    truth = ConformalTransform(math.radians(1.5), 6.3, -4.1,
                               center_px=((shape[1] - 1) / 2, (shape[0] - 1) / 2))
    fixed, moving = make_pair(shape, truth, seed=7, noise_k=0.1)

    def agree(a, b):
        assert a.converged and b.converged
        assert rms_displacement(a, truth, shape) < 0.05  # pixels
        assert rms_displacement(b, truth, shape) < 0.05

    return (lambda: register_conformal(fixed, moving, max_shift_px=20, max_angle_deg=4)), agree


def _maps():
    cam, pose, grid = _geometry()

    def agree(a, b):
        (mx, my), (rx, ry) = a, b
        both = (mx >= 0) & (rx >= 0)
        assert both.sum() > 1000 and np.mean((mx >= 0) != (rx >= 0)) < 1e-3
        assert np.max(np.abs(mx[both] - rx[both])) < 1e-3  # pixels (float32 rounding)
        assert np.max(np.abs(my[both] - ry[both])) < 1e-3

    return (cam, pose, grid, 0.0, True), agree


def _resample():
    from clearfast_gis.geometry.projection import ground_maps

    cam, pose, grid = _geometry()
    mx, my = ground_maps(cam, pose, grid)
    frame = np.nan_to_num(scene(5, (128, 160))[:, ::-1].copy(), nan=0.5) + 20.0
    inner = cv2.erode((mx >= 0).astype(np.uint8), np.ones((9, 9), np.uint8)).astype(bool)

    def agree(a, b):
        # cv2 works in fixed point (1/32 pixel) and truncates its Gaussian differently
        assert np.all(np.isfinite(b[inner])) and inner.sum() > 1000
        assert np.nanmax(np.abs(a[inner] - b[inner])) < 0.02  # K

    return (frame, mx, my, 1.2), agree


def _inverse_planck():
    from clearfast_gis.radiometry.table import BandTable

    table = BandTable(8.0, 9.2)
    rad = table.radiance(np.linspace(240.0, 340.0, 1001))

    def agree(a, b):  # linear interpolation on the paper's 0.1 K table
        assert np.max(np.abs(a - b)) < 0.03  # K

    return (table, rad, np.float64), agree


def _apparent_frames():
    from clearfast_gis.radiometry.calibration import GainOffset
    from clearfast_gis.radiometry.table import BandTable

    rng = np.random.default_rng(4)
    table = BandTable(8.0, 9.2)
    shape = (48, 64)
    raw = rng.integers(9000, 12000, size=(3, *shape)).astype(np.uint16)

    def calibration(level):
        gain = np.full(shape, 2.0e-4) * rng.uniform(0.95, 1.05, shape)
        offset = np.full(shape, level)
        valid = np.ones(shape, dtype=bool)
        valid[0, :3] = False
        gain[~valid] = offset[~valid] = np.nan
        return GainOffset(gain, offset, valid)

    early, late = calibration(1.2), calibration(1.3)
    # one calibration alone, two blended in time, the other alone; a scalar transmittance,
    # a map and another scalar
    parts = [[(early, 1.0)], [(early, 0.25), (late, 0.75)], [(late, 1.0)]]
    taus = [0.93, rng.uniform(0.9, 0.95, shape), 0.97]
    t_air = np.array([295.0, 296.0, 297.0])

    def agree(a, b):
        _same_image(a, b, atol=0.03)  # K: the fast table against the paper's 0.1 K table
        assert np.isfinite(a).sum() > 3 * 3000

    return (raw, parts, taus, t_air, table.radiance(t_air), table,
            np.empty((3, *shape), np.float32)), agree


def _heat_equation():
    from clearfast_gis.thermal import clear_sky_forcing, get_soil, simulate_background

    forcing = clear_sky_forcing(9.0, -75.0, 1763164800.0, 6 * 3600.0, 300.0)
    out_t = forcing.time_s[::4]

    def run():
        return simulate_background(get_soil("dry_sand"), forcing, out_t).surface_k

    return run, lambda a, b: np.testing.assert_allclose(a, b, rtol=0, atol=1e-6)  # K


EXAMPLES = {
    "top_hat_by_reconstruction": _hat,
    "bottom_hat_by_reconstruction": _hat,
    "binary_opening_by_reconstruction": _opening,
    "order_statistics": _order_statistics,
    "box_mean": _box_mean,
    "register_conformal": _registration,
    "ground_maps": _maps,
    "resample": _resample,
    "inverse_planck": _inverse_planck,
    "apparent_frames": _apparent_frames,
    "heat_equation": _heat_equation,
}


def test_every_kernel_has_an_example():
    assert set(EXAMPLES) == set(kernels.REGISTRY)


@pytest.mark.parametrize("name", sorted(kernels.REGISTRY))
def test_fast_and_reference_agree(name):
    args, agree = EXAMPLES[name]()
    pair = kernels.REGISTRY[name]
    if callable(args):  # a whole model run, on each kernel set
        results = []
        for kernel_set in kernels.KERNELS:
            with kernels.use(kernel_set):
                assert kernels.kernel(name) is pair.implementation(kernel_set)
                results.append(args())
    else:
        results = []
        for kernel_set in kernels.KERNELS:
            run = pair.implementation(kernel_set)
            copied = [a.copy() if isinstance(a, np.ndarray) else a for a in args]
            out = run(*copied)
            results.append(copied[-1] if out is None else out)
    agree(*results)


def test_docs_table_is_the_registry():
    assert kernels.markdown_table() in DOCS.read_text()


@pytest.mark.parametrize("name", sorted(kernels.REGISTRY))
def test_implementations_live_in_their_domains_private_modules(name):
    """``clearfast_gis.<domain>._kernels:<name>`` and ``clearfast_gis.<domain>._reference:<name>``;
    the public function of the domain that holds the name calls it through the registry."""
    pair = kernels.REGISTRY[name]
    domain = pair.domain
    assert pair.fast == f"clearfast_gis.{domain}._kernels:{name}"
    assert pair.reference == f"clearfast_gis.{domain}._reference:{name}"
    for kernel_set in kernels.KERNELS:
        impl = pair.implementation(kernel_set)
        assert impl.__name__ == name and impl.__module__ == pair.__getattribute__(
            kernel_set).split(":")[0]
    root = Path(kernels.__file__).parent / domain
    callers = [p.name for p in root.glob("*.py")
               if f'kernels.kernel("{name}")' in p.read_text()]
    assert len(callers) == 1 and not callers[0].startswith("_"), callers


def test_no_kernel_branch_left_in_public_functions():
    """Kernels are chosen through the registry only; ``parallel.serial_kernels`` asks which
    set is active to set the libraries' thread pools, which is not a kernel."""
    root = Path(kernels.__file__).parent
    branches = [p.relative_to(root).as_posix() for p in root.rglob("*.py")
                if "kernels.reference()" in p.read_text()]
    assert branches == ["parallel.py"]
