"""``clearfast`` with ``max_anomalies`` capped, for subprocess tests.

Usage: ``python capped_cli.py MAX_ANOMALIES process SURVEY -o PRODUCTS ...``: the real command
line, with the one parameter it does not expose set small so a tiny survey's run stays short.
"""

from __future__ import annotations

import dataclasses
import sys

import clearfast_gis.cli.options as cli_options
from clearfast_gis.cli.main import cli

_build = cli_options.build_options


def _capped(params, invert=True):
    return dataclasses.replace(_build(params, invert), max_anomalies=int(sys.argv[1]))


if __name__ == "__main__":
    cli_options.build_options = _capped
    cli(sys.argv[2:])
