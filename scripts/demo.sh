#!/usr/bin/env bash
# Main job on the embedded default: simulate the demo survey and process it end to end.
# Usage: scripts/demo.sh [OUTDIR]   (default: ./demo-out)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
source "$here/scripts/bootstrap.sh"
out="${1:-$here/demo-out}"
clearfast demo "$out"
