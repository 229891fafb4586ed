"""Entry point of the ``clearfast`` command line.

Subcommands live in one module each (``clearfast_gis.cli.<name>``, exposing ``command``) and are
imported only when used, so ``clearfast --help`` stays fast. Every error the toolkit anticipates
(:class:`~clearfast_gis.errors.ClearfastError`) is printed as one line naming the file and the
problem; exit status 1 for invalid input or failed runs, 2 for usage errors.
"""

from __future__ import annotations

import importlib
import os

import click

from clearfast_gis import __version__
from clearfast_gis.allocator import keep_freed_memory
from clearfast_gis.errors import ClearfastError

#: subcommand name -> (module, one-line help)
SUBCOMMANDS: dict[str, tuple[str, str]] = {
    "plan": ("plan", "Plan a stop-and-go pan/tilt scanning mission."),
    "validate": ("validate", "Check a survey folder completely."),
    "simulate": ("simulate", "Simulate a complete survey with ground truth."),
    "calibrate": ("calibrate", "Radiometric calibration to apparent temperature."),
    "mosaic": ("mosaic", "Build georeferenced COG mosaics, one per scan."),
    "detect": ("detect", "Re-run anomaly detection on existing mosaics."),
    "detect-images": ("detect_images", "Detect anomalies in plain thermal snapshots."),
    "process": ("process", "Run the whole chain: survey folder to products."),
    "export": ("export", "Export products for a mine action centre."),
    "batch": ("batch", "Convert many surveys, locally or on a Dask cluster."),
    "log": ("log", "Log the field instruments over serial ports."),
    "acquire": ("acquire", "Run a scanning mission with the field instruments."),
    "simulate-devices": ("simulate_devices", "Serve the digital twin's instruments on ptys."),
    "import": ("import_survey", "Build a survey folder from a radiometric camera's files."),
    "thermal-frame": ("thermal_frame", "One camera frame's object temperature (deg C TIFF)."),
    "demo": ("demo", "Simulate the embedded demo survey and process it end to end."),
    "options": ("options_cmd", "Show the processing defaults (--json for programs)."),
}


class LazyGroup(click.Group):
    """A click group whose subcommands are imported on first use, and which turns every error
    of a subcommand into one line and an exit status (so ``click.testing.CliRunner`` sees
    exactly what a shell sees)."""

    def invoke(self, ctx: click.Context):
        try:
            return super().invoke(ctx)
        except (click.exceptions.Exit, click.ClickException):
            raise
        except click.exceptions.Abort:
            click.echo("clearfast: aborted", err=True)
            ctx.exit(130)
        except ClearfastError as exc:
            click.echo(f"clearfast: error: {exc.one_line()}", err=True)
            ctx.exit(exc.exit_code)
        except KeyboardInterrupt:
            click.echo("clearfast: interrupted; run again with --resume to continue", err=True)
            ctx.exit(130)
        except Exception as exc:  # last line of defence for the CLI
            if os.environ.get("CLEARFAST_DEBUG"):
                raise
            line = " ".join(str(exc).split()) or type(exc).__name__
            click.echo(f"clearfast: internal error: {type(exc).__name__}: {line} "
                       "(set CLEARFAST_DEBUG=1 for details)", err=True)
            ctx.exit(3)

    def list_commands(self, ctx: click.Context) -> list[str]:
        return [n for n, (mod, _) in SUBCOMMANDS.items() if _module_exists(mod)]

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        if cmd_name not in SUBCOMMANDS or not _module_exists(SUBCOMMANDS[cmd_name][0]):
            return None
        module = importlib.import_module(f"clearfast_gis.cli.{SUBCOMMANDS[cmd_name][0]}")
        return module.command

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        rows = [(n, SUBCOMMANDS[n][1]) for n in self.list_commands(ctx)]
        if rows:
            with formatter.section("Commands"):
                formatter.write_dl(rows)


def _module_exists(mod: str) -> bool:
    from importlib.util import find_spec

    return find_spec(f"clearfast_gis.cli.{mod}") is not None


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="clearfast")
def group() -> None:
    """Stand-off thermal-IR minefield survey: from a survey folder to maps you can act on."""


def cli(argv: list[str] | None = None) -> None:
    """Run the command line; never show a traceback for anticipated errors (the group maps
    them, :class:`LazyGroup`).

    Set ``CLEARFAST_DEBUG=1`` to see the traceback of an unexpected error (and GDAL's own
    log messages, which are otherwise kept off the terminal).
    """
    if not os.environ.get("CLEARFAST_DEBUG"):
        import logging

        for name in ("rasterio", "pyogrio", "fiona"):
            logging.getLogger(name).addHandler(logging.NullHandler())
            logging.getLogger(name).propagate = False
    group.main(args=argv, prog_name="clearfast")


def main() -> None:
    """The ``clearfast`` program: :func:`cli` in a process of its own, whose C heap keeps
    freed memory for reuse (:mod:`clearfast_gis.allocator`; a process that calls
    :func:`cli` keeps its allocator as it is)."""
    keep_freed_memory()
    cli()


if __name__ == "__main__":
    main()
