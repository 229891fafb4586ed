"""Real field files that `clearfast process` cannot use as they are: a station table whose
columns are not mapped, values in the wrong column, a broken station profile, a receiver log
without checksums. One line naming file, line and field; exit 1; nothing written."""

from __future__ import annotations

import json

from tests.survey.test_station_profile_cli import PROFILE, station_survey

from .conftest import assert_fatal


def _weather_lines(survey):
    return (survey / "weather.dat").read_bytes().decode().split("\r\n")


def test_station_table_without_its_profile(tmp_path, process):
    survey = station_survey(tmp_path / "s")
    assert_fatal(process(survey, tmp_path / "out"),
                 "weather.dat: line 2: missing air temperature (air_temp_c, e.g. AirTC_Avg), "
                 "wind speed (wind_ms, e.g. WS_ms_Avg); the file has columns TIMESTAMP")
    assert not (tmp_path / "out").exists()
    profile = tmp_path / "station.json"
    profile.write_text(json.dumps({**PROFILE, "columns": {
        **PROFILE["columns"], "wind_ms": {"column": "Wind_kn", "unit": "furlongs"}}}))
    assert_fatal(process(survey, tmp_path / "out", "--station-profile", str(profile)),
                 f"{profile}: columns.wind_ms.unit: unit 'furlongs' is not a speed unit")
    assert not (tmp_path / "out").exists()


def test_solar_logged_as_air_temperature(survey, tmp_path, process):
    """A station whose columns were mapped by position: 147 W/m^2 read as 147 deg C."""
    lines = _weather_lines(survey)
    out = lines[:4]
    for line in lines[4:]:
        f = line.split(",")
        if len(f) > 6:
            f[2] = "147"
        out.append(",".join(f))
    (survey / "weather.dat").write_bytes("\r\n".join(out).encode())
    result = process(survey, tmp_path / "out")
    assert_fatal(result, "weather.dat: line 5: AirTC_Avg (air_temp_c): ")
    assert "outside -60..60 deg C, first line 5: 147 deg C (wrong column or unit?)" in result[2]
    assert not (tmp_path / "out").exists()


def test_receiver_without_checksums(survey, tmp_path, process):
    text = (survey / "gnss.nmea").read_bytes().decode()
    (survey / "gnss.nmea").write_bytes("".join(
        line.split("*")[0] + "\r\n" for line in text.split("\r\n") if line).encode())
    assert_fatal(process(survey, tmp_path / "out"),
                 "gnss.nmea: no sentence has a checksum (")
    assert not (tmp_path / "out").exists()
