"""RTK-DGPS fixes to world positions: UTM zone, WGS84 <-> survey CRS, the platform track.

The track interpolates the antenna position linearly in time between usable fixes (GGA fix
quality 1-5; 6 dead reckoning, 7 manual and 8 simulator are not measurements), keeps the fix
quality of every epoch (4 = RTK fixed; anything else is degraded)
and refuses frame times that are too far from any usable fix.
"""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass
from typing import Protocol

import numpy as np
from pyproj import CRS, Transformer

from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey.nmea_lines import USABLE_FIX_QUALITIES
from clearfast_gis.timeutil import format_utc

#: GGA fix quality of an RTK fixed solution (anything else is degraded)
RTK_FIXED = 4


def _utm_zone_scalar(lat: float, lon: float) -> int:
    lon = ((lon + 180.0) % 360.0) - 180.0
    zone = int(np.floor((lon + 180.0) / 6.0)) % 60 + 1
    if 56.0 <= lat < 64.0 and 3.0 <= lon < 12.0:
        zone = 32  # south-west Norway
    elif 72.0 <= lat < 84.0 and 0.0 <= lon < 42.0:
        zone = (31, 33, 35, 37)[min(3, int((lon + 3.0) // 12.0))]  # Svalbard
    return zone


def utm_epsg_for(lat_deg: float, lon_deg: float) -> int:
    """EPSG code of the WGS84 UTM zone containing a point (326zz north, 327zz south).

    Follows the standard zone rules including the Norway (32V) and Svalbard (31X-37X)
    exceptions.

    Parameters
    ----------
    lat_deg, lon_deg : float
        WGS84 latitude in [-80, 84] and longitude in degrees.
    """
    lat, lon = float(lat_deg), float(lon_deg)
    if not (np.isfinite(lat) and np.isfinite(lon)) or not -80.0 <= lat <= 84.0:
        raise ValueError(f"no UTM zone for latitude {lat_deg}, longitude {lon_deg}")
    zone = _utm_zone_scalar(lat, lon)
    return (32600 if lat >= 0.0 else 32700) + zone


def survey_epsg(survey, gnss) -> int:
    """EPSG code of a survey's CRS: the one its manifest states, else the UTM zone of its
    first usable GNSS fix.

    Raises
    ------
    InvalidInput
        No CRS stated and no usable fix (naming the GNSS log).
    """
    crs = survey.manifest.get("crs") or {}
    if crs.get("epsg"):
        return int(crs["epsg"])
    ok = gnss.usable
    if not np.any(ok):
        raise InvalidInput("no GNSS fix to choose the UTM zone", survey.label("gnss"))
    i = int(np.flatnonzero(ok)[0])
    return utm_epsg_for(float(gnss.lat_deg[i]), float(gnss.lon_deg[i]))


@functools.lru_cache(maxsize=32)
def _transformer(src: int, dst: int) -> Transformer:
    return Transformer.from_crs(CRS.from_epsg(src), CRS.from_epsg(dst), always_xy=True)


def lonlat_to_crs(lon_deg: np.ndarray, lat_deg: np.ndarray,
                  epsg: int) -> tuple[np.ndarray, np.ndarray]:
    """WGS84 longitude/latitude (degrees) to (x, y) metres in EPSG ``epsg``."""
    x, y = _transformer(4326, int(epsg)).transform(np.asarray(lon_deg, dtype=float),
                                                    np.asarray(lat_deg, dtype=float))
    return np.asarray(x), np.asarray(y)


def crs_to_lonlat(x: np.ndarray, y: np.ndarray, epsg: int) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) metres in EPSG ``epsg`` to WGS84 longitude/latitude (degrees)."""
    lon, lat = _transformer(int(epsg), 4326).transform(np.asarray(x, dtype=float),
                                                       np.asarray(y, dtype=float))
    return np.asarray(lon), np.asarray(lat)


class GnssArrays(Protocol):
    """What :func:`platform_track` reads from a GNSS log (``clearfast_gis.survey.GnssLog``)."""

    time_s: np.ndarray
    lat_deg: np.ndarray
    lon_deg: np.ndarray
    alt_m: np.ndarray
    fix_quality: np.ndarray


@dataclass(frozen=True)
class PlatformTrack:
    """The GNSS antenna's world position over time.

    Attributes
    ----------
    time_s : float64 (N,)
        Epoch times of every GGA epoch, sorted (UTC epoch seconds).
    fix_quality : int (N,)
        GGA fix quality of every epoch.
    usable : bool (N,)
        Epochs with a fix (quality 1-5 and finite coordinates); only these are interpolated.
    position_m : float64 (N, 3)
        (E, N, z above ground) of every epoch, NaN where not usable.
    epsg : int
        CRS of E and N.
    max_gap_s : float
        A time farther than this from every usable fix has no position.
    source : str
        Name of the log in error messages.
    """

    time_s: np.ndarray
    fix_quality: np.ndarray
    usable: np.ndarray
    position_m: np.ndarray
    epsg: int
    max_gap_s: float = 5.0
    source: str = "gnss.nmea"

    @functools.cached_property
    def usable_time_s(self) -> np.ndarray:
        """Times of the usable epochs, shape (M,) (selected once: a frame's pose asks for
        one time at a time, and the selection over a day's 86,400 epochs cost more than the
        interpolation)."""
        return self.time_s[self.usable]

    @functools.cached_property
    def usable_position_m(self) -> np.ndarray:
        """Positions of the usable epochs, (M, 3) (selected once, as :attr:`usable_time_s`)."""
        return self.position_m[self.usable]

    def distance_to_fix_s(self, time_s: np.ndarray) -> np.ndarray:
        """Seconds from each time to the nearest usable fix (inf if there is none)."""
        return distance_to_nearest_s(self.usable_time_s, time_s)

    def covered(self, time_s: np.ndarray) -> np.ndarray:
        """True where a time is within ``max_gap_s`` of a usable fix."""
        return self.distance_to_fix_s(time_s) <= self.max_gap_s

    def gaps(self, min_gap_s: float | None = None) -> list[tuple[float, float]]:
        """Intervals (start_s, end_s) between consecutive usable fixes longer than
        ``min_gap_s`` (default ``max_gap_s``)."""
        limit = self.max_gap_s if min_gap_s is None else float(min_gap_s)
        tu = self.usable_time_s
        if tu.size < 2:
            return []
        dt = np.diff(tu)
        return [(float(tu[i]), float(tu[i + 1])) for i in np.flatnonzero(dt > limit)]

    def at(self, time_s: np.ndarray, strict: bool = True) -> np.ndarray:
        """Antenna world positions (N, 3) at ``time_s``, linear in time between usable fixes.

        Times up to ``max_gap_s`` before the first or after the last usable fix take that
        fix's position.

        Parameters
        ----------
        time_s : array_like (N,)
            UTC epoch seconds.
        strict : bool
            Raise :class:`InvalidInput` when a time is farther than ``max_gap_s`` from every
            usable fix; otherwise return NaN rows there.
        """
        t = np.atleast_1d(np.asarray(time_s, dtype=float))
        ok = self.covered(t)
        if strict and not np.all(ok):
            bad = t[~ok][0]
            when = format_utc(float(bad)) if np.isfinite(bad) else str(bad)
            raise InvalidInput(
                f"{int(np.count_nonzero(~ok))} time(s) farther than {self.max_gap_s:g} s from "
                f"any usable fix, first {when}", self.source, "fix_quality")
        tu = self.usable_time_s
        out = np.full((t.size, 3), np.nan)
        if tu.size == 0:
            return out
        pos = self.usable_position_m
        for k in range(3):
            out[:, k] = np.interp(t, tu, pos[:, k])
        out[~ok] = np.nan
        return out

    def fix_quality_at(self, time_s: np.ndarray) -> np.ndarray:
        """GGA fix quality of the epoch nearest each time (int, shape (N,))."""
        t = np.atleast_1d(np.asarray(time_s, dtype=float))
        i = np.clip(np.searchsorted(self.time_s, t), 1, max(self.time_s.size - 1, 1))
        left = np.abs(t - self.time_s[i - 1])
        right = np.abs(self.time_s[np.minimum(i, self.time_s.size - 1)] - t)
        idx = np.where(right < left, np.minimum(i, self.time_s.size - 1), i - 1)
        return self.fix_quality[idx].astype(int)

    def degraded_at(self, time_s: np.ndarray) -> np.ndarray:
        """True where the nearest epoch is not an RTK fixed solution."""
        return self.fix_quality_at(time_s) != RTK_FIXED


def platform_track(gnss_log: GnssArrays, epsg: int, ground_altitude_m: float,
                   max_gap_s: float = 5.0, source: str = "gnss.nmea") -> PlatformTrack:
    """The antenna track in the world frame from a GNSS log.

    Parameters
    ----------
    gnss_log : GnssLog
        Arrays ``time_s, lat_deg, lon_deg, alt_m, fix_quality`` (N,).
    epsg : int
        Survey CRS (projected, metres).
    ground_altitude_m : float
        Altitude of the ground plane on the GGA datum (MSL), metres; z = alt - ground.
    max_gap_s : float
        Largest distance in time to a usable fix for which a position is given.
    source : str
        Name of the log in error messages.

    Raises
    ------
    InvalidInput
        When the log has no epoch or no usable fix.
    """
    t = np.asarray(gnss_log.time_s, dtype=float).reshape(-1)
    n = t.size
    arrays = {}
    for name in ("lat_deg", "lon_deg", "alt_m", "fix_quality"):
        a = np.asarray(getattr(gnss_log, name)).reshape(-1)
        if a.size != n:
            raise InvalidInput(f"{name} has {a.size} values for {n} epochs", source, name)
        arrays[name] = a
    if n == 0:
        raise InvalidInput("no GGA epoch", source)
    order = np.argsort(t, kind="stable")
    t = t[order]
    lat = arrays["lat_deg"][order].astype(float)
    lon = arrays["lon_deg"][order].astype(float)
    alt = arrays["alt_m"][order].astype(float)
    quality = arrays["fix_quality"][order].astype(int)
    usable = np.isin(quality, USABLE_FIX_QUALITIES) & np.isfinite(lat) & np.isfinite(lon) \
        & np.isfinite(alt) & np.isfinite(t)
    if not np.any(usable):
        raise InvalidInput("no usable fix (no epoch has fix quality 1-5)", source,
                           "fix_quality")
    # keep one epoch per time (a repeated timestamp would break interpolation)
    dup = np.zeros(n, dtype=bool)
    tu_idx = np.flatnonzero(usable)
    dup[tu_idx[1:][np.diff(t[tu_idx]) <= 0.0]] = True
    usable &= ~dup
    pos = np.full((n, 3), np.nan)
    x, y = lonlat_to_crs(lon[usable], lat[usable], epsg)
    pos[usable, 0] = x
    pos[usable, 1] = y
    pos[usable, 2] = alt[usable] - float(ground_altitude_m)
    return PlatformTrack(t, quality, usable, pos, int(epsg), float(max_gap_s), source)


#: losses of fix the smoothed track of a quasi-static platform bridges, seconds
STATIC_BRIDGE_S = 600.0


def distance_to_nearest_s(sorted_times_s: np.ndarray, time_s: np.ndarray) -> np.ndarray:
    """Seconds from each of ``time_s`` to the nearest of ``sorted_times_s`` (increasing; inf
    when it is empty)."""
    t = np.atleast_1d(np.asarray(time_s, dtype=float))
    tu = np.asarray(sorted_times_s, dtype=float)
    if tu.size == 0:
        return np.full(t.shape, np.inf)
    i = np.clip(np.searchsorted(tu, t), 1, max(tu.size - 1, 1))
    left = np.abs(t - tu[i - 1])
    right = np.abs(tu[np.minimum(i, tu.size - 1)] - t)
    return np.minimum(left, right)


FIX_SIGMA_M: dict[int, float] = {4: 0.02, 5: 0.30, 2: 0.8, 1: 2.0}
"""Typical 1-sigma horizontal position noise per GGA fix quality, metres (RTK fixed,
RTK float, DGPS, autonomous); other usable qualities (3, PPS) count as autonomous."""


def smooth_static_track(track: PlatformTrack, window_s: float = 600.0,
                        max_gap_s: float = STATIC_BRIDGE_S) -> PlatformTrack:
    """Smooth the track of a quasi-static platform (a parked boom lift).

    Each usable epoch's position is replaced by a local linear fit in time over the usable
    epochs within ``window_s`` of it, weighted by ``1 / sigma^2`` of their fix quality
    (:data:`FIX_SIGMA_M`). RTK-fixed epochs then dominate wherever they exist, RTK-float noise
    (decimetres) averages down where they do not, and a slow drift (a sinking lift) is still
    followed. Short losses of fix are bridged up to ``max_gap_s``.

    Parameters
    ----------
    track : PlatformTrack
    window_s : float
        Half-width of the fitting window, seconds.
    max_gap_s : float
        Largest distance in time to a usable fix for which the smoothed track gives a
        position, seconds.

    Returns
    -------
    PlatformTrack
        Same epochs and qualities, smoothed positions.
    """
    idx = np.flatnonzero(track.usable)
    if idx.size == 0:
        return track
    t = track.time_s[idx]
    q = track.fix_quality[idx]
    sigma = np.array([FIX_SIGMA_M.get(int(v), FIX_SIGMA_M[1]) for v in q])
    w = 1.0 / sigma**2
    tc = t - t.mean()
    lo = np.searchsorted(t, t - window_s, side="left")
    hi = np.searchsorted(t, t + window_s, side="right")

    def window_sum(v: np.ndarray) -> np.ndarray:
        c = np.concatenate([[0.0], np.cumsum(v)])
        return c[hi] - c[lo]

    s0, s1, s2 = window_sum(w), window_sum(w * tc), window_sum(w * tc * tc)
    det = s0 * s2 - s1 * s1
    pos = track.position_m.copy()
    for k in range(3):
        x = track.position_m[idx, k]
        x0 = x.mean()
        b0, b1 = window_sum(w * (x - x0)), window_sum(w * tc * (x - x0))
        with np.errstate(invalid="ignore", divide="ignore"):
            slope = np.where(det > 1e-12 * s0 * s0 * window_s**2, (s0 * b1 - s1 * b0) / det,
                             0.0)
        mean = b0 / s0
        tbar = s1 / s0
        pos[idx, k] = x0 + mean + slope * (tc - tbar)
    return dataclasses.replace(track, position_m=pos, max_gap_s=float(max_gap_s))


def survey_markers(markers, epsg: int) -> tuple[list[str], np.ndarray]:
    """Surveyed markers (``Markers`` or None) in the survey CRS: ids and (M, 2) positions."""
    if markers is None:
        return [], np.zeros((0, 2))
    m = markers
    x, y = lonlat_to_crs(np.asarray(m.lon_deg, float), np.asarray(m.lat_deg, float), epsg)
    return [str(i) for i in m.id], np.column_stack([x, y])


def fix_quality_summary(track: PlatformTrack, time_s: np.ndarray) -> dict:
    """The GNSS fix quality at the frames' times ``time_s`` (UTC epoch s): counts per quality,
    the RTK-fixed share, the worst, and whether any frame was taken without an RTK fix
    (``products.json`` ``fix_quality``)."""
    t = time_s
    q = track.fix_quality_at(t)
    values, counts = np.unique(q, return_counts=True)
    return {"counts_at_frames": {str(int(v)): int(c) for v, c in zip(values, counts,
                                                                        strict=True)},
            "rtk_fixed_share": float(np.mean(q == 4)) if q.size else 0.0,
            "worst_during_frames": int(q.min()) if q.size else None,
            "degraded": bool(np.any(q != 4))}
