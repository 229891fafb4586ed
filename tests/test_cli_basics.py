"""The command line's frame: help, version, one-line errors."""

from __future__ import annotations

import subprocess
import sys

from clearfast_gis.errors import ClearfastError


def run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "clearfast_gis.cli.main", *args],
                          capture_output=True, text=True, timeout=120)


def test_version_and_help():
    r = run("--version")
    assert r.returncode == 0 and "clearfast" in r.stdout
    r = run("--help")
    assert r.returncode == 0 and "Usage" in r.stdout


def test_unknown_command_is_usage_error():
    r = run("no-such-command")
    assert r.returncode == 2
    assert "Traceback" not in r.stderr


def test_error_one_line():
    e = ClearfastError("expected 2 integers", "survey.json", "camera.resolution")
    assert e.one_line() == "survey.json: camera.resolution: expected 2 integers"
    e = ClearfastError("bad\n  thing", "a.tif")
    assert "\n" not in e.one_line()


def test_errors_are_mapped_in_process(tmp_path):
    """The click group itself maps errors, so CliRunner (in-process) sees one line and the
    exit status a shell sees."""
    from click.testing import CliRunner

    from clearfast_gis.cli.main import group

    runner = CliRunner()
    r = runner.invoke(group, ["process", str(tmp_path), "-o", str(tmp_path / "p")])
    assert r.exit_code == 1
    assert r.output.strip().splitlines() == [
        "clearfast: error: survey.json: file not found (empty or not a survey folder)"]
    assert r.exception is None or isinstance(r.exception, SystemExit)
    assert not (tmp_path / "p" / "products.json").exists()
    r = runner.invoke(group, ["no-such-command"])
    assert r.exit_code == 2 and "No such command" in r.output


def test_unexpected_error_is_one_line(monkeypatch, tmp_path):
    from click.testing import CliRunner

    import clearfast_gis.cli.options_cmd as options_cmd
    from clearfast_gis.cli.main import group

    def broken() -> dict:
        raise RuntimeError("disk\n on fire")

    monkeypatch.delenv("CLEARFAST_DEBUG", raising=False)
    monkeypatch.setattr(options_cmd, "defaults_document", broken)
    r = CliRunner().invoke(group, ["options"])
    assert r.exit_code == 3
    assert r.output.strip() == ("clearfast: internal error: RuntimeError: disk on fire "
                                "(set CLEARFAST_DEBUG=1 for details)")


def test_options_json_are_the_process_defaults():
    import json

    from click.testing import CliRunner

    from clearfast_gis import __version__
    from clearfast_gis.cli.main import group
    from clearfast_gis.pipeline.options import ProcessOptions

    r = CliRunner().invoke(group, ["options", "--json"])
    assert r.exit_code == 0
    assert json.loads(r.output) == {"version": __version__,
                                    "process": ProcessOptions().as_dict()}


def test_help_states_the_real_defaults():
    from click.testing import CliRunner

    from clearfast_gis.cli.main import group
    from clearfast_gis.pipeline.options import ProcessOptions

    d = ProcessOptions()
    for cmd in ("process", "detect", "batch"):
        text = " ".join(CliRunner().invoke(group, [cmd, "--help"],
                                           terminal_width=200).output.split())
        assert f"[default: {d.d2_m}; x>0.0]" in text
        assert f"[default: {d.d1_m}; x>0.0]" in text
        assert f"[default: {d.max_anomalies}; x>=1]" in text
        assert "a quarter of the images covering each pixel" in text
        assert "half the scans" not in text


def test_process_from_after_until_is_a_usage_error(tmp_path):
    from click.testing import CliRunner

    from clearfast_gis.cli.main import group

    r = CliRunner().invoke(group, ["process", str(tmp_path), "-o", str(tmp_path / "p"),
                                   "--from", "products", "--until", "mosaics"])
    assert r.exit_code == 2
    assert "--from products comes after --until mosaics" in r.output
    r = CliRunner().invoke(group, ["process", str(tmp_path), "-o", str(tmp_path / "p"),
                                   "--until", "mosaic"])
    assert r.exit_code == 2 and "residuals_and_footprint" in r.output
