"""ConformalTransform: Eq. 3 layout, OpenCV agreement, compose/inverse round trips."""

from __future__ import annotations

import math

import cv2
import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from clearfast_gis.registration import ConformalTransform

angles = st.floats(-math.pi, math.pi, allow_nan=False)
shifts = st.floats(-500.0, 500.0, allow_nan=False)
scales = st.floats(0.5, 2.0, allow_nan=False)
coords = st.floats(-200.0, 800.0, allow_nan=False)


@st.composite
def transforms(draw: st.DrawFn) -> ConformalTransform:
    return ConformalTransform(draw(angles), draw(shifts), draw(shifts), draw(scales),
                              center_px=(draw(coords), draw(coords)))


def _grid() -> np.ndarray:
    vv, uu = np.mgrid[-50:700:37, -30:650:41].astype(float)
    return np.column_stack([uu.ravel(), vv.ravel()])


def test_eq3_row_vector_layout() -> None:
    # Eq. 3: (u, v) = [x y 1] [[cos a, -sin a], [sin a, cos a], [tx, ty]] about the origin
    a, tx, ty = 0.3, 4.0, -2.5
    t = ConformalTransform(a, tx, ty)
    m = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)], [tx, ty]])
    pts = _grid()
    expected = np.column_stack([pts, np.ones(len(pts))]) @ m
    np.testing.assert_allclose(t.apply(pts), expected, atol=1e-9)


@given(angles, shifts, shifts, scales, coords, coords)
def test_matrix_matches_opencv_rotation_matrix(a: float, tx: float, ty: float, s: float,
                                               cu: float, cv: float) -> None:
    t = ConformalTransform(a, tx, ty, s, center_px=(cu, cv))
    ref = cv2.getRotationMatrix2D((cu, cv), math.degrees(a), s)
    ref[:, 2] += (tx, ty)
    np.testing.assert_allclose(t.matrix(), ref, atol=1e-6 * (1 + abs(cu) + abs(cv)))


@settings(max_examples=200)
@given(transforms())
def test_inverse_round_trip(t: ConformalTransform) -> None:
    pts = _grid()
    np.testing.assert_allclose(t.inverse().apply(t.apply(pts)), pts, atol=1e-7)
    ident = t.compose(t.inverse())
    assert abs(ident.scale - 1) < 1e-12 and abs(math.sin(ident.angle_rad)) < 1e-12
    np.testing.assert_allclose(ident.apply(pts), pts, atol=1e-7)


@settings(max_examples=200)
@given(transforms(), transforms())
def test_compose_is_apply_after_apply(a: ConformalTransform, b: ConformalTransform) -> None:
    pts = _grid()
    ab = a.compose(b)
    assert ab.center_px == b.center_px
    np.testing.assert_allclose(ab.apply(pts), a.apply(b.apply(pts)), atol=1e-6, rtol=1e-9)
    # (a o b)^-1 = b^-1 o a^-1
    np.testing.assert_allclose(ab.inverse().apply(pts),
                               b.inverse().compose(a.inverse()).apply(pts), atol=1e-6,
                               rtol=1e-9)


@given(transforms(), coords, coords)
def test_with_center_keeps_the_map(t: ConformalTransform, cu: float, cv: float) -> None:
    pts = _grid()
    moved = t.with_center((cu, cv))
    assert moved.center_px == (cu, cv)
    np.testing.assert_allclose(moved.apply(pts), t.apply(pts), atol=1e-7)


@given(transforms())
def test_from_matrix_round_trip(t: ConformalTransform) -> None:
    back = ConformalTransform.from_matrix(t.matrix(), t.center_px)
    np.testing.assert_allclose(back.matrix(), t.matrix(), atol=1e-9)
    assert abs(back.scale - t.scale) < 1e-12


@given(transforms(), st.sampled_from([0.5, 0.25, 2.0]))
def test_scaled_is_the_map_on_resampled_pixels(t: ConformalTransform, f: float) -> None:
    pts = _grid()
    np.testing.assert_allclose(t.scaled(f).apply(pts * f), t.apply(pts) * f, atol=1e-7)


def test_record_fields_survive_inverse() -> None:
    t = ConformalTransform(0.1, 1, 2, 1.0, metric=0.8, n_samples=123, converged=False)
    inv = t.inverse()
    assert (inv.metric, inv.n_samples, inv.converged) == (0.8, 123, False)
