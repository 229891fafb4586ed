#!/usr/bin/env bash
# Prepare .venv for clearfast-gis on a Debian machine. Sourced by scripts/demo.sh and
# scripts/test.sh; safe to run again (it only installs what is missing).
#   scripts/bootstrap.sh            toolkit only
#   scripts/bootstrap.sh --test     toolkit + test tools + QGIS (Debian python3-qgis)
#
# The venv is made from Debian's /usr/bin/python3 with --system-site-packages so that QGIS's
# Python bindings (python3-qgis, only packaged for Debian's Python) are visible inside it. Such a
# venv also sees Debian's older Python packages (some, like python3-affine, break current
# rasterio), so every dependency of the toolkit is installed into the venv itself with
# --ignore-installed: the venv's own versions shadow Debian's.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
want_test=0
[ "${1:-}" = "--test" ] && want_test=1

sudo_cmd=""
[ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"

apt_pkgs=()
[ -x /usr/bin/python3 ] || apt_pkgs+=(python3)
/usr/bin/python3 -c "import ensurepip" 2>/dev/null || apt_pkgs+=(python3-venv)
# exiftool decodes radiometric camera files (clearfast import / thermal-frame)
command -v exiftool >/dev/null 2>&1 || apt_pkgs+=(libimage-exiftool-perl)
if [ "$want_test" = 1 ]; then
  /usr/bin/python3 -c "import qgis.core" 2>/dev/null || apt_pkgs+=(python3-qgis qgis-providers)
  command -v qgis_process >/dev/null 2>&1 || apt_pkgs+=(qgis)
  command -v gdalinfo >/dev/null 2>&1 || apt_pkgs+=(gdal-bin)
  command -v pdfinfo >/dev/null 2>&1 || apt_pkgs+=(poppler-utils)
fi
if [ "${#apt_pkgs[@]}" -gt 0 ]; then
  echo "bootstrap: installing Debian packages: ${apt_pkgs[*]}" >&2
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends \
    "${apt_pkgs[@]}" >/dev/null
fi

venv="$here/.venv"
if [ ! -x "$venv/bin/python" ]; then
  /usr/bin/python3 -m venv --system-site-packages "$venv"
fi
stamp="$venv/.clearfast-installed"
extras=""
[ "$want_test" = 1 ] && extras="[dev]"
key="$(cat "$here/pyproject.toml" | sha256sum | cut -c1-16)$extras"
if [ ! -f "$stamp" ] || ! grep -qx "$key" "$stamp"; then
  "$venv/bin/python" -m pip install -q --upgrade pip
  "$venv/bin/python" -m pip install -q --ignore-installed -e "$here$extras"
  echo "$key" > "$stamp"
fi
export PATH="$venv/bin:$PATH"
