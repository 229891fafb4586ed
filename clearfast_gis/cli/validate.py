"""``clearfast validate SURVEY``: check a survey folder completely.

Prints every problem as ``file: field: problem`` (warnings prefixed ``warning:``), then a
summary. Exit status 0 when valid (warnings allowed), 1 when invalid, 2 for usage errors.
"""

from __future__ import annotations

import json

import click

from clearfast_gis.cli.options import station_profile_opt, survey_arg


def _summary_lines(summary: dict) -> list[str]:
    s = summary
    out = [f"survey:      {s.get('survey_id')}"]
    if "frames" in s:
        out.append(f"frames:      {s['frames']} ({s.get('scans', 0)} scans x "
                   f"{s.get('positions', 0)} positions x {len(s.get('bands', []))} bands; "
                   f"{s.get('missing_frames', 0)} missing of {s.get('frames_expected', 0)})")
    out.append(f"bands:       {', '.join(str(b) for b in s.get('bands', [])) or '-'}")
    if "time_start_utc" in s:
        out.append(f"time span:   {s['time_start_utc']} to {s['time_end_utc']} (UTC)")
    if "gnss_epochs" in s:
        counts = ", ".join(f"q{k}: {v}" for k, v in s.get("fix_quality_counts", {}).items())
        out.append(f"gnss:        {s['gnss_epochs']} epochs, RTK fixed "
                   f"{100.0 * s.get('rtk_fixed_share', 0.0):.1f}% ({counts}); "
                   f"{len(s.get('gnss_gaps', []))} gap(s)")
    if "weather_records" in s:
        out.append(f"weather:     {s['weather_records']} records; "
                   f"{len(s.get('weather_gaps', []))} gap(s)")
        cols = s.get("weather_columns") or {}
        if cols:
            out.append("  columns:   " + ", ".join(f"{q} <- {c}" for q, c in cols.items()))
    if "calibration_events" in s:
        out.append(f"calibration: {s['calibration_events']} blackbody event(s)")
    if "markers" in s:
        out.append(f"markers:     {s['markers']}")
    return out


@click.command("validate")
@survey_arg
@click.option("--json", "as_json", is_flag=True, help="Print the report as one JSON object.")
@click.option("--gnss-gap", "gnss_gap_s", type=click.FloatRange(min=0.0, min_open=True),
              default=10.0, show_default=True, help="Report GNSS gaps longer than this (s).")
@click.option("--weather-gap", "weather_gap_s", type=click.FloatRange(min=0.0, min_open=True),
              default=180.0, show_default=True, help="Report weather gaps longer than this (s).")
@station_profile_opt
@click.pass_context
def command(ctx: click.Context, survey: str, as_json: bool, gnss_gap_s: float,
            weather_gap_s: float, station_profile: str | None) -> None:
    """Check the survey folder SURVEY completely: schema, files, tables, logs, time coverage."""
    from clearfast_gis.survey.validate import validate_survey

    report = validate_survey(survey, gnss_gap_s=gnss_gap_s, weather_gap_s=weather_gap_s,
                             station_profile=station_profile)
    if as_json:
        click.echo(json.dumps(report.to_dict(), indent=2))
    else:
        for p in report.problems:
            click.echo(p.line())
        for w in report.warnings:
            click.echo(f"warning: {w.line()}")
        if report.problems or report.warnings:
            click.echo("")
        for line in _summary_lines(report.summary):
            click.echo(line)
        click.echo(f"result:      {'valid' if report.valid else 'INVALID'} "
                   f"({len(report.problems)} problem(s), {len(report.warnings)} warning(s))")
    ctx.exit(0 if report.valid else 1)
