"""Global search for a coarse alignment: phase correlation of gradient magnitudes over angles.

Gradient magnitude is blind to the sign of the contrast, so a day image and a night image of
the same ground (contrast inverted, monotone but non-linear temperature mapping) correlate.
Phase correlation finds the translation for each trial angle in one FFT; the candidates are
then ranked by mutual information by the caller.
"""

from __future__ import annotations

import cv2
import numpy as np
import scipy.fft

from clearfast_gis.registration.transform import ConformalTransform


def gradient_magnitude(image: np.ndarray, margin_px: int = 2) -> np.ndarray:
    """Zero-mean gradient magnitude of an image with NaN no-data, 0 off the valid area.

    Parameters
    ----------
    image : ndarray, float32, shape (H, W)
        NaN marks no-data.
    margin_px : int
        Pixels next to no-data (and the image border) are zeroed over this width so the
        footprint outline itself does not register.

    Returns
    -------
    ndarray, float32, shape (H, W)
    """
    valid = np.isfinite(image)
    filled = np.where(valid, image, np.nanmean(image) if valid.any() else 0.0).astype(np.float32)
    gx = cv2.Sobel(filled, cv2.CV_32F, 1, 0, ksize=3, borderType=cv2.BORDER_REFLECT)
    gy = cv2.Sobel(filled, cv2.CV_32F, 0, 1, ksize=3, borderType=cv2.BORDER_REFLECT)
    # not cv2.magnitude: its IPP path rounds the last bit differently depending on the
    # buffers' memory alignment, which made two runs of the chain register differently;
    # numpy's elementwise operations are correctly rounded wherever the data sit
    mag = np.sqrt(gx * gx + gy * gy)
    core = valid.astype(np.uint8)
    if margin_px > 0:
        core = cv2.erode(core, np.ones((2 * margin_px + 1,) * 2, np.uint8),
                         borderType=cv2.BORDER_CONSTANT, borderValue=0)
    inside = core.astype(bool)
    if not inside.any():
        return np.zeros_like(mag)
    mag -= mag[inside].mean()
    mag[~inside] = 0.0
    return mag


def _subpixel(r: np.ndarray, i: int, j: int) -> tuple[float, float]:
    """Parabolic refinement of a peak at (row i, col j) of a periodic surface."""
    h, w = r.shape
    c = r[i, j]

    def vertex(m: float, p: float) -> float:
        den = m - 2.0 * c + p
        return 0.0 if den >= 0 else float(np.clip(0.5 * (m - p) / den, -0.5, 0.5))

    di = vertex(r[(i - 1) % h, j], r[(i + 1) % h, j])
    dj = vertex(r[i, (j - 1) % w], r[i, (j + 1) % w])
    return i + di, j + dj


class PhaseCorrelator:
    """Phase correlation of one fixed image against many moving images.

    Finds shifts ``d`` with ``fixed(x) ~ moving(x + d)`` (``x = (u, v)``); both images are
    zero-padded so that every shift that leaves some overlap is represented once.

    Parameters
    ----------
    fixed : ndarray, float32, shape (Hf, Wf)
        Typically :func:`gradient_magnitude` of the fixed image.
    moving_shape : tuple of int
        ``(Hm, Wm)`` of the moving images to come.
    """

    def __init__(self, fixed: np.ndarray, moving_shape: tuple[int, int]) -> None:
        hf, wf = fixed.shape
        hm, wm = moving_shape
        self.shape = (scipy.fft.next_fast_len(hf + hm), scipy.fft.next_fast_len(wf + wm))
        self._ff = scipy.fft.rfft2(fixed, s=self.shape, workers=1)

    def peaks(
        self,
        moving: np.ndarray,
        n_peaks: int = 3,
        center_uv: tuple[float, float] = (0.0, 0.0),
        max_shift_px: float | None = None,
    ) -> list[tuple[float, float, float]]:
        """The ``n_peaks`` highest correlation peaks as ``(du, dv, height)``.

        Only shifts within ``max_shift_px`` (per axis) of ``center_uv`` are considered.
        Peaks are separated by at least 3 pixels.
        """
        fm = scipy.fft.rfft2(moving, s=self.shape, workers=1)
        cross = self._ff * np.conj(fm)
        cross /= np.abs(cross) + 1e-12
        raw = scipy.fft.irfft2(cross, s=self.shape, workers=1)
        r = raw
        h, w = self.shape
        # r peaks at index k = -d (mod shape): fixed(x) = moving(x + d)
        dv = -np.fft.fftfreq(h, 1.0 / h)[:, None]
        du = -np.fft.fftfreq(w, 1.0 / w)[None, :]
        if max_shift_px is not None:
            allowed = ((np.abs(du - center_uv[0]) <= max_shift_px + 1.0)
                       & (np.abs(dv - center_uv[1]) <= max_shift_px + 1.0))
            r = np.where(allowed, r, -np.inf)
        out: list[tuple[float, float, float]] = []
        work = r.copy()
        for _ in range(n_peaks):
            flat = int(np.argmax(work))
            i, j = divmod(flat, w)
            height = float(work[i, j])
            if not np.isfinite(height):
                break
            fi, fj = _subpixel(raw, i, j)
            shift_v = -(fi if fi < h / 2 else fi - h)
            shift_u = -(fj if fj < w / 2 else fj - w)
            out.append((float(shift_u), float(shift_v), height))
            rows = np.arange(i - 3, i + 4) % h
            cols = np.arange(j - 3, j + 4) % w
            work[np.ix_(rows, cols)] = -np.inf
        return out


