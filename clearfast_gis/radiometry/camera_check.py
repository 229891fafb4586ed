"""A radiometric camera checked against the survey's blackbodies, calibration event by event.

With a self-calibrated camera (``camera.radiometry``) the blackbody frames are not needed to
calibrate; when they exist they check the camera: at each event the camera's own at-sensor
temperature of each blackbody (median over the central half of the mean blackbody image)
against the blackbody log, and the gain and offset that would map the camera onto the log,
the offset taken at the ambient blackbody 2 (``T_log = T2_camera + offset + gain * (T_camera -
T2_camera)``, kelvin): referred to 0 K instead, a 10 K blackbody span would multiply a few
millikelvin of camera noise into tenths of a kelvin of offset. ``products.json`` records them
(``camera_check``); the chain does not apply them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from clearfast_gis.radiometry.calibration import blackbody_temperature_at
from clearfast_gis.timeutil import format_utc
from clearfast_gis.units import ZERO_CELSIUS_K, c_to_k

if TYPE_CHECKING:
    from clearfast_gis.survey import Survey


def central_median(image: np.ndarray) -> float:
    """Median of the central half (rows and columns) of an (H, W) image."""
    h, w = image.shape
    return float(np.nanmedian(image[h // 4: h - h // 4, w // 4: w - w // 4]))


def camera_blackbody_check(survey: Survey) -> list[dict]:
    """Per calibration event and band: blackbody log vs the camera's own temperature.

    Returns
    -------
    list of dict
        ``event, band, time_utc, bb1_log_c, bb1_camera_c, bb2_log_c, bb2_camera_c`` (degrees
        C, 3 decimals), ``gain`` (dimensionless, blackbody span of the log over the camera's)
        and ``offset_k`` (kelvin, log minus camera at blackbody 2); empty for a survey
        without camera radiometry or without blackbody files.
    """
    from clearfast_gis.survey import read_blackbody_frames, read_blackbody_log

    files = survey.manifest["files"]
    if survey.radiometry is None or "blackbody_frames" not in files \
            or "blackbody_log" not in files:
        return []
    label = survey.label("blackbody_log")
    log = read_blackbody_log(survey.path("blackbody_log"), label)
    out = []
    for e in read_blackbody_frames(survey):
        t_log = [float(blackbody_temperature_at(log.time_s, c_to_k(temps), when, source=label))
                 for temps, when in ((log.bb1_c, e.bb1_time_s), (log.bb2_c, e.bb2_time_s))]
        t_cam = [central_median(survey.radiometry.sensor_temperature_k(img))
                 for img in (e.bb1_mean, e.bb2_mean)]
        gain = (t_log[0] - t_log[1]) / (t_cam[0] - t_cam[1]) \
            if abs(t_cam[0] - t_cam[1]) > 1e-6 else float("nan")
        offset = t_log[1] - t_cam[1]
        out.append({"event": int(e.event), "band": int(e.band),
                    "time_utc": format_utc(e.time_s, "seconds"),
                    "bb1_log_c": round(t_log[0] - ZERO_CELSIUS_K, 3),
                    "bb1_camera_c": round(t_cam[0] - ZERO_CELSIUS_K, 3),
                    "bb2_log_c": round(t_log[1] - ZERO_CELSIUS_K, 3),
                    "bb2_camera_c": round(t_cam[1] - ZERO_CELSIUS_K, 3),
                    "gain": round(gain, 5) if np.isfinite(gain) else None,
                    "offset_k": round(offset, 3) if np.isfinite(offset) else None})
    return out
