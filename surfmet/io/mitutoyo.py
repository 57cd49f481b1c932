"""Mitutoyo SurfTest Excel export (``.xlsx``): a profile with the instrument's conditions.

The SurfTest software writes a workbook with (at least) two sheets:

* ``DATA``: column E the lateral positions (in the unit of the cut-off, mm), column F the
  heights (in the unit of the printed results, µm), one point per row from row 1; column A
  the printed results as text (``"Ra     3.308  µm"``); column B the evaluation
  conditions as codes (``"CUT 2.5mm"``, ``"N 4"``, ``"CUV R"``, ``"FIL GAUSS"``,
  ``"STD ISO 1997"``, ``"LS  8µm"``, ``"STP 1.5"``);
* ``Certificate``: the date in E2 (``"20- Jun -2023"``) and the same conditions as labelled
  pairs (``Standard | ISO 1997``, ``N | 4``, ``Profile | R``, ``Cut-Off | 2.5mm``,
  ``λs | 8µm``, ``Filter | GAUSS``) in columns B/C and D/E.

The layout follows SurfaceTopography's ``MitutoyoReader`` (MIT) and its test files; the
workbook itself is read with :mod:`surfmet.io._xlsx` (no openpyxl).

Metadata (SI values; the keys agreed with ``roughness``, see docs/formats.md):

``evaluation_conditions``  ``{"standard": "iso4287", "standard_text": "ISO 1997",
                           "lc": 0.0025, "ls": 8e-06, "n_sampling": 4, "profile": "R",
                           "filter": "gaussian", "rk_line": "levels",
                           "element_start": "first-crossing",
                           "source": "Mitutoyo SurfTest export"}``;
                           a key is absent when the file does not state it
``instrument_results``     the printed results in print order, ``{"Ra": {"value": 3.308e-06,
                           "unit": "m"}, "Rsk": {"value": -0.144, "unit": ""}, "Mr1":
                           {"value": 5.822, "unit": "%"}, "A1": {"value": 8.48e-08,
                           "unit": "m"}, ...}``: in the units surfmet states the same
                           parameters in (lengths in metres, ratios in %); ``A1``, ``A2``,
                           printed without a unit, are Rpk Mr1 / 2 and Rvk (100 % - Mr2) / 2
                           in µm·% (ISO 13565-2; the printed Rpk, Mr1, Rvk and Mr2 give
                           them to the printed digits), so in metres they are the printed
                           value x 1e-6 x 1e-2, as surfmet's A1 = Rpk Mr1 / 2 with Mr1 a
                           fraction; ``Rkµ``, ``RDq``, ``RSm`` are
                           renamed ``Rku``, ``Rdq``, ``Rsm``
"""

from __future__ import annotations

import datetime as _dt
import re
from typing import Any

import numpy as np

from surfmet._errors import SurfmetFormatError, SurfmetInputError
from surfmet._model import Profile
from surfmet.io._binary import check_step, format_error, positions_profile
from surfmet.io._registry import register_reader
from surfmet.io._xlsx import Cells, read_cells, shared_strings, sheet_paths
from surfmet.io._zip import ZIP_MAGIC, member_names, open_zip
from surfmet.units import length_factor, quantity

FORMAT = "mitutoyo"
_RESULT_RE = re.compile(r"^\s*(\S+)\s+([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S*)\s*$")
_LENGTH_RE = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+))\s*([^\s\d]+)\s*$")
_RENAME = {"Rkµ": "Rku", "Rkμ": "Rku", "RDq": "Rdq", "RSm": "Rsm"}
#: The Rk construction of the SurfTest (:data:`profiles._rk.CONSTRUCTIONS`).
RK_LINE = "levels"
#: How the SurfTest pairs profile elements (:data:`profiles._elements.ELEMENT_STARTS`).
ELEMENT_START = "first-crossing"
# ISO 13565-2 areas, printed without a unit in (height unit) x %
_AREAS = ("A1", "A2")
_STANDARDS = {"iso 1997": "iso4287", "iso1997": "iso4287", "iso 4287": "iso4287",
              "iso 2021": "iso21920", "iso 21920": "iso21920"}