def rotation_candidates(
    fixed_grad: np.ndarray,
    moving_grad: np.ndarray,
    angles_rad: np.ndarray,
    fixed_center: tuple[float, float],
    base: ConformalTransform,
    max_shift_px: float | None,
    n_peaks: int = 3,
) -> list[ConformalTransform]:
    """Candidate transforms (fixed -> moving) from rotated phase correlations.

    Parameters
    ----------
    fixed_grad, moving_grad : ndarray, float32
        Gradient magnitudes (:func:`gradient_magnitude`) of the fixed and moving images.
    angles_rad : ndarray (K,)
        Trial rotation angles (radians, Eq. 3 convention).
    fixed_center : tuple of float
        Rotation centre of the returned transforms, fixed pixels.
    base : ConformalTransform
        Translation bounds are taken around ``base``'s translation.
    max_shift_px : float or None
        Largest allowed deviation of the translation from ``base``, pixels.
    n_peaks : int
        Peaks kept per angle.

    Returns
    -------
    list of ConformalTransform
        ``len(angles_rad) * n_peaks`` candidates at most, metric unset.
    """
    hm, wm = moving_grad.shape
    cm = ((wm - 1) / 2.0, (hm - 1) / 2.0)
    c = np.asarray(fixed_center, dtype=np.float64)
    pc = PhaseCorrelator(fixed_grad, moving_grad.shape)
    out: list[ConformalTransform] = []
    for ang in angles_rad:
        rot = ConformalTransform(float(ang), scale=base.scale, center_px=cm)
        rotated = cv2.warpAffine(moving_grad, rot.matrix(), (wm, hm),
                                 flags=cv2.INTER_LINEAR | cv2.WARP_INVERSE_MAP,
                                 borderMode=cv2.BORDER_CONSTANT, borderValue=0.0)
        lin = rot.linear()
        # fixed(x) = rotated(x + d) = moving(R (x + d - cm) + cm)  =>  t = R (d - cm + c) + cm - c
        expected_d = None
        if max_shift_px is not None:
            # d = R^-1 (t - cm + c) + cm - c, evaluated at the base translation
            t0 = np.array([base.tx_px, base.ty_px])
            expected_d = np.linalg.solve(lin, t0 - np.asarray(cm) + c) + np.asarray(cm) - c
        for du, dv, _height in pc.peaks(
            rotated, n_peaks,
            center_uv=(0.0, 0.0) if expected_d is None else (expected_d[0], expected_d[1]),
            max_shift_px=max_shift_px,
        ):
            d = np.array([du, dv])
            t = lin @ (d - np.asarray(cm) + c) + np.asarray(cm) - c
            out.append(ConformalTransform(float(ang), float(t[0]), float(t[1]), base.scale,
                                          center_px=(float(c[0]), float(c[1]))))
    return out
