"""How much thermal contrast a survey's day gave, from what its logs say.

The thermal model of the site (the weather log's forcing, the soil fitted to the
thermocouples and the background) is run for a reference mine, a 10.4 cm x 8 cm TNT
cylinder (the M2A4 AP mine), at a few depths. Its contrast over the survey's scans, as much
of it as the mosaics deliver to the detector (:data:`DELIVERED_FRACTION`), against the
detector's own cut (its threshold in noise sigmas, in at least the share of the scans that
votes) says down to which depth a buried mine can show on that day: a clear day in sand
gives kelvins at 1 cm, an overcast day after rain a few tenths or less.
The sun is compared with the clear sky of the site and date (clear-sky index).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from clearfast_gis.detection.clutter import THRESHOLD_SNR
from clearfast_gis.thermal.canopy import seen_share, under_canopy
from clearfast_gis.thermal.forcing import Forcing
from clearfast_gis.thermal.forward import BuriedObject, ObjectModel
from clearfast_gis.thermal.materials import MATERIALS, Soil
from clearfast_gis.thermal.solar import clear_sky_ghi, solar_position

#: Reference mine: radius and height (m) of the M2A4 AP mine, TNT-filled.
REFERENCE_RADIUS_M = 0.052
REFERENCE_HEIGHT_M = 0.08
#: Depths at which the day's contrast is stated, m.
REFERENCE_DEPTHS_M = (0.0, 0.01, 0.02, 0.03, 0.05, 0.08, 0.10)
#: The detector's cut lies at most ``threshold_snr`` clutter sigmas above the background; the
#: hat at a mine's peak cell sits about this many sigmas above its mean contrast (the largest
#: of signal plus noise over the mine's 20-30 cells).
PEAK_LIFT_SIGMA = 1.0
#: A contrast shows when it exceeds this many noise sigmas (the detector's default cut,
#: ``ProcessOptions.threshold_snr``, less the lift of the peak cell) ...
SHOW_SNR = THRESHOLD_SNR - PEAK_LIFT_SIGMA
#: ... in at least this share of the scans (the detector's default voting level).
SHOW_SCAN_SHARE = 0.25
#: Share of the modelled peak contrast the detector sees at the mine on the mosaics: the
#: top-hat's peak at a 10.4 cm mine 5 cm deep over the modelled peak was 0.6-0.75 on the
#: clear demo surveys of ``benchmarks/conditions.py`` (seed 0: clear, tropics, grass), 1.2
#: under the overcast and in the northern summer; at 1-3 cm, where contrasts are larger,
#: 0.4-0.75. The camera's pixel footprint (2-5 cm) and the mosaic's cell spread the 10 cm
#: signature, the top-hat measures it from the saddle of its surroundings, the band
#: emissivity (0.84-0.97) scales it.
DELIVERED_FRACTION = 0.7


@dataclass(frozen=True)
class DayContrast:
    """The day's contrast for the reference mine.

    Attributes
    ----------
    depths_m : ndarray, shape (D,)
        Depths of the reference mine, m.
    peak_contrast_k : ndarray, shape (D,)
        Peak |contrast| over the scans (centre minus background), K.
    showing_share : ndarray, shape (D,)
        Share of the scans whose delivered |contrast| (``delivered_fraction`` of it) reaches
        ``show_snr`` noise sigmas.
    noise_k : float
        1-sigma noise of a measured contrast, K.
    clear_sky_index : float
        Measured over clear-sky solar energy of the daylight hours (1 clear, ~0.3 overcast);
        NaN without daylight.
    rain_mm : float
        Rain logged over the record, mm.
    delivered_fraction, show_snr, show_share : float
        Share of the contrast the mosaics deliver, the detector's cut in noise sigmas and
        the share of the scans that must reach it.
    curves_k : ndarray, shape (D, S), or None
        The reference mine's modelled contrast (centre minus background, signed) at each
        depth and scan time, K: the diurnal curve a buried mine follows on that day
        (:func:`clearfast_gis.detection.curve.mine_curve_match`).
    """

    depths_m: np.ndarray
    peak_contrast_k: np.ndarray
    showing_share: np.ndarray
    noise_k: float
    clear_sky_index: float
    rain_mm: float
    delivered_fraction: float = DELIVERED_FRACTION
    show_snr: float = SHOW_SNR
    show_share: float = SHOW_SCAN_SHARE
    curves_k: np.ndarray | None = None

    @property
    def deepest_showing_m(self) -> float:
        """Deepest reference depth whose delivered contrast reaches ``show_snr`` noise sigmas
        in at least ``show_share`` of the scans, m; NaN when even the shallowest does not."""
        shows = self.showing_share >= self.show_share - 1e-9
        return float(self.depths_m[shows].max()) if shows.any() else float("nan")

    def contrast_at(self, depth_m: float) -> float:
        """Peak contrast at ``depth_m`` (linear between the reference depths), K."""
        return float(np.interp(depth_m, self.depths_m, self.peak_contrast_k))

    def as_dict(self) -> dict:
        """JSON-ready record (products.json ``day_contrast``)."""
        return {"reference": "TNT cylinder 10.4 cm x 8 cm (AP mine)",
                "depths_m": [float(d) for d in self.depths_m],
                "peak_contrast_k": [round(float(c), 4) for c in self.peak_contrast_k],
                "showing_share": [round(float(c), 3) for c in self.showing_share],
                "noise_k": round(float(self.noise_k), 4),
                "delivered_fraction": self.delivered_fraction,
                "show_snr": self.show_snr, "show_share": self.show_share,
                "deepest_showing_m": None if not np.isfinite(self.deepest_showing_m)
                else float(self.deepest_showing_m),
                "clear_sky_index": None if not np.isfinite(self.clear_sky_index)
                else round(float(self.clear_sky_index), 3),
                "rain_mm": round(float(self.rain_mm), 1)}


def clear_sky_index(forcing: Forcing, lat_deg: float, lon_deg: float) -> float:
    """Logged solar energy over the Haurwitz clear-sky energy of the record's daylight."""
    elev, _ = solar_position(lat_deg, lon_deg, forcing.time_s)
    clear = clear_sky_ghi(elev)
    day = clear > 50.0
    if day.sum() < 2:
        return float("nan")
    return float(np.trapezoid(forcing.solar_wm2[day], forcing.time_s[day])
                 / np.trapezoid(clear[day], forcing.time_s[day]))


