"""Dektak stylus profilometer CSV export (profile, non-uniform x).

The export is a comma-separated text file (Latin-1, CRLF) in three sections, each headed
by a line holding only its title::

    Scan Parameters
    Scan Type,Standard Scan
    Stylus,Radius: 2.5 µm
    Length,1500.0 um
    Duration,32 sec
    Resolution,0.156 um/sample
    Force,3.00 mg
    Measurement Range,524 um
    R. Cursor,Pos: 100.0 um Width: 0.0 um
    ...

    Analytical Results
    Function,R.Cur Pos,R.Cur Width,M.Cur Pos,M.Cur Width,Result
    Ra,468.0 um,0.0 um,733.0 um,0.0 um,0.00525 um
    Skew,468.0 um,0.0 um,733.0 um,0.0 um,6.96
    ...

    Scan Data
    Lateral um,Raw Micrometer,
    0.0,-0.00933,,
    0.2,-0.00760,,

The lateral positions are printed to 0.1 µm while the sampling step is 0.156 µm, so the
positions are not evenly spaced: the profile is returned with explicit ``x`` positions
(``Profile.is_uniform`` is False) unless the steps are equal to 1e-3 relative.

Metadata (SI, quantities as ``{"value", "unit"}``):

``tip_radius``            stylus radius (``Stylus,Radius: 2.5 µm``)
``scan_length``, ``resolution``, ``measurement_range``, ``scan_duration`` (s)
``stylus_force``          the stylus load in newtons; the export states it as a mass
                          (``3.00 mg``), converted with standard gravity 9.80665 m/s²
``cursors``               the display cursors R and M of the header (position, width)
``instrument_results``    the instrument's own analysis, e.g.
                          ``{"Ra": {"value": 5.25e-9, "unit": "m"}, "Skew": {"value": 6.96,
                          "unit": ""}, ...}``
``instrument_results_cursors``  per function, the R and M cursor positions and widths
                          between which the instrument computed it
``evaluation_range``      ``{"start", "end"}``: the R and M cursor positions, when every
                          result row shares them (468 µm and 733 µm in the example)
``scan_parameters``       every header line as written
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from surfmet._errors import SurfmetFormatError, SurfmetInputError
from surfmet._model import Profile
from surfmet.io._binary import decode_text, format_error, looks_like_text, positions_profile
from surfmet.io._registry import register_reader
from surfmet.units import length_factor, quantity

FORMAT = "dektak"
G_STANDARD = 9.80665  # m/s², converts the force stated as a mass
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_QTY_RE = re.compile(rf"^\s*({_NUMBER})\s*([^\s\d,][^,]*?)?\s*$")
_CURSOR_RE = re.compile(rf"Pos:\s*({_NUMBER})\s*(\S+)\s+Width:\s*({_NUMBER})\s*(\S+)", re.I)
_SECTIONS = ("scan parameters", "analytical results", "scan data")
_MASS = {"mg": 1e-6, "g": 1e-3, "ug": 1e-9, "µg": 1e-9}
_UNIFORM_RTOL = 1e-3


def _fail(name: str, problem: str) -> SurfmetFormatError:
    return format_error(name, FORMAT, problem)


def _is_dektak(buf: bytes) -> bool:
    if not looks_like_text(buf[:2048]):
        return False
    head = decode_text(buf[:4096]).lstrip()
    first = head.split("\n", 1)[0].strip().rstrip(",").strip()
    if first.lower() == "scan parameters":
        return True
    return bool(re.search(r"^Scan Data\s*,*\s*$", head, re.M)) and "Lateral" in head


def _unit_factor(unit: str) -> float | None:
    u = unit.strip().replace("Â", "")
    try:
        return length_factor(u)
    except SurfmetInputError:
        return None


def _length_q(text: str) -> dict[str, Any] | None:
    m = _QTY_RE.match(text)
    if not m or not m.group(2):
        return None
    unit = m.group(2).split("/")[0].strip()
    f = _unit_factor(unit)
    if f is None:
        return None
    return quantity(float(m.group(1)) * f, "m")


def _result_q(text: str) -> dict[str, Any] | None:
    # "0.00525 um" -> metres; "6.96" -> dimensionless; anything else: None
    m = _QTY_RE.match(text)
    if not m:
        return None
    value = float(m.group(1))
    unit = (m.group(2) or "").strip()
    if not unit:
        return quantity(value, "")
    f = _unit_factor(unit)
    if f is not None:
        return quantity(value * f, "m")
    return quantity(value, unit)


def _canonical(unit: str, factor: float) -> str:
    for symbol, f in (("m", 1.0), ("mm", 1e-3), ("um", 1e-6), ("nm", 1e-9), ("Å", 1e-10)):
        if abs(factor - f) <= 1e-12 * f:
            return symbol
    return unit


def _column_unit(title: str) -> tuple[str, float] | None:
    # "Lateral um" -> ("um", 1e-6); "Raw Micrometer" -> ("Micrometer", 1e-6);
    # "Total Profile (Å)" -> ("Å", 1e-10)
    words = re.split(r"[\s()\[\]]+", title.strip())
    for w in reversed([w for w in words if w]):
        f = _unit_factor(w)
        if f is not None:
            return _canonical(w, f), f
    return None


def _parameters(md: dict[str, Any], params: dict[str, str]) -> None:
    def length(key: str, target: str) -> None:
        if key in params and (q := _length_q(params[key])) is not None:
            md[target] = q

    stylus = params.get("Stylus", "")
    m = re.search(rf"Radius:\s*({_NUMBER})\s*(\S+)", stylus)
    if m and (f := _unit_factor(m.group(2))) is not None:
        md["tip_radius"] = quantity(float(m.group(1)) * f, "m")
    length("Length", "scan_length")
    length("Resolution", "resolution")
    length("Measurement Range", "measurement_range")
    if (m := re.match(rf"^\s*({_NUMBER})\s*(s|sec|seconds?)\s*$", params.get("Duration", ""))):
        md["scan_duration"] = quantity(float(m.group(1)), "s")
    force = params.get("Force", "")
    if (m := re.match(rf"^\s*({_NUMBER})\s*(\S+)\s*$", force)):
        unit = m.group(2).lower().replace("μ", "µ")
        if unit in _MASS:
            md["stylus_force"] = quantity(float(m.group(1)) * _MASS[unit] * G_STANDARD, "N")
        elif unit in ("n", "mn", "un", "µn"):
            scale = {"n": 1.0, "mn": 1e-3, "un": 1e-6, "µn": 1e-6}[unit]
            md["stylus_force"] = quantity(float(m.group(1)) * scale, "N")
    for key, short in (("R. Cursor", "R"), ("M. Cursor", "M")):
        c = _CURSOR_RE.search(params.get(key, ""))
        if c:
            fp, fw = _unit_factor(c.group(2)), _unit_factor(c.group(4))
            if fp is not None and fw is not None:
                md.setdefault("cursors", {})[short] = {
                    "position": quantity(float(c.group(1)) * fp, "m"),
                    "width": quantity(float(c.group(3)) * fw, "m"),
                }
    for key, target in (("Scan Type", "scan_type"), ("Profile", "profile_mode"),
                        ("ID", "scan_id")):
        if params.get(key):
            md[target] = params[key].strip()


def _results(md: dict[str, Any], rows: list[list[str]]) -> None:
    if not rows:
        return
    titles = [t.strip().lower() for t in rows[0]]
    if not titles or titles[0] != "function":
        return
    col = {t: i for i, t in enumerate(titles)}
    results: dict[str, Any] = {}
    cursors: dict[str, Any] = {}
    for row in rows[1:]:
        if not row or not row[0].strip():
            continue
        fn = row[0].strip()
        cells = {t: (row[i].strip() if i < len(row) else "") for t, i in col.items()}
        q = _result_q(cells.get("result", ""))
        if q is None:
            continue
        results[fn] = q
        cur: dict[str, Any] = {}
        for key, out in (("r.cur pos", "R"), ("r.cur width", "R_width"),
                         ("m.cur pos", "M"), ("m.cur width", "M_width")):
            if (c := _length_q(cells.get(key, ""))) is not None:
                cur[out] = c
        if cur:
            cursors[fn] = cur
    if results:
        md["instrument_results"] = results
    if cursors:
        md["instrument_results_cursors"] = cursors
        pairs = {(c.get("R", {}).get("value"), c.get("M", {}).get("value"))
                 for c in cursors.values()}
        if len(pairs) == 1:
            start, end = pairs.pop()
            if start is not None and end is not None:
                md["evaluation_range"] = {"start": quantity(min(start, end), "m"),
                                          "end": quantity(max(start, end), "m")}


def _sections(lines: list[str]) -> tuple[dict[str, str], list[list[str]], int | None]:
    """Scan parameters, analytical-result rows and the first line after 'Scan Data'."""
    section = ""
    params: dict[str, str] = {}
    result_rows: list[list[str]] = []
    data_start = None
    for k, line in enumerate(lines):
        stripped = line.strip().rstrip(",").strip()
        if not stripped:
            continue
        if stripped.lower() in _SECTIONS:
            section = stripped.lower()
            if section == "scan data":
                data_start = k + 1
                break
            continue
        if section == "scan parameters" or not section:
            if "," in line:
                key, value = line.split(",", 1)
                params[key.strip()] = value.strip()
        elif section == "analytical results":
            result_rows.append(line.split(","))
    return params, result_rows, data_start


def _columns(lines: list[str], first: int, xu: tuple[str, float], zu: tuple[str, float],
             name: str) -> tuple[np.ndarray, np.ndarray]:
    """The x and z columns from line ``first`` on, in metres."""
    xs: list[str] = []
    zs: list[str] = []
    for j in range(first, len(lines)):
        line = lines[j].strip()
        if not line:
            continue
        cells = line.split(",")
        if len(cells) < 2:
            raise _fail(name, f"data line {j + 1} ({line[:40]!r}) has fewer than two columns")
        xs.append(cells[0].strip())
        zs.append(cells[1].strip() or "nan")
    if not xs:
        raise _fail(name, "the 'Scan Data' section holds no points")
    try:
        x = np.array(xs, dtype=np.float64) * xu[1]
        z = np.array(zs, dtype=np.float64) * zu[1]
    except ValueError:
        raise _fail(name, "a data value is not a number (damaged file?)") from None
    return x, z


@register_reader(FORMAT, extensions=("csv",), description="Dektak profilometer CSV export",
                 magic=_is_dektak, priority=40)
def decode(buf: bytes, name: str) -> Profile:
    """Read a Dektak CSV export into a :class:`~surfmet._model.Profile`."""
    lines = decode_text(buf).splitlines()
    params, result_rows, data_start = _sections(lines)
    if data_start is None:
        raise _fail(name, "no 'Scan Data' section (truncated file?)")

    # Column titles, then rows "x,z[,...]"
    k = data_start
    while k < len(lines) and not lines[k].strip():
        k += 1
    if k >= len(lines):
        raise _fail(name, "the 'Scan Data' section is empty")
    titles = [t.strip() for t in lines[k].split(",")]
    if len(titles) < 2:
        raise _fail(name, f"cannot read the data column titles {lines[k][:60]!r}")
    xu = _column_unit(titles[0])
    zu = _column_unit(titles[1])
    if xu is None or zu is None:
        raise _fail(name, f"no length units in the column titles {titles[:2]!r}")
    x, z = _columns(lines, k + 1, xu, zu, name)
    if not np.all(np.isfinite(x)):
        raise _fail(name, "a lateral position is not finite")
    z[~np.isfinite(z)] = np.nan
    steps = np.diff(x)
    if x.size > 1 and not np.all(steps > 0):
        bad = int(np.argmax(~(steps > 0)))
        raise _fail(name, f"lateral positions must increase; data line {bad + 2} goes from "
                          f"{x[bad]:.6g} m to {x[bad + 1]:.6g} m")
    if x.size < 2:
        raise _fail(name, "a profile needs at least two points")
    mean_step = float((x[-1] - x[0]) / (x.size - 1))

    md: dict[str, Any] = {
        "instrument": "Dektak",
        "height_unit": zu[0],
        "lateral_unit": xu[0],
        "lateral_calibrated": True,
        "x_offset": quantity(float(x[0]), "m"),
        "columns": titles[:2],
        "scan_parameters": params,
    }
    _parameters(md, params)
    _results(md, result_rows)
    # A CSV cut at a line boundary still parses: compare the span with the stated length.
    span = float(x[-1] - x[0])
    if "scan_length" in md:
        stated = md["scan_length"]["value"]
        tolerance = 2 * md["resolution"]["value"] if "resolution" in md else 0.01 * stated
        if stated and span < stated - max(tolerance, 1e-3 * stated):
            raise _fail(name, f"truncated: the data span {span * 1e6:.6g} µm but the header "
                              f"states a scan length of {stated * 1e6:.6g} µm")
    return positions_profile(z, x, mean_step, _UNIFORM_RTOL, md)


__all__ = ["G_STANDARD", "decode"]
