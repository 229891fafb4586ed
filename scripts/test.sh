#!/usr/bin/env bash
# Install everything the tests need (QGIS included) on a Debian machine, then lint and test.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
source "$here/scripts/bootstrap.sh" --test
cd "$here"
export QT_QPA_PLATFORM=offscreen
ruff check .
python -m pytest -q -n 2 "$@"