def day_contrast(forcing: Forcing, soil: Soil, scan_time_s: np.ndarray, noise_k: float,
                 lat_deg: float, lon_deg: float,
                 depths_m: tuple[float, ...] = REFERENCE_DEPTHS_M,
                 show_snr: float = SHOW_SNR, show_share: float = SHOW_SCAN_SHARE,
                 canopy: float = 0.0) -> DayContrast:
    """The reference mine's peak contrast at ``depths_m`` over the scans (see the module).

    Parameters
    ----------
    forcing : Forcing
        The weather log's forcing.
    soil : Soil
        The site soil as the chain fitted it.
    scan_time_s : ndarray, shape (S,)
        Scan times, UTC epoch seconds.
    noise_k : float
        1-sigma noise of a measured contrast, K.
    lat_deg, lon_deg : float
        Site.
    show_snr, show_share : float
        The detector's cut in noise sigmas and its voting share of the scans.
    canopy : float
        Grass cover recorded for the site, 0-1: the mine lies under it
        (:mod:`clearfast_gis.thermal.canopy`); its contrast is seen times ``1 - canopy``.
    """
    curves = reference_curves(forcing, soil, scan_time_s, depths_m, canopy)
    peaks = [float(np.max(np.abs(c))) for c in curves]
    shares = [float(np.mean(DELIVERED_FRACTION * np.abs(c) >= show_snr * noise_k))
              for c in curves]
    dt_h = np.diff(forcing.time_s, prepend=forcing.time_s[0]) / 3600.0
    rain = float(np.sum(forcing.rain_mm_h * dt_h))
    return DayContrast(np.asarray(depths_m, float), np.asarray(peaks), np.asarray(shares),
                       float(noise_k),
                       clear_sky_index(forcing, lat_deg, lon_deg), rain,
                       DELIVERED_FRACTION, float(show_snr), float(show_share),
                       np.asarray(curves, float))


def reference_curves(forcing: Forcing, soil: Soil, scan_time_s: np.ndarray,
                     depths_m, canopy: float = 0.0) -> np.ndarray:
    """The reference mine's modelled contrast (axis minus undisturbed surface), K, float64
    (D, S): buried at each of the D ``depths_m`` (m, top of the mine), at each of the S
    ``scan_time_s`` (UTC epoch s); ``forcing``, ``soil`` and ``canopy`` as for
    :func:`day_contrast`."""
    model = ObjectModel(soil, under_canopy(forcing, canopy), scan_time_s, REFERENCE_RADIUS_M)
    seen = seen_share(canopy)
    return np.array([seen * (model.surface_at(
        BuriedObject(REFERENCE_RADIUS_M, REFERENCE_HEIGHT_M, d, MATERIALS["tnt"]), [0.0]
    )[:, 0] - model.background_k) for d in depths_m], dtype=np.float64)


def contrast_noise_k(inversions: dict, survey=None, clutter_k: float = float("nan")) -> float:
    """1-sigma noise of a measured contrast, K: the larger of the median residual rms of the
    anomalies' fits (registration and seams included) and the background clutter of the
    mosaics (``clutter_k``, :func:`clearfast_gis.detection.clutter.background_clutter_k`);
    without either, the camera's NETD from ``survey.json``, else 0.05 K."""
    rms = [inv.residual_rms_k for inv in inversions.values()
           if np.isfinite(inv.residual_rms_k)]
    found = [float(np.median(rms))] if rms else []
    if np.isfinite(clutter_k):
        found.append(float(clutter_k))
    if found:
        return max(found)
    if survey is not None:
        netd = survey.manifest.get("camera", {}).get("netd_k")
        if isinstance(netd, int | float) and netd > 0:
            return float(netd)
    return 0.05
