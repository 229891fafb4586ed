"""`clearfast validate` / `process` with a real station's own column names and units: the
profile by option or named in survey.json, one error without it; survey.json gnss.checksums."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from clearfast_gis.cli.main import cli
from clearfast_gis.survey import read_survey, read_toa5, validate_survey
from clearfast_gis.survey.testing import make_minimal_survey

PROFILE = {"format": "clearfast-station-profile", "format_version": 1, "name": "test station",
           "columns": {"air_temp_c": {"column": "AirTemp_F", "unit": "deg F"},
                       "wind_ms": {"column": "Wind_kn", "unit": "knots"}}}


def station_survey(root: Path) -> Path:
    """A minimal survey whose weather.dat is a station's own table: deg F, knots, mbar and
    names that are no standard program's (air temperature and wind)."""
    make_minimal_survey(root)
    lines = (root / "weather.dat").read_bytes().decode().split("\r\n")
    names = lines[1].replace('"AirTC_Avg"', '"AirTemp_F"').replace('"WS_ms_Avg"', '"Wind_kn"')
    names = names.replace('"BP_hPa_Avg"', '"BP_mbar_Avg"')
    units = lines[2].replace('"Deg C"', '"Deg F"').replace('"meters/second"', '"knots"')
    out = [lines[0], names, units, lines[3]]
    for line in lines[4:]:
        if not line:
            continue
        f = line.split(",")
        f[2] = f"{float(f[2]) * 1.8 + 32.0:.4f}"  # AirTC_Avg deg C -> deg F
        f[5] = f"{float(f[5]) / (1852.0 / 3600.0):.6f}"  # WS_ms_Avg m/s -> knots
        out.append(",".join(f))
    (root / "weather.dat").write_text("\r\n".join(out) + "\r\n")
    return root


def run(capsys, *args) -> tuple[int, str]:
    with pytest.raises(SystemExit) as e:
        cli(list(map(str, args)))
    out, err = capsys.readouterr()
    return e.value.code, out + err


def test_validate_without_then_with_the_profile(tmp_path, capsys):
    survey = station_survey(tmp_path / "s")
    code, out = run(capsys, "validate", survey)
    assert code == 1
    problem = next(line for line in out.splitlines() if line.startswith("weather.dat"))
    assert problem.startswith("weather.dat: line 2: missing air temperature (air_temp_c, e.g. "
                              "AirTC_Avg), wind speed (wind_ms, e.g. WS_ms_Avg); the file has "
                              "columns TIMESTAMP, RECORD, AirTemp_F, RH_Avg, BP_mbar_Avg, "
                              "Wind_kn")
    prof = tmp_path / "station.json"
    prof.write_text(json.dumps(PROFILE))
    code, out = run(capsys, "validate", survey, "--station-profile", prof)
    assert code == 0, out
    # the survey folder carries its profile: validate and the chain find it without the option
    (survey / "station_profile.json").write_text(json.dumps(PROFILE))
    doc = json.loads((survey / "survey.json").read_text())
    doc["files"]["station_profile"] = "station_profile.json"
    (survey / "survey.json").write_text(json.dumps(doc))
    rep = validate_survey(survey)
    assert rep.valid, [p.line() for p in rep.problems]
    assert rep.summary["weather_columns"]["air_temp_c"] == "AirTemp_F [deg F]"
    srv = read_survey(survey)
    w = read_toa5(srv.path("weather"), "weather.dat", srv.station_profile)
    ref = read_toa5(station_survey(tmp_path / "ref") / "weather.dat", "w",
                    srv.station_profile)
    np.testing.assert_allclose(w.air_temp_c, ref.air_temp_c)
    assert 14.0 < float(np.mean(w.air_temp_c)) < 16.0  # 15 deg C written as 59 deg F
    np.testing.assert_allclose(w.wind_ms, 2.0, atol=1e-5)  # 2 m/s written in knots


def test_gnss_checksums_optional_in_survey_json(tmp_path):
    survey = tmp_path / "s"
    make_minimal_survey(survey)
    text = (survey / "gnss.nmea").read_text()
    (survey / "gnss.nmea").write_text("".join(line.split("*")[0] + "\r\n"
                                              for line in text.splitlines() if line))
    rep = validate_survey(survey)
    assert not rep.valid
    assert "no sentence has a checksum" in rep.problems[0].line()
    doc = json.loads((survey / "survey.json").read_text())
    doc["gnss"] = {"checksums": "optional"}
    (survey / "survey.json").write_text(json.dumps(doc))
    rep = validate_survey(survey)
    assert rep.valid, [p.line() for p in rep.problems]
    assert rep.summary["gnss_epochs"] > 100
