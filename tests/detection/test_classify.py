"""Class cues and confidence."""

import numpy as np
import pytest

from clearfast_gis.detection import CLASSES, AnomalyFeatures, classify, diffusivity_cue


def _feat(diameter_m, circularity=0.9, polarity="warm_day_cool_night", score=10.0, n=12):
    pol = np.ones(n, np.int8)
    return AnomalyFeatures(
        id=1, row=0.0, col=0.0, x=np.nan, y=np.nan, area_px=100, area_m2=np.nan,
        diameter_px=11.3, diameter_m=diameter_m, circularity=circularity, axis_ratio=0.9,
        compactness=0.9, polarity_per_scan=pol, polarity=polarity, n_scans=n,
        centre_k=np.zeros(n), ring_k=np.zeros(n), contrast_k=np.zeros(n),
        noise_k=np.zeros(n), score=score,
    )


@pytest.mark.parametrize("diameter, expected", [
    (0.337 * 0.9, "at_mine"), (0.104, "ap_mine"), (0.14, "ap_mine"), (0.6, "unknown"),
    (0.02, "unknown"), (np.nan, "unknown"),
])
def test_size_rules(diameter, expected):
    cue, conf = classify(_feat(diameter))
    assert cue == expected and 0.0 <= conf <= 1.0


def test_clutter_rules():
    assert classify(_feat(0.3, circularity=0.4))[0] == "clutter"
    assert classify(_feat(0.3, polarity="mixed"))[0] == "clutter"
    assert classify(_feat(0.1), {"diffusivity_m2s": 1.3e-6})[0] == "clutter"  # stone
    assert classify(_feat(0.1), {"diffusivity_m2s": 1.2e-5})[0] == "clutter"  # steel


def test_diffusivity_raises_and_lowers_confidence():
    base = classify(_feat(0.104))[1]
    tnt = classify(_feat(0.104), {"diffusivity_m2s": 1.0e-7, "characterised": True})
    soil = classify(_feat(0.104), {"diffusivity_m2s": 6e-7})
    not_char = classify(_feat(0.104), {"diffusivity_m2s": 1.3e-6, "characterised": False})
    assert tnt[0] == "ap_mine" and tnt[1] > base > soil[1]
    assert not_char == ("ap_mine", base)  # an uncharacterised fit is ignored


def test_confidence_orders_by_evidence():
    strong = classify(_feat(0.3, score=20))[1]
    weak = classify(_feat(0.3, score=1))[1]
    steady = classify(_feat(0.3, polarity="warm"))[1]
    assert strong > weak and classify(_feat(0.3))[1] > steady
    assert set(CLASSES) == {"at_mine", "ap_mine", "clutter", "unknown"}
    assert [diffusivity_cue(a) for a in (1e-7, 6e-7, 2e-6)] == ["mine", "soil", "stone_metal"]


def test_cool_by_day_is_clutter_and_weak_is_unknown():
    # a 10 cm blob cool around midday: a stone or low-emissivity metal, not a mine
    assert classify(_feat(0.104), contrast_day_k=-0.8)[0] == "clutter"
    assert classify(_feat(0.104), contrast_day_k=+0.8)[0] == "ap_mine"
    # at noise level (score below the threshold) nothing is cued as a mine or as clutter
    assert classify(_feat(0.104, score=0.5))[0] == "unknown"
    assert classify(_feat(0.3, circularity=0.4, score=0.5))[0] == "unknown"
    assert classify(_feat(0.104, score=0.5), contrast_day_k=-0.8)[0] == "unknown"
