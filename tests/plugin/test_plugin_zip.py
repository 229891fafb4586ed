"""The documented command builds an installable plugin zip."""

from __future__ import annotations

import subprocess
import zipfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def test_build_plugin_zip(tmp_path):
    r = subprocess.run([str(REPO / "scripts" / "build_plugin_zip.sh"), str(tmp_path)],
                       capture_output=True, text=True, timeout=60, check=True)
    zip_path = Path(r.stdout.strip())
    assert zip_path == tmp_path / "clearfast-0.1.0.zip"
    names = zipfile.ZipFile(zip_path).namelist()
    expected = {"clearfast/" + p.relative_to(REPO / "qgis_plugin" / "clearfast").as_posix()
                for p in (REPO / "qgis_plugin" / "clearfast").rglob("*")
                if p.is_file() and "__pycache__" not in p.parts}
    assert set(names) == expected
    assert {"clearfast/metadata.txt", "clearfast/__init__.py", "clearfast/icons/clearfast.svg",
            "clearfast/loader.py", "clearfast/provider.py"} <= set(names)
    assert [p.name for p in tmp_path.iterdir()] == [zip_path.name]
