#!/usr/bin/env bash
# Build the installable QGIS plugin: a zip of qgis_plugin/clearfast (top folder "clearfast"),
# for QGIS's Plugins > Manage and Install Plugins > Install from ZIP.
#   scripts/build_plugin_zip.sh [OUTDIR]        (default: ./dist)
# Prints the path of the zip: OUTDIR/clearfast-<version>.zip
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$here/dist}"
src="$here/qgis_plugin/clearfast"
version="$(sed -n 's/^version=//p' "$src/metadata.txt")"
[ -n "$version" ] || { echo "build_plugin_zip: no version in $src/metadata.txt" >&2; exit 1; }
mkdir -p "$out"
zip_path="$out/clearfast-$version.zip"
python="$(command -v python3 || command -v python)"
"$python" - "$src" "$zip_path" <<'PY'
import os
import sys
import tempfile
import zipfile
from pathlib import Path

src, final = Path(sys.argv[1]), Path(sys.argv[2])
fd, tmp = tempfile.mkstemp(prefix=".clearfast-", suffix=".zip.part", dir=final.parent)
os.close(fd)
try:
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as zf:
        for path in sorted(src.rglob("*")):
            rel = path.relative_to(src)
            if path.is_dir() or "__pycache__" in rel.parts or path.suffix in (".pyc", ".pyo"):
                continue
            zf.write(path, str(Path("clearfast") / rel))
    os.replace(tmp, final)
finally:
    if os.path.exists(tmp):
        os.unlink(tmp)
PY
echo "$zip_path"
