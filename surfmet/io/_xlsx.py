"""A minimal Office Open XML spreadsheet (.xlsx) cell reader: zipfile + ElementTree.

Reads cell values only (numbers, shared strings, inline strings, cached formula results),
by sheet name, following ``xl/workbook.xml`` and its relationships as ECMA-376 Part 1
(SpreadsheetML, section 18) describes them. Styles, formulas and charts are ignored.
"""

from __future__ import annotations

import re
import zipfile
from xml.etree import ElementTree as ET

from surfmet.io._binary import format_error
from surfmet.io._zip import read_member

_MAIN = "{http://schemas.openxmlformats.org/spreadsheetml/2006/main}"
_REL = "{http://schemas.openxmlformats.org/officeDocument/2006/relationships}"
_PKG = "{http://schemas.openxmlformats.org/package/2006/relationships}"
_REF_RE = re.compile(r"^([A-Z]{1,3})(\d{1,7})$")
# A sheet's XML is text around numbers: 256 MiB would be tens of millions of cells.
MAX_XML_BYTES = 256 * 2**20

Cells = dict[tuple[str, int], "str | float"]


def _parse(raw: bytes, name: str, fmt: str, what: str) -> ET.Element:
    if b"<!DOCTYPE" in raw[:65536] or b"<!ENTITY" in raw[:65536]:
        raise format_error(name, fmt, f"{what} declares a DOCTYPE; refused")
    try:
        return ET.fromstring(raw)
    except ET.ParseError as exc:
        raise format_error(name, fmt, f"{what} is not well-formed XML ({exc})") from None


def sheet_paths(zf: zipfile.ZipFile, name: str, fmt: str) -> dict[str, str]:
    """Sheet name -> archive path of its XML, in workbook order."""
    book = _parse(read_member(zf, "xl/workbook.xml", name, fmt, MAX_XML_BYTES),
                  name, fmt, "workbook.xml")
    rels_root = _parse(read_member(zf, "xl/_rels/workbook.xml.rels", name, fmt, MAX_XML_BYTES),
                       name, fmt, "workbook relationships")
    targets = {r.get("Id"): r.get("Target", "") for r in rels_root.iter(f"{_PKG}Relationship")}
    out: dict[str, str] = {}
    for sheet in book.iter(f"{_MAIN}sheet"):
        target = targets.get(sheet.get(f"{_REL}id"))
        if target:
            path = target.lstrip("/") if target.startswith("/") else "xl/" + target
            out[sheet.get("name", "")] = path
    return out


def shared_strings(zf: zipfile.ZipFile, name: str, fmt: str) -> list[str]:
    """The shared-string table (empty when the workbook has none)."""
    if "xl/sharedStrings.xml" not in zf.namelist():
        return []
    root = _parse(read_member(zf, "xl/sharedStrings.xml", name, fmt, MAX_XML_BYTES),
                  name, fmt, "sharedStrings.xml")
    # Rich text splits a string into runs: join every <t> of the item.
    return ["".join(t.text or "" for t in si.iter(f"{_MAIN}t")) for si in root]


def read_cells(zf: zipfile.ZipFile, path: str, strings: list[str], name: str, fmt: str
               ) -> Cells:
    """``{(column letters, row number): value}`` for every cell holding a value."""
    root = _parse(read_member(zf, path, name, fmt, MAX_XML_BYTES), name, fmt, path)
    cells: Cells = {}
    for c in root.iter(f"{_MAIN}c"):
        m = _REF_RE.match(c.get("r", ""))
        if m is None:
            continue
        kind = c.get("t", "n")
        if kind == "inlineStr":
            node = c.find(f"{_MAIN}is")
            if node is not None:
                cells[(m.group(1), int(m.group(2)))] = "".join(
                    t.text or "" for t in node.iter(f"{_MAIN}t"))
            continue
        v = c.find(f"{_MAIN}v")
        if v is None or v.text is None:
            continue
        key = (m.group(1), int(m.group(2)))
        if kind == "s":
            cells[key] = strings[int(v.text)]
        elif kind in ("str", "e"):
            cells[key] = v.text
        elif kind == "b":
            cells[key] = float(v.text == "1")
        else:
            cells[key] = float(v.text)
    return cells


__all__ = ["Cells", "read_cells", "shared_strings", "sheet_paths"]
