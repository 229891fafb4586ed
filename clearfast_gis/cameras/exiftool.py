"""The one way the toolkit runs exiftool (Phil Harvey's, Debian ``libimage-exiftool-perl``).

exiftool decodes the metadata of FLIR and DJI radiometric files (FLIR's FFF records inside
JPEG APP1 segments, SEQ/CSQ/FFF containers, XMP gimbal tags) and extracts their embedded raw
thermal images. It is run as a subprocess on a file or on bytes given on its standard input
(one FFF record of a SEQ file); its JSON is read with ``-n`` (numbers, not printed
conversions) and ``-G1`` (tag names prefixed by their group, e.g. ``FLIR:PlanckR1``).
"""

from __future__ import annotations

import json
import shutil
import subprocess
from os import PathLike
from typing import Any

from clearfast_gis.errors import InvalidInput

EXIFTOOL = "exiftool"
INSTALL_HINT = "exiftool is not installed (Debian: apt-get install libimage-exiftool-perl)"


def _run(args: list[str], source: str | PathLike, data: bytes | None,
         targets: list[str] | None = None) -> bytes:
    exe = shutil.which(EXIFTOOL)
    if exe is None:
        raise InvalidInput(INSTALL_HINT, source)
    if targets is None:
        targets = ["-" if data is not None else str(source)]
    try:
        proc = subprocess.run([exe, *args, "--", *targets], input=data, capture_output=True,
                              check=False, timeout=120 + len(targets))
    except (OSError, subprocess.TimeoutExpired) as exc:
        raise InvalidInput(f"exiftool failed: {exc}", source) from None
    if proc.returncode != 0 and not proc.stdout:
        msg = proc.stderr.decode("utf-8", "replace").strip().splitlines()
        raise InvalidInput(f"exiftool cannot read it: {msg[-1] if msg else 'no output'}", source)
    return proc.stdout


def read_tags(source: str | PathLike, data: bytes | None = None) -> dict[str, Any]:
    """All tags of a file (or of ``data``, named ``source`` in errors) as ``{"GROUP:Tag": value}``.

    Numbers come as numbers (exiftool's ``-n``); exiftool writes some as JSON strings, which
    :func:`number` converts.
    """
    out = _run(["-j", "-n", "-G1", "-a"], source, data)
    try:
        tags = json.loads(out.decode("utf-8", "replace"))[0]
    except (ValueError, IndexError):
        raise InvalidInput("exiftool gave no metadata", source) from None
    return tags


def read_tags_many(paths: list[str | PathLike]) -> dict[str, dict[str, Any]]:
    """Tags of many files in one exiftool run (starting exiftool dominates for small files):
    ``{str(path): tags}``, the raw thermal image included as exiftool's ``base64:`` text
    (:func:`binary_tag`); a file exiftool cannot read is an error naming it."""
    if not paths:
        return {}
    out = _run(["-j", "-n", "-G1", "-a", "-q", "-q", "-b", "-all", "-RawThermalImage",
                "--ThumbnailImage", "--EmbeddedImage", "--PreviewImage"], paths[0], None,
               [str(p) for p in paths])
    try:
        docs = json.loads(out.decode("utf-8", "replace"))
    except ValueError:
        raise InvalidInput("exiftool gave no metadata", paths[0]) from None
    by_name = {d.get("SourceFile"): d for d in docs}
    result = {}
    for p in paths:
        if str(p) not in by_name:
            raise InvalidInput("exiftool cannot read it", p)
        result[str(p)] = by_name[str(p)]
    return result


def binary_tag(tags: dict[str, Any], key: str) -> bytes | None:
    """The bytes of a binary tag that exiftool put into its JSON (``base64:...``), or None."""
    import base64

    val = tags.get(key)
    if isinstance(val, str) and val.startswith("base64:"):
        return base64.b64decode(val[len("base64:"):])
    return None


def read_binary(source: str | PathLike, tag: str, data: bytes | None = None) -> bytes:
    """The bytes of one binary tag (e.g. ``RawThermalImage``); empty if the tag is absent."""
    return _run(["-b", f"-{tag}"], source, data)


def number(tags: dict[str, Any], key: str, source: str | PathLike) -> float:
    """Tag ``key`` as a float; an error naming the file and tag when missing or not a number."""
    if key not in tags:
        raise InvalidInput("tag missing", source, key)
    try:
        return float(tags[key])
    except (TypeError, ValueError):
        raise InvalidInput(f"not a number: {tags[key]!r}", source, key) from None
