"""The suspects layer: schema validation, derived lat/lon, contrast series."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st
from pyproj import Transformer

from clearfast_gis.errors import InvalidInput
from clearfast_gis.export import (
    SUSPECT_COLUMNS,
    contrast_series_text,
    parse_contrast_series,
    suspects_frame,
)


def record(**over):
    rec = {"anomaly_id": "A001", "x": 532786.0, "y": 3891961.0, "area_m2": 0.09,
           "diameter_m": 0.34, "circularity": 0.9, "depth_m": 0.01, "depth_sigma_m": 0.005,
           "diffusivity_m2s": 1.0e-7, "status": "ok", "polarity": "hot",
           "class_cue": "at_mine", "cue_confidence": 0.9, "n_scans": 49}
    rec.update(over)
    return rec


def test_frame_columns_types_and_lonlat():
    series = {"time_utc": ["2026-11-15T00:00:00Z", "2026-11-15T12:00:00Z"],
              "contrast_k": [-0.4, 1.2]}
    frame = suspects_frame([record(contrast_series=series, score=3.5),
                            record(anomaly_id="A002", depth_m=None, depth_sigma_m=None,
                                   diffusivity_m2s=None, status="not_characterised",
                                   fix_quality=5)], 32636)
    assert list(frame.columns) == [*SUSPECT_COLUMNS, "score", "geometry"]
    assert frame.crs.to_epsg() == 32636
    assert frame.geometry.x.tolist() == [532786.0, 532786.0]
    lon, lat = Transformer.from_crs(32636, 4326, always_xy=True).transform(532786.0, 3891961.0)
    assert frame["lat"].iloc[0] == pytest.approx(lat, abs=1e-12)
    assert frame["lon"].iloc[0] == pytest.approx(lon, abs=1e-12)
    assert 35.16 < lat < 35.18 and 33.35 < lon < 33.37
    assert math.isnan(frame["depth_m"].iloc[1])
    assert str(frame["fix_quality"].dtype) == "Int64" and frame["fix_quality"].iloc[1] == 5
    assert frame["n_scans"].dtype == np.int64
    assert json.loads(frame["contrast_series"].iloc[0]) == series


@pytest.mark.parametrize(("over", "field", "text"), [
    ({"class_cue": "mine"}, "suspects[0].class_cue", "at_mine, ap_mine, clutter, unknown"),
    ({"depth_m": -0.1}, "suspects[0].depth_m", "burial depth >= 0"),
    ({"n_scans": 2.5}, "suspects[0].n_scans", "an integer"),
    ({"status": "maybe"}, "suspects[0].status", "weak_contrast"),
    ({"figure": "/abs/path.png"}, "suspects[0].figure", "relative path"),
    ({"contrast_series": "[1, 2]"}, "suspects[0].contrast_series", "equal length"),
])
def test_invalid_attribute_names_field(over, field, text):
    with pytest.raises(InvalidInput) as err:
        suspects_frame([record(**over)], 32636)
    assert err.value.field == field and text in err.value.message


def test_missing_and_repeated():
    rec = record()
    del rec["depth_m"]
    with pytest.raises(InvalidInput) as err:
        suspects_frame([rec], 32636, path="anomalies.gpkg")
    assert err.value.one_line() == "anomalies.gpkg: suspects[0].depth_m: missing"
    with pytest.raises(InvalidInput, match="repeated anomaly_id"):
        suspects_frame([record(), record()], 32636)


@given(st.lists(st.tuples(st.datetimes().map(lambda d: d.isoformat() + "Z"),
                          st.floats(-50, 50, allow_nan=False)), max_size=60))
@example([("2000-01-01T00:00:00Z", 0.0025)])
def test_contrast_series_round_trip(pairs):
    times = [t for t, _ in pairs]
    values = np.array([c for _, c in pairs])
    back_t, back_c = parse_contrast_series(contrast_series_text(times, values))
    assert back_t == times
    # rounded to 1 mK as Python rounds the double (0.0025 -> 0.003: the double is a hair
    # above 0.0025), not as np.round's scale-round-unscale does (-> 0.002)
    np.testing.assert_array_equal(back_c, [round(float(c), 3) for c in values])


def test_contrast_series_nan_is_null():
    text = contrast_series_text(["a", "b"], [1.0, float("nan")])
    assert json.loads(text)["contrast_k"] == [1.0, None]
    assert np.isnan(parse_contrast_series(text)[1][1])
