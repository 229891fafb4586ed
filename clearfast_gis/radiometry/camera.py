"""A radiometric camera's own calibration: stored counts to at-sensor blackbody temperature.

Radiometric cameras calibrate themselves; a survey made with one (``survey.json``
``camera.radiometry``, written by ``clearfast import``) needs no blackbody frames. The
stage turns its counts into the at-sensor blackbody temperature, that into band radiance
(:class:`~clearfast_gis.radiometry.table.BandTable`), and then applies the toolkit's own
atmosphere per pixel (weather log, slant range) exactly as for calibrated detector counts.

- ``flir-planck``: counts are FLIR's raw signal; ``T = B / ln(R1 / (R2 (S + O)) + F)``
  (:class:`~clearfast_gis.radiometry.flir.FlirPlanck`), i.e. the camera's radiometry with
  emissivity 1 and no atmosphere (both are the chain's business).
- ``linear``: ``T_K = scale_k * counts + offset_k`` (TLinear cores; temperature TIFFs stored at
  0.01 K per count). The camera must have been set to emissivity 1 and no atmospheric
  correction (a TLinear core's defaults), so that its temperature is the at-sensor one.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry.flir import FlirPlanck

KINDS = ("flir-planck", "linear")


@dataclass(frozen=True)
class CameraRadiometry:
    """Counts -> at-sensor blackbody temperature of a self-calibrated camera.

    Attributes
    ----------
    kind : {"flir-planck", "linear"}
    planck : FlirPlanck or None
        FLIR's constants (``flir-planck``).
    scale_k, offset_k : float
        Kelvin per count and kelvin offset (``linear``).
    """

    kind: str
    planck: FlirPlanck | None = None
    scale_k: float = 1.0
    offset_k: float = 0.0

    def sensor_temperature_k(self, counts: ArrayLike) -> np.ndarray:
        """At-sensor blackbody temperature, kelvin (float64, shape of ``counts``; NaN where
        the counts have no temperature)."""
        c = np.asarray(counts, dtype=np.float64)
        if self.kind == "flir-planck":
            return self.planck.temperature_k(c)
        return self.scale_k * c + self.offset_k

    def counts(self, t_k: ArrayLike) -> np.ndarray:
        """The counts (float64) of an at-sensor blackbody temperature, kelvin."""
        t = np.asarray(t_k, dtype=np.float64)
        if self.kind == "flir-planck":
            return self.planck.signal(t)
        return (t - self.offset_k) / self.scale_k

    def to_manifest(self) -> dict:
        """The ``camera.radiometry`` object of ``survey.json``."""
        if self.kind == "flir-planck":
            p = self.planck
            return {"kind": self.kind, "planck": {"r1": p.r1, "r2": p.r2, "b": p.b, "f": p.f,
                                                  "o": p.o}}
        return {"kind": self.kind, "scale_k": self.scale_k, "offset_k": self.offset_k}

    @classmethod
    def from_manifest(cls, doc: dict, source: str = "survey.json") -> CameraRadiometry:
        """From ``survey.json`` ``camera.radiometry`` (already schema-checked)."""
        kind = doc.get("kind")
        if kind == "flir-planck":
            p = doc["planck"]
            return cls(kind, planck=FlirPlanck(float(p["r1"]), float(p["r2"]), float(p["b"]),
                                               float(p["f"]), float(p["o"])))
        if kind == "linear":
            if not float(doc["scale_k"]) > 0:
                raise InvalidInput("must be positive", source, "camera.radiometry.scale_k")
            return cls(kind, scale_k=float(doc["scale_k"]), offset_k=float(doc["offset_k"]))
        raise InvalidInput(f"unknown kind {kind!r} (expected one of {', '.join(KINDS)})", source,
                           "camera.radiometry.kind")