# Codes of the DATA sheet's column B -> the Certificate sheet's labels.
_CODES = {"CUT": "cut-off", "N": "n", "CUV": "profile", "FIL": "filter", "STD": "standard",
          "LS": "λs"}
_UNIFORM_RTOL = 1e-4
_ORDER = ("standard", "standard_text", "lc", "ls", "n_sampling", "profile", "filter")


def _is_mitutoyo(buf: bytes) -> bool:
    return buf[:4] == ZIP_MAGIC and b"xl/workbook.xml" in member_names(buf)


def _fail(name: str, problem: str) -> SurfmetFormatError:
    return format_error(name, "Mitutoyo xlsx", problem)


def _column(cells: Cells, col: str) -> list[tuple[int, str | float]]:
    return sorted((row, v) for (c, row), v in cells.items() if c == col)


def _results(data: Cells) -> tuple[dict[str, Any], str | None]:
    """Column A's printed results (SI) and the unit of the first length result."""
    out: dict[str, Any] = {}
    height_unit = None
    for _, text in _column(data, "A"):
        if not isinstance(text, str):
            break
        m = _RESULT_RE.match(text)
        if m is None:
            continue
        key, value, unit = m.group(1), float(m.group(2)), m.group(3)
        key = _RENAME.get(key, key)
        if unit == "%":
            out[key] = quantity(value, "%")  # as surfmet states Mr1, Mr2, Rmr
        elif key in _AREAS and not unit and height_unit is not None:
            # printed in (height unit) x %: Rpk Mr1 / 2 with Mr1 in %
            out[key] = quantity(value * length_factor(height_unit) / 100.0, "m")
        elif unit:
            try:
                out[key] = quantity(value * length_factor(unit), "m")
            except SurfmetInputError:
                out[key] = quantity(value, unit)
                continue
            height_unit = height_unit or unit
        else:
            out[key] = quantity(value, "")
    return out, height_unit


def _conditions(certificate: Cells, data: Cells) -> dict[str, str]:
    """Label (lower case) -> printed value, from the Certificate pairs, else DATA codes."""
    found: dict[str, str] = {}
    for _, text in _column(data, "B"):
        if isinstance(text, str) and text.strip():
            code, _, value = text.strip().partition(" ")
            if code in _CODES:
                found[_CODES[code]] = value.strip()
    for (col, row), label in certificate.items():
        if not isinstance(label, str) or col not in ("B", "D"):
            continue
        cell = certificate.get((chr(ord(col) + 1), row))
        if isinstance(cell, str) and cell.strip() and label.strip():
            found[label.strip().lower()] = cell.strip()
        elif isinstance(cell, float) and label.strip():
            found[label.strip().lower()] = repr(cell)
    return found


def _length(text: str | None, name: str, what: str) -> tuple[float, str] | None:
    if not text:
        return None
    m = _LENGTH_RE.match(text)
    if m is None:
        raise _fail(name, f"{what} {text!r} is not a length")
    try:
        return float(m.group(1)) * length_factor(m.group(2)), m.group(2)
    except SurfmetInputError:
        raise _fail(name, f"{what} {text!r} has no length unit") from None


def _evaluation(found: dict[str, str], name: str) -> tuple[dict[str, Any], str | None]:
    """The evaluation conditions in SI, and the unit of the cut-off (= of the positions)."""
    ev: dict[str, Any] = {}
    std = found.get("standard")
    if std:
        ev["standard_text"] = std
        key = " ".join(std.lower().split())
        if key in _STANDARDS:
            ev["standard"] = _STANDARDS[key]
    cut = _length(found.get("cut-off"), name, "cut-off")
    if cut is not None:
        ev["lc"] = cut[0]
    ls = _length(found.get("λs"), name, "λs")
    if ls is not None:
        ev["ls"] = ls[0]
    if found.get("n"):
        try:
            ev["n_sampling"] = int(float(found["n"]))
        except ValueError:
            raise _fail(name, f"number of sampling lengths {found['n']!r} is not a number") \
                from None
    if found.get("profile"):
        ev["profile"] = found["profile"]
    if found.get("filter"):
        word = found["filter"].strip().lower()
        ev["filter"] = "gaussian" if word in ("gauss", "gaussian") else word
    ev = dict(sorted(ev.items(), key=lambda kv: _ORDER.index(kv[0])))
    if ev:
        # the instrument's Rk construction is part of how it evaluated: SurfTest reads
        # Rk, Rpk, Rvk, Mr1, Mr2, A1, A2 off the material-ratio curve tabulated at 1 %
        # levels (reproduced to the printed digits on the realdata export; the secant
        # construction differs by 6 % in Rpk, 16 % in Mr1)
        ev["rk_line"] = RK_LINE
        # and its profile elements (RSm, Rc) are paired from the first mean-line crossing
        # of each sampling length (RSm 419.9 µm, Rc 13.306 µm to the printed digits on the
        # same export; peak-first pairing gives 416.6 and 13.217)
        ev["element_start"] = ELEMENT_START
        ev["source"] = "Mitutoyo SurfTest export"
    return ev, (cut[1] if cut is not None else None)


