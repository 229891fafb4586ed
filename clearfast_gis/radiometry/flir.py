"""FLIR's camera radiometry: raw signal <-> object temperature with the camera's own parameters.

FLIR radiometric cameras (and cores inside other makers' cameras, e.g. DJI Zenmuse XT) store a
raw 16-bit signal ``S`` that is, after the offset ``O``, proportional to the band radiance the
detector received, and the calibration of that proportionality as "Planck constants":

    S = R1 / (R2 (exp(B / T) - F)) - O            T in kelvin (the sensor's blackbody law)
    T = B / ln(R1 / (R2 (S + O)) + F)

The object temperature the camera's software shows removes, in signal units, the reflected
surroundings (emissivity ``E``, reflected apparent temperature), the atmosphere between object
and camera (air temperature, relative humidity, the camera's single ``ObjectDistance`` and its
stored transmittance constants ``AtmosphericTrans{X,Alpha1,Alpha2,Beta1,Beta2}``) and an
optional external IR window (temperature and transmission). The formula is the one FLIR's
software uses as published by the Thermimage R package's ``raw2temp`` (G. Tattersall,
doi:10.5281/zenodo.1069704): the path is split at the window, each half with the transmittance
of ``ObjectDistance / 2`` (:func:`clearfast_gis.radiometry.atmosphere.water_vapour_transmittance`,
the same model as the toolkit's own atmosphere). Without a window (transmission 1) this is
the model ``S_obj = (S - (1 - tau) S_atm - tau (1 - E) S_refl) / (E tau)``.

Temperatures in this module are degrees Celsius where the name says ``_c`` (the cameras' own
unit) and kelvin where it says ``_k``; raw signals are dimensionless counts (float64).
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np
from numpy.typing import ArrayLike

from clearfast_gis.errors import InvalidInput
from clearfast_gis.radiometry.atmosphere import water_vapour_content, water_vapour_transmittance
from clearfast_gis.units import ZERO_CELSIUS_K as C_TO_K


@dataclass(frozen=True)
class FlirPlanck:
    """A FLIR camera's calibration of raw signal against blackbody temperature.

    Attributes
    ----------
    r1, r2, b, f, o : float
        ``PlanckR1``, ``PlanckR2``, ``PlanckB`` (kelvin), ``PlanckF``, ``PlanckO`` (counts).
    """

    r1: float
    r2: float
    b: float
    f: float
    o: float

    def signal(self, t_k: ArrayLike) -> np.ndarray:
        """Raw signal of a blackbody at ``t_k`` (kelvin), counts (float64)."""
        t = np.asarray(t_k, dtype=np.float64)
        return self.r1 / (self.r2 * (np.exp(self.b / t) - self.f)) - self.o

    def temperature_k(self, signal: ArrayLike) -> np.ndarray:
        """Blackbody temperature (kelvin) of a raw signal; NaN where no temperature fits."""
        s = np.asarray(signal, dtype=np.float64)
        with np.errstate(divide="ignore", invalid="ignore"):
            arg = self.r1 / (self.r2 * (s + self.o)) + self.f
            t = self.b / np.log(arg)
        return np.where(np.isfinite(t) & (t > 0), t, np.nan)


@dataclass(frozen=True)
class FlirObjectParams:
    """The camera's object parameters stored with each radiometric frame.

    Attributes
    ----------
    emissivity : float
        Object emissivity, (0, 1].
    reflected_c : float
        Reflected apparent temperature, degrees C.
    atmosphere_c : float
        Atmospheric temperature, degrees C.
    distance_m : float
        ``ObjectDistance`` (the camera's, not EXIF SubjectDistance), metres.
    rh_pct : float
        Relative humidity, percent (FLIR stores a fraction; readers convert).
    window_c : float
        IR window temperature, degrees C.
    window_transmission : float
        IR window transmission, (0, 1]; 1 = no window.
    x, alpha1, alpha2, beta1, beta2 : float
        The camera's atmospheric transmittance constants.
    """

    emissivity: float
    reflected_c: float
    atmosphere_c: float
    distance_m: float
    rh_pct: float
    window_c: float
    window_transmission: float
    x: float
    alpha1: float
    alpha2: float
    beta1: float
    beta2: float

    def __post_init__(self) -> None:
        checks = {
            "emissivity": 0.0 < self.emissivity <= 1.0,
            "distance_m": 0.0 <= self.distance_m <= 1e5,
            "rh_pct": 0.0 <= self.rh_pct <= 100.0,
            "window_transmission": 0.0 < self.window_transmission <= 1.0,
        }
        for f in fields(self):
            if not np.isfinite(getattr(self, f.name)):
                raise InvalidInput(f"not a finite number: {getattr(self, f.name)}", field=f.name)
        for name, ok in checks.items():
            if not ok:
                raise InvalidInput(f"not physical: {getattr(self, name)}", field=name)

    def half_path_transmittance(self) -> float:
        """Transmittance of half the object distance (each side of the IR window)."""
        w = water_vapour_content(self.atmosphere_c + C_TO_K, self.rh_pct)
        return float(water_vapour_transmittance(self.distance_m / 2.0, w, self.x, self.alpha1,
                                                self.alpha2, self.beta1, self.beta2))

    def transmittance(self) -> float:
        """Transmittance of the whole object distance as the camera models it."""
        return self.half_path_transmittance() ** 2


def object_signal(raw: ArrayLike, planck: FlirPlanck, p: FlirObjectParams) -> np.ndarray:
    """The object's own blackbody-equivalent signal: raw signal with reflection, atmosphere and
    window removed by the camera's model (Thermimage ``raw2temp``).

    Parameters
    ----------
    raw : array_like
        Raw signal, counts, any shape.
    planck : FlirPlanck
        The camera's calibration.
    p : FlirObjectParams
        The frame's object parameters.

    Returns
    -------
    ndarray of float64
        Signal of a blackbody at the object temperature, counts, shape of ``raw``.
    """
    e, irt = p.emissivity, p.window_transmission
    tau = p.half_path_transmittance()
    s_refl = float(planck.signal(p.reflected_c + C_TO_K))
    s_atm = float(planck.signal(p.atmosphere_c + C_TO_K))
    s_win = float(planck.signal(p.window_c + C_TO_K))
    # With an anti-reflective window (reflection 0): the terms of raw2temp in its order.
    atm1 = (1.0 - tau) / e / tau * s_atm
    atm2 = (1.0 - tau) / e / tau / irt / tau * s_atm
    win = (1.0 - irt) / e / tau / irt * s_win
    refl = (1.0 - e) / e * s_refl
    r = np.asarray(raw, dtype=np.float64)
    return r / e / tau / irt / tau - atm1 - atm2 - win - refl


def raw_from_object_signal(s_obj: ArrayLike, planck: FlirPlanck,
                           p: FlirObjectParams) -> np.ndarray:
    """Inverse of :func:`object_signal`: the raw signal the camera records (float64 counts)."""
    e, irt = p.emissivity, p.window_transmission
    tau = p.half_path_transmittance()
    zero = object_signal(0.0, planck, p)
    return (np.asarray(s_obj, dtype=np.float64) - zero) * (e * tau * irt * tau)


def object_temperature_c(raw: ArrayLike, planck: FlirPlanck, p: FlirObjectParams) -> np.ndarray:
    """Object temperature, degrees C, as the camera's software computes it (float64, NaN where
    the raw signal has no temperature)."""
    return planck.temperature_k(object_signal(raw, planck, p)) - C_TO_K


def raw_from_object_temperature_c(t_c: ArrayLike, planck: FlirPlanck,
                                  p: FlirObjectParams) -> np.ndarray:
    """The raw signal (float64 counts) the camera records for an object at ``t_c`` (deg C)."""
    return raw_from_object_signal(planck.signal(np.asarray(t_c, dtype=np.float64) + C_TO_K),
                                  planck, p)
