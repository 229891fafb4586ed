"""The detector's reconstructions: scikit-image vs OpenCV + SimpleITK (vs scipy) vs ours.

Run: .venv/bin/python benchmarks/detection_kernels.py [--repeat 15] [--mosaic SCAN.tif]
Prints markdown tables of median times (same images, same run) and checks the results agree:
the top-hat's reconstruction by dilation of the D1 erosion (640x512 float32 noise, and band 0
of a survey's scan mosaic when given, its no-data filled with its minimum), and the binary
reconstruction of the D2 opening (the image's top 3 % after the top-hat, seeded by its D2
erosion).
"""

from __future__ import annotations

import argparse
import time

import cv2
import numpy as np
import SimpleITK as sitk
from scipy import ndimage
from skimage.morphology import erosion
from skimage.morphology import reconstruction as sk_reconstruction

from clearfast_gis.detection.morphology import disk_footprint, erode_disk
from clearfast_gis.detection.reconstruction import (
    binary_reconstruction,
    reconstruction_by_dilation,
)

_EIGHT = np.ones((3, 3), dtype=bool)


def _skimage(f, fp):
    return sk_reconstruction(erosion(f, fp), f)


def _cv2_sitk(f, fp):
    seed = cv2.erode(f, fp)
    out = sitk.ReconstructionByDilation(sitk.GetImageFromArray(seed), sitk.GetImageFromArray(f),
                                        True)
    return sitk.GetArrayFromImage(out)


def _ours(f, fp, d):
    return reconstruction_by_dilation(erode_disk(f, d), f)


def _label_lookup(seed, mask):
    """The components of ``mask`` touching ``seed`` by labelling the whole mask (scipy)."""
    labels, n = ndimage.label(mask, structure=_EIGHT)
    keep = np.zeros(n + 1, dtype=bool)
    keep[labels[seed & mask]] = True
    keep[0] = False
    return keep[labels]


def _table(images: dict, methods: dict, repeat: int, reference: str) -> None:
    for name, arg in images.items():
        ref = methods[reference](*arg)
        for label, fn in methods.items():
            out = fn(*arg)  # warm-up (numba compile)
            times = []
            for _ in range(repeat):
                t0 = time.perf_counter()
                fn(*arg)
                times.append(time.perf_counter() - t0)
            equal = np.array_equal(np.asarray(out, dtype=np.float32),
                                   np.asarray(ref, dtype=np.float32))
            print(f"| {name} | {label} | {1000 * np.median(times):.1f} | {equal} |")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=15)
    ap.add_argument("--d1", type=float, default=15.0)
    ap.add_argument("--d2", type=float, default=3.0)
    ap.add_argument("--mosaic", help="a scan mosaic (COG) whose band 0 is a third image")
    args = ap.parse_args()
    rng = np.random.default_rng(0)
    images = {
        "smooth noise 640x512": ndimage.gaussian_filter(rng.random((512, 640)), 3
                                                        ).astype(np.float32),
        "white noise 640x512": rng.random((512, 640)).astype(np.float32),
    }
    if args.mosaic:
        from clearfast_gis.export.cog import read_mosaic

        band = read_mosaic(args.mosaic).bands_c[0]
        h, w = band.shape
        images[f"scan mosaic {w}x{h}"] = np.where(np.isfinite(band), band,
                                                  np.nanmin(band)).astype(np.float32)
    fp = disk_footprint(args.d1)
    print(f"Reconstruction by dilation of the D1 = {args.d1:g} px erosion (float32)\n")
    print("| image | implementation | median ms | equal to skimage |")
    print("|---|---|---|---|")
    _table({k: (f,) for k, f in images.items()}, {
        "skimage erosion + reconstruction": lambda f: _skimage(f, fp),
        "cv2.erode + SimpleITK ReconstructionByDilation": lambda f: _cv2_sitk(f, fp),
        "chord erosion + hybrid queue (numba, ours)": lambda f: _ours(f, fp, args.d1),
    }, args.repeat, "skimage erosion + reconstruction")
    masks = {}
    for name, f in images.items():
        hat = f - _ours(f, fp, args.d1)
        g = hat > np.quantile(hat, 0.97)
        masks[name] = (erode_disk(g, args.d2), g)
    print(f"\nBinary reconstruction of the top 3 % of the top-hat from its D2 = {args.d2:g} px "
          "erosion\n")
    print("| image | implementation | median ms | equal to skimage |")
    print("|---|---|---|---|")
    _table(masks, {
        "skimage reconstruction (uint8)": lambda s, m: sk_reconstruction(
            s.astype(np.uint8), m.astype(np.uint8), footprint=_EIGHT).astype(bool),
        "scipy label + lookup": _label_lookup,
        "seeded depth-first fill (numba, ours)": binary_reconstruction,
    }, args.repeat, "skimage reconstruction (uint8)")


if __name__ == "__main__":
    main()