def _positions_and_heights(data: Cells, name: str) -> tuple[np.ndarray, np.ndarray]:
    xs = dict((row, v) for row, v in _column(data, "E") if isinstance(v, float))
    zs = dict((row, v) for row, v in _column(data, "F") if isinstance(v, float))
    rows = sorted(set(xs) & set(zs))
    if len(rows) < 2:
        raise _fail(name, "the DATA sheet holds fewer than two points in columns E/F")
    if len(rows) != len(xs) or len(rows) != len(zs):
        raise _fail(name, "columns E (position) and F (height) of the DATA sheet differ in "
                          "length (damaged export?)")
    return np.array([xs[r] for r in rows]), np.array([zs[r] for r in rows])


def _date(certificate: Cells) -> str | None:
    text = certificate.get(("E", 2))
    if not isinstance(text, str):
        return None
    try:
        return _dt.datetime.strptime("".join(text.split()), "%d-%b-%Y").date().isoformat()
    except ValueError:
        return None


@register_reader(FORMAT, extensions=("xlsx",),
                 description="Mitutoyo SurfTest Excel export (profile + conditions)",
                 magic=_is_mitutoyo, priority=25)
def decode(buf: bytes, name: str) -> Profile:
    """Read the profile, the evaluation conditions and the printed results."""
    with open_zip(buf, name, FORMAT) as zf:
        paths = {k.strip().lower(): v for k, v in sheet_paths(zf, name, FORMAT).items()}
        if "data" not in paths:
            raise _fail(name, f"no sheet named DATA (sheets: {sorted(paths)})")
        strings = shared_strings(zf, name, FORMAT)
        data = read_cells(zf, paths["data"], strings, name, FORMAT)
        certificate = (read_cells(zf, paths["certificate"], strings, name, FORMAT)
                       if "certificate" in paths else {})
    results, height_unit = _results(data)
    evaluation, x_unit = _evaluation(_conditions(certificate, data), name)
    if height_unit is None:
        raise _fail(name, "no printed result with a length unit: the height unit is unknown")
    if x_unit is None:
        raise _fail(name, "no cut-off: the unit of the positions is unknown")
    x, z = _positions_and_heights(data, name)
    x = x * length_factor(x_unit)
    z = z * length_factor(height_unit)
    if not np.all(np.isfinite(x)) or not np.all(np.diff(x) > 0):
        raise _fail(name, "the positions (column E) are not finite and increasing")
    z[~np.isfinite(z)] = np.nan
    dx = check_step(float((x[-1] - x[0]) / (x.size - 1)), name, FORMAT, "mean step")
    md: dict[str, Any] = {
        "vendor": "Mitutoyo",
        "instrument": "SurfTest",
        "height_unit": height_unit,
        "lateral_unit": x_unit,
        "lateral_calibrated": True,
        "x_offset": quantity(float(x[0]), "m"),
    }
    date = _date(certificate)
    if date:
        md["date"] = date
    if evaluation:
        md["evaluation_conditions"] = evaluation
    if results:
        md["instrument_results"] = results
    return positions_profile(z, x, dx, _UNIFORM_RTOL, md)


__all__ = ["decode"]
