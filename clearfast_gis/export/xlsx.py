"""Byte-reproducible XLSX workbooks of export tables (openpyxl), for spreadsheet imports.

openpyxl stamps the workbook's modification time (at save) and every zip member's time with the
clock; both are set to one given instant here, so the same tables always give the same bytes.
"""

from __future__ import annotations

import io
import re
import zipfile
from collections.abc import Mapping
from datetime import datetime, timezone

import numpy as np


def _cell(value, decimals: int | None):
    """A cell value: None for nulls, a rounded float, an int or text."""
    import pandas as pd

    if value is None or (not isinstance(value, str) and pd.isna(value)):
        return None
    if isinstance(value, str):
        return value
    if decimals is not None:
        return round(float(value), decimals)
    if isinstance(value, (int, np.integer)):
        return int(value)
    return float(value)


def workbook_bytes(sheets: Mapping[str, tuple], decimals: Mapping[str, int],
                   timestamp_s: float) -> bytes:
    """An XLSX file with one sheet per table.

    Parameters
    ----------
    sheets : mapping of str to (pandas.DataFrame, sequence of str)
        Sheet name (at most 31 characters) -> the table and the columns to write, in order.
        The first row holds the column names.
    decimals : mapping of str to int
        Column name -> decimals its numbers are rounded to (as in the CSV files).
    timestamp_s : float
        UTC epoch seconds stored as the workbook's created/modified time and the zip members'
        times.

    Returns
    -------
    bytes
    """
    from openpyxl import Workbook

    when = datetime.fromtimestamp(float(timestamp_s), timezone.utc).replace(tzinfo=None)  # noqa: UP017
    book = Workbook()
    book.remove(book.active)
    for name, (table, columns) in sheets.items():
        sheet = book.create_sheet(name)
        sheet.append(list(columns))
        for row in table[list(columns)].itertuples(index=False):
            sheet.append([_cell(v, decimals.get(c)) for c, v in zip(columns, row, strict=True)])
        sheet.freeze_panes = "A2"
    book.properties.created = when
    book.properties.modified = when
    book.properties.creator = "clearfast-gis"
    raw = io.BytesIO()
    book.save(raw)
    return _fixed_zip_times(raw.getvalue(), when)


def _fixed_zip_times(data: bytes, when: datetime) -> bytes:
    """The zip archive ``data`` with every member, and the workbook's modification time in
    ``docProps/core.xml``, dated ``when`` (members in their order)."""
    iso = when.strftime("%Y-%m-%dT%H:%M:%SZ")
    stamp = (max(when.year, 1980), when.month, when.day, when.hour, when.minute, when.second)
    out = io.BytesIO()
    with zipfile.ZipFile(io.BytesIO(data)) as src, \
            zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as dst:
        for info in src.infolist():
            member = zipfile.ZipInfo(info.filename, date_time=stamp)
            member.compress_type = zipfile.ZIP_DEFLATED
            member.external_attr = 0o600 << 16
            content = src.read(info.filename)
            if info.filename == "docProps/core.xml":
                content = re.sub(rb"(<dcterms:modified[^>]*>)[^<]*(</dcterms:modified>)",
                                 rb"\g<1>" + iso.encode() + rb"\g<2>", content)
            dst.writestr(member, content)
    return out.getvalue()
