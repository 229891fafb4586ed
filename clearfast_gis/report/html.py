"""``report.html``: what was surveyed, what was found, how much to trust it."""

from __future__ import annotations

import html
import math
from dataclasses import dataclass, field
from pathlib import Path

from clearfast_gis import __version__
from clearfast_gis.atomic import write_bytes, write_text
from clearfast_gis.timeutil import format_utc

CREDIT = ("Processing: clearfast-gis {version}. Method: CLEARFAST stand-off thermal-IR survey "
          "(morphological anomaly detection on the diurnal sequence, thermal-model inversion).")

TABLE_COLUMNS = [
    ("priority", "Priority", "{}"), ("p_mine", "p_mine", "{:.2f}"),
    ("anomaly_id", "ID", "{}"), ("x", "X (m)", "{:.2f}"), ("y", "Y (m)", "{:.2f}"),
    ("area_m2", "Area (m²)", "{:.4f}"), ("diameter_m", "Diameter (m)", "{:.3f}"),
    ("depth_m", "Depth (cm)", "cm"), ("diffusivity_m2s", "Diffusivity (mm²/s)", "mm2s"),
    ("circularity", "Circularity", "{:.3f}"), ("polarity", "Polarity", "{}"),
    ("status", "Status", "{}"), ("class_cue", "Class cue", "{}"),
    ("cue_confidence", "Cue confidence", "{:.2f}"), ("n_scans", "Scans", "{}"),
]


@dataclass
class ReportData:
    """Everything the report shows.

    Attributes
    ----------
    survey_id, site_name : str
    epsg : int
        Survey CRS.
    start_s, end_s : float
        Survey time span (UTC epoch seconds).
    suspects : list of dict
        One record per suspect with the ``anomalies.gpkg`` suspects fields, in priority order.
    overview_png : bytes
        The Fig. 7-like panel (day mosaic, detections, night mosaic).
    curves_png : dict[str, bytes]
        Contrast-curve figure per anomaly id.
    facts : list of (str, str)
        Survey and processing facts (frames, scans, GNSS quality, residuals, ...).
    warnings : list of str
        Things a user must know (degraded RTK, gaps, failed registrations).
    timings_s : dict[str, float]
        Wall time per stage.
    parameters : dict
        Processing parameters.
    candidates : list of dict
        Detections set aside (``set_aside_reason``), the ``candidates`` layer.
    operating_curve : dict
        Expected operating curve of the ranked list (``products.json``).
    operating_png : bytes
        Its figure.
    """

    survey_id: str
    site_name: str
    epsg: int
    start_s: float
    end_s: float
    suspects: list[dict]
    overview_png: bytes
    curves_png: dict[str, bytes] = field(default_factory=dict)
    facts: list[tuple[str, str]] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    timings_s: dict[str, float] = field(default_factory=dict)
    parameters: dict = field(default_factory=dict)
    candidates: list[dict] = field(default_factory=list)
    operating_curve: dict = field(default_factory=dict)
    operating_png: bytes = b""


def figure_name(anomaly_id: str) -> str:
    """Relative path of an anomaly's contrast-curve figure inside the products folder."""
    return f"figures/contrast_{anomaly_id}.png"


UNCONSTRAINED_TEXT = "unconstrained"
"""What the report and the QGIS form show for a diffusivity whose 1-sigma exceeds its value."""


def diffusivity_text(alpha_m2s: float, sigma_m2s: float | None = None) -> str:
    """A diffusivity (m²/s) as a planner reads it: in mm²/s, two significant digits, with its
    1-sigma when it is known (as the QGIS form shows it); no unit in the text. A value whose
    1-sigma is larger than itself (:data:`UNCONSTRAINED_TEXT`: the curve did not constrain it,
    often the end of the model's table) is not printed as a number.

    >>> diffusivity_text(1.47e-7, 3.1e-8)
    '0.15 ± 0.031'
    >>> diffusivity_text(3.2e-5, 1.2e-3)
    'unconstrained'
    """
    has_sigma = isinstance(sigma_m2s, float) and math.isfinite(sigma_m2s)
    if has_sigma and sigma_m2s > alpha_m2s:
        return UNCONSTRAINED_TEXT
    txt = f"{1e6 * alpha_m2s:#.2g}".rstrip(".")
    if has_sigma:
        txt += f" ± {1e6 * sigma_m2s:#.2g}".rstrip(".")
    return txt


def _cell(rec: dict, key: str, fmt: str) -> str:
    v = rec.get(key)
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "–"
    if fmt == "cm":
        s = rec.get("depth_sigma_m")
        txt = f"{100 * v:.1f}"
        if isinstance(s, float) and math.isfinite(s):
            txt += f" ± {100 * s:.1f}"
        return txt
    if fmt == "mm2s":
        return diffusivity_text(v, rec.get("diffusivity_sigma_m2s"))
    return html.escape(fmt.format(v))


