"""Image registration: mutual information, the conformal model of Eq. 3, band co-registration.

- :func:`register_conformal` aligns a moving image to a fixed one (temporal co-registration of
  frames and mosaics, frame-to-mosaic co-registration), robust to the day/night contrast
  inversion and to ragged no-data footprints.
- :func:`warp_conformal` resamples the moving image onto the fixed grid.
- :func:`mutual_information`, :func:`normalized_mutual_information` score an alignment.
- :func:`estimate_band_offsets`, :func:`apply_band_offsets` co-register the spectral bands.
"""

from clearfast_gis.registration.bands import apply_band_offsets, estimate_band_offsets
from clearfast_gis.registration.conformal import register_conformal
from clearfast_gis.registration.metric import (
    joint_histogram,
    mutual_information,
    normalized_mutual_information,
)
from clearfast_gis.registration.transform import ConformalTransform
from clearfast_gis.registration.warp import warp_conformal

__all__ = [
    "ConformalTransform",
    "apply_band_offsets",
    "estimate_band_offsets",
    "joint_histogram",
    "mutual_information",
    "normalized_mutual_information",
    "register_conformal",
    "warp_conformal",
]
