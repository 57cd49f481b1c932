"""The Mitutoyo SurfTest export ``mitutoyo_2_mock.xlsx`` read for the tests only.

The file (SurfaceTopography's ``test/file_format_examples``, MIT; a copy lies in
``../shared/realdata`` with its MANIFEST row) holds the instrument's own printout: its
23 results, its conditions (λc 2.5 mm, λs 8 µm, N = 4, Gauss, ISO 1997, R-profile) and
the exported R-profile (6664 points at 1.5 µm), plus its material ratio curve at 1 % of
Rt and amplitude distribution. The package's own xlsx reader belongs to ``surfmet.io``;
this helper reads the sheet with ``zipfile`` and ``xml`` so that the roughness tests do
not depend on it.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
import zipfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

_NS = "{http://schemas.openxmlformats.org/spreadsheetml/2006/main}"


@dataclass(frozen=True)
class Printout:
    """What the instrument printed and exported (SI: metres; ratios in %)."""

    results: dict[str, float]  # symbol -> value as printed (µm values converted to m)
    digits: dict[str, float]  # symbol -> half a unit of the last printed digit (SI)
    conditions: dict[str, str]
    z: np.ndarray  # exported R-profile, metres
    dx: float
    bac_ratio: np.ndarray  # material ratio (%) at depths 0, 1, ... 99 % of Rt


def _cells(book: zipfile.ZipFile, sheet: int, strings: list[str]) -> dict[str, object]:
    root = ET.fromstring(book.read(f"xl/worksheets/sheet{sheet}.xml"))
    cells: dict[str, object] = {}
    for c in root.iter(_NS + "c"):
        v = c.find(_NS + "v")
        if v is None:
            continue
        kind = c.get("t")
        cells[c.get("r")] = strings[int(v.text)] if kind == "s" else (
            v.text if kind in ("str", "b") else float(v.text))
    return cells


def _column(cells: dict[str, object], col: str) -> np.ndarray:
    rows = sorted((int(k[len(col):]), v) for k, v in cells.items()
                  if re.fullmatch(col + r"\d+", k))
    return np.array([v for _, v in rows], dtype=float)


def read_printout(path: Path) -> Printout:
    """Parse the export (sheet 1: certificate with the results; sheet 2: data)."""
    with zipfile.ZipFile(path) as book:
        sst = ET.fromstring(book.read("xl/sharedStrings.xml"))
        strings = ["".join(t.text or "" for t in si.iter(_NS + "t"))
                   for si in sst.findall(_NS + "si")]
        cert = _cells(book, 1, strings)
        data = _cells(book, 2, strings)
    results: dict[str, float] = {}
    digits: dict[str, float] = {}
    for col_sym, col_val in (("B", "C"), ("D", "E")):
        for row in range(52, 64):
            sym = str(cert.get(f"{col_sym}{row}", "")).strip()
            text = str(cert.get(f"{col_val}{row}", "")).strip()
            if not sym or not text:
                continue
            number, _, unit = text.partition(" ")
            scale = 1e-6 if unit.strip() == "µm" else 1.0
            decimals = len(number.partition(".")[2])
            results[sym] = float(number) * scale
            digits[sym] = 0.5 * 10.0 ** -decimals * scale
    conditions = {str(cert[f"{k}{r}"]).strip(): str(cert[f"{v}{r}"]).strip()
                  for r in (47, 48, 49) for k, v in (("B", "C"), ("D", "E"))}
    x = _column(data, "E") * 1e-3
    z = _column(data, "F") * 1e-6
    return Printout(results, digits, conditions, z, float(np.median(np.diff(x))),
                    _column(data, "C"))