def render_html(data: ReportData) -> str:
    """The report page as HTML text (figures referenced relatively)."""
    esc = html.escape
    rows = []
    for rec in data.suspects:
        cells = "".join(f"<td>{_cell(rec, k, f)}</td>" for k, _, f in TABLE_COLUMNS)
        fig = figure_name(str(rec["anomaly_id"]))
        rows.append(f"<tr>{cells}<td><a href='{fig}'>curve</a></td></tr>")
    head = "".join(f"<th>{esc(t)}</th>" for _, t, _ in TABLE_COLUMNS) + "<th>Figure</th>"
    facts = "".join(f"<tr><th>{esc(k)}</th><td>{esc(v)}</td></tr>" for k, v in data.facts)
    warns = "".join(f"<li>{esc(w)}</li>" for w in data.warnings) or "<li>none</li>"
    timing = "".join(f"<tr><th>{esc(k)}</th><td>{v:.1f} s</td></tr>"
                     for k, v in data.timings_s.items())
    params = "".join(f"<tr><th>{esc(str(k))}</th><td>{esc(str(v))}</td></tr>"
                     for k, v in data.parameters.items())
    curves = "".join(
        f"<figure><img src='{figure_name(a)}' alt='contrast {esc(a)}'>"
        f"<figcaption>{esc(a)}</figcaption></figure>" for a in data.curves_png)
    n_mine = sum(1 for r in data.suspects if r.get("class_cue") in ("at_mine", "ap_mine"))
    expected = sum(float(r.get("p_mine") or 0.0) for r in data.suspects)
    aside: dict[str, int] = {}
    for r in data.candidates:
        why = str(r.get("set_aside_reason", "")).split(",")[0].split(" ", 1)[0]
        aside[why] = aside.get(why, 0) + 1
    aside_txt = ", ".join(f"{n} {k}" for k, n in sorted(aside.items())) or "none"
    # a dull day is said where the map is read, not only among the warnings at the bottom
    said = [w.removeprefix("low thermal contrast: ") for w in data.warnings
            if w.startswith("low thermal contrast")]
    dull = "".join(f"<p class='note'><b>Low thermal contrast.</b> {esc(t[:1].upper() + t[1:])}"
                   "</p>" for t in said)
    curve_img = ("<img src='figures/operating_curve.png' alt='operating curve'>"
                 if data.operating_png else "")
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>CLEARFAST survey {esc(data.survey_id)}</title>
<style>
body {{ font-family: sans-serif; margin: 2em; max-width: 1400px; }}
table {{ border-collapse: collapse; font-size: 0.85em; }}
th, td {{ border: 1px solid #bbb; padding: 3px 6px; text-align: left; }}
.wide {{ overflow-x: auto; }}
table.suspects td {{ white-space: nowrap; text-align: right; }}
th {{ background: #eee; }}
figure {{ display: inline-block; margin: 0.5em; }}
.note {{ background: #fff4e0; border-left: 4px solid #e67e22; padding: 0.5em 1em; }}
</style></head><body>
<h1>Stand-off thermal-IR survey {esc(data.survey_id)}</h1>
<p>{esc(data.site_name)} · {esc(format_utc(data.start_s, 'minutes'))} to
{esc(format_utc(data.end_s, 'minutes'))} UTC · CRS EPSG:{data.epsg}</p>
<p class="note">Every suspect below is an <b>indication</b> from indirect (thermal) evidence,
never a confirmed hazard: {len(data.suspects)} suspects ({n_mine} cued as mines; about
{expected:.1f} mines expected from their p_mine), ranked by mine likelihood.
{len(data.candidates)} further detections cannot be mines and are set aside in the
<code>candidates</code> layer (by blob, footprint or scans: {esc(aside_txt)}).</p>
{dull}
<h2>Mosaics and detections</h2>
<img src="figures/overview.png" alt="mosaics and detections" style="max-width:100%">
<h2>Operating curve</h2>
<p>Clearing the suspects in priority order: expected mines found against expected false
alarms per m² (from the calibrated p_mine; docs/likelihood.md).</p>
{curve_img}
<h2>Suspects in priority order</h2>
<div class="wide"><table class="suspects"><tr>{head}</tr>{''.join(rows)}</table></div>
<h2>Warnings</h2><ul>{warns}</ul>
<h2>Survey and processing</h2><table>{facts}</table>
<h2>Parameters</h2><table>{params}</table>
<h2>Stage timings</h2><table>{timing}</table>
<h2>Contrast curves</h2>{curves}
<p><small>{esc(CREDIT.format(version=__version__))}</small></p>
</body></html>
"""


def write_report(folder: str | Path, data: ReportData) -> Path:
    """Write ``report.html`` and its figures into ``folder`` (atomically, file by file)."""
    folder = Path(folder)
    write_bytes(folder / "figures" / "overview.png", data.overview_png)
    if data.operating_png:
        write_bytes(folder / "figures" / "operating_curve.png", data.operating_png)
    for aid, png in data.curves_png.items():
        write_bytes(folder / figure_name(aid), png)
    return write_text(folder / "report.html", render_html(data))
