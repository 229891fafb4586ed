"""The suspects table of report.html: values in the units a planner reads."""

from __future__ import annotations

import math

import pytest

from clearfast_gis.report.html import TABLE_COLUMNS, _cell


def _fmt(key: str) -> str:
    return next(f for k, _, f in TABLE_COLUMNS if k == key)


@pytest.mark.parametrize(("alpha", "sigma", "text"), [
    (1.47e-7, 3.1e-8, "0.15 ± 0.031"),
    (1.0e-7, 1.0e-8, "0.10 ± 0.010"),
    (1.23e-5, 4.0e-6, "12 ± 4.0"),
    (9.8e-8, math.nan, "0.098"),
    (3.16e-8, None, "0.032"),
    (3.2e-5, 1.2e-3, "unconstrained"),  # 1-sigma larger than the value: not a number to read
    (2.0e-7, 2.0e-7, "0.20 ± 0.20"),
])
def test_diffusivity_in_mm2_per_s_with_two_significant_digits(alpha, sigma, text):
    rec = {"diffusivity_m2s": alpha, "diffusivity_sigma_m2s": sigma}
    assert _cell(rec, "diffusivity_m2s", _fmt("diffusivity_m2s")) == text


def test_depth_in_cm_with_its_sigma_and_missing_values_as_a_dash():
    assert _cell({"depth_m": 0.0234, "depth_sigma_m": 0.0071}, "depth_m", _fmt("depth_m")) \
        == "2.3 ± 0.7"
    assert _cell({"depth_m": math.nan}, "depth_m", _fmt("depth_m")) == "–"
    assert _cell({}, "diffusivity_m2s", _fmt("diffusivity_m2s")) == "–"


def test_column_headers_name_their_units():
    heads = {k: t for k, t, _ in TABLE_COLUMNS}
    assert heads["diffusivity_m2s"] == "Diffusivity (mm²/s)"
    assert heads["depth_m"] == "Depth (cm)"


def test_only_the_suspects_table_keeps_its_cells_on_one_line():
    """The long facts (the day's contrast, ...) wrap in their column; the suspects' values
    stay on one line in a table that scrolls sideways on a narrow screen."""
    import re

    from clearfast_gis.report.html import ReportData, render_html

    long_fact = "modelled peak 1.37 K at 1 cm, " * 8
    page = render_html(ReportData("S1", "site", 32636, 0.0, 3600.0,
                                  [{"priority": 1, "anomaly_id": "S1-0001"}], b"",
                                  facts=[("thermal contrast of the day", long_fact)]))
    style = page[page.index("<style>"):page.index("</style>")]
    assert re.findall(r"([^\n{}]*)\{[^}]*white-space: nowrap", style) == ["table.suspects td "]
    assert '<div class="wide"><table class="suspects">' in page
    assert "<table><tr><th>thermal contrast of the day</th>" in page
