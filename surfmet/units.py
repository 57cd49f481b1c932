"""Units at the edges: parsing command-line quantities, naming file units, JSON quantities.

Inside surfmet every value is SI (m, Pa, N). Conversions happen only here, in readers
(file unit to metre) and in output (JSON and display).
"""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Mapping
from typing import Any

from surfmet._errors import SurfmetInputError

# Symbols accepted on the command line and in file headers. Both the micro sign (U+00B5)
# and the Greek mu (U+03BC) occur in real files.
LENGTH_UNITS: Mapping[str, float] = {
    "m": 1.0,
    "cm": 1e-2,
    "mm": 1e-3,
    "um": 1e-6,
    "µm": 1e-6,
    "μm": 1e-6,
    "nm": 1e-9,
    "pm": 1e-12,
    "a": 1e-10,
    "å": 1e-10,
}

# Spelled-out forms found in instrument headers.
_LENGTH_ALIASES: Mapping[str, str] = {
    "meter": "m",
    "meters": "m",
    "metre": "m",
    "metres": "m",
    "millimeter": "mm",
    "millimeters": "mm",
    "millimetre": "mm",
    "micrometer": "um",
    "micrometers": "um",
    "micrometre": "um",
    "micron": "um",
    "microns": "um",
    "mic": "um",
    "nanometer": "nm",
    "nanometers": "nm",
    "nanometre": "nm",
    "angstrom": "a",
    "centimeter": "cm",
}

# Units a user types (command line, material options, API text), matched exactly: SI
# prefixes are case-sensitive (m is milli, M is mega), so "10MN" is not "10mN" and "1mPa"
# is not "1MPa". File headers, which spell units in capitals or in words, are read with
# :func:`length_factor` instead.
TYPED_LENGTH_UNITS: Mapping[str, float] = {
    **{k: v for k, v in LENGTH_UNITS.items() if k not in ("a", "å")}, "Å": 1e-10,
}
FORCE_UNITS: Mapping[str, float] = {
    "N": 1.0, "kN": 1e3, "mN": 1e-3, "uN": 1e-6, "µN": 1e-6, "μN": 1e-6,
}
PRESSURE_UNITS: Mapping[str, float] = {
    "Pa": 1.0,
    "kPa": 1e3,
    "MPa": 1e6,
    "GPa": 1e9,
    "N/mm2": 1e6,
    "N/mm^2": 1e6,
    "N/mm²": 1e6,
}
#: Work of adhesion (surface energy per area); N/m is the same unit (a line tension).
SURFACE_ENERGY_UNITS: Mapping[str, float] = {
    "J/m2": 1.0, "J/m^2": 1.0, "J/m²": 1.0, "mJ/m2": 1e-3, "mJ/m^2": 1e-3, "mJ/m²": 1e-3,
    "N/m": 1.0, "mN/m": 1e-3,
}

SPEED_UNITS: Mapping[str, float] = {
    "m/s": 1.0, "cm/s": 1e-2, "mm/s": 1e-3, "um/s": 1e-6, "µm/s": 1e-6, "km/h": 1 / 3.6,
}

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_QUANTITY_RE = re.compile(rf"^\s*({_NUMBER})\s*([^\s\d].*?)?\s*$")


def length_factor(unit: str) -> float:
    """Metres per ``unit``, for a unit name as it appears in a file header.

    Parameters
    ----------
    unit : str
        ``"mm"``, ``"um"``, ``"µm"``, ``"micrometer"``, ``"nm"``, ``"m"``...

    Raises
    ------
    SurfmetInputError
        If the unit is not a length unit.
    """
    key = unit.strip().lower().rstrip(".")
    key = _LENGTH_ALIASES.get(key, key)
    if key in LENGTH_UNITS:
        return LENGTH_UNITS[key]
    # Keep the case-sensitive micro signs working after lower().
    if unit.strip() in LENGTH_UNITS:
        return LENGTH_UNITS[unit.strip()]
    raise SurfmetInputError(f"unknown length unit {unit!r}; use one of nm, um, µm, mm, m")


def _typed_factor(unit: str, table: Mapping[str, float], kind: str, text: str) -> float:
    """The factor of a unit a user typed, matched exactly; an unknown spelling, or one that
    differs from an accepted unit only in case, is one error naming the accepted units."""
    if unit in table:
        return table[unit]
    accepted = ", ".join(table)
    near = [k for k in table if k.lower() == unit.lower()]
    if near:
        raise SurfmetInputError(
            f"unit {unit!r} in {kind} {text!r} is not {near[0]!r}: SI prefixes are "
            f"case-sensitive (m = milli, M = mega); accepted: {accepted}")
    raise SurfmetInputError(f"unknown unit {unit!r} in {kind} {text!r}; accepted: {accepted}")


def _parse(text: str, table: Mapping[str, float], kind: str, default: str,
           unit_required: bool = False) -> float:
    if not isinstance(text, str):
        value = float(text)
        if not math.isfinite(value):
            raise SurfmetInputError(f"{kind} must be finite, got {text!r}")
        return value
    m = _QUANTITY_RE.match(text)
    if not m:
        raise SurfmetInputError(
            f"cannot read {kind} {text!r}: write a number with an optional unit, e.g. "
            f"'1.5{default}'"
        )
    number = float(m.group(1))
    unit = (m.group(2) or "").strip()
    if unit_required and not unit:
        raise SurfmetInputError(
            f"{kind} {text!r} has no unit: write it with one, e.g. '{text.strip()}{default}'; "
            f"accepted: {', '.join(table)}")
    factor = _typed_factor(unit, table, kind, text) if unit else 1.0
    value = number * factor
    if not math.isfinite(value):
        raise SurfmetInputError(f"{kind} {text!r} is not finite")
    if 0 < abs(value) < sys.float_info.min:  # subnormal: no physical value is that small
        raise SurfmetInputError(f"{kind} {text!r} is too small to compute with (below "
                                f"{sys.float_info.min:.3g} in SI units)")
    return value


def parse_length(text: str | float) -> float:
    """Parse a length such as ``"468um"``, ``"0.5 mm"``, ``"20mm"`` or ``"2e-6"`` to metres.

    A bare number is taken in metres (SI).
    """
    return _parse(text, TYPED_LENGTH_UNITS, "length", "um")


def parse_force(text: str | float) -> float:
    """Parse a force such as ``"10N"``, ``"4.7 N"`` or ``"500mN"`` to newtons."""
    return _parse(text, FORCE_UNITS, "force", "N")


def parse_pressure(text: str | float, *, unit_required: bool = True,
                   example: str = "MPa") -> float:
    """Parse a pressure such as ``"1.2GPa"`` or ``"300 MPa"`` to pascals.

    Typed text needs its unit, wherever a pressure is typed (applied pressures,
    ``--hardness``, ``--e-star``, a material's ``E=`` and ``H=``): a bare ``200`` meant as
    GPa would be read 1e9 times too small, and ``--hardness 1`` as 1 Pa. This is the one
    exception to "a bare number is SI" (:func:`bare_number_note`). A number (not text),
    as the Python API passes it, is pascals. ``example`` is the unit the refusal suggests.
    """
    return _parse(text, PRESSURE_UNITS, "pressure", example, unit_required)


def parse_speed(text: str | float) -> float:
    """Parse a speed such as ``"1m/s"``, ``"50 mm/s"`` or ``"0.1"`` (m/s) to m/s."""
    return _parse(text, SPEED_UNITS, "speed", "m/s")


def parse_surface_energy(text: str | float) -> float:
    """Parse a work of adhesion such as ``"0.05J/m2"``, ``"50 mJ/m^2"`` to J/m^2."""
    return _parse(text, SURFACE_ENERGY_UNITS, "work of adhesion", "J/m2")


def parse_length_range(text: str) -> tuple[float, float]:
    """Parse ``"X0:X1"`` (each a length with optional unit) into metres, X0 < X1."""
    parts = text.split(":")
    if len(parts) != 2:
        raise SurfmetInputError(f"cannot read range {text!r}: write START:END, e.g. 468um:733um")
    lo, hi = parse_length(parts[0]), parse_length(parts[1])
    if not hi > lo:
        raise SurfmetInputError(f"range {text!r} is empty: END must exceed START")
    return lo, hi


def is_bare_number(text: Any) -> bool:
    """Whether ``text`` (as typed) is a number without a unit, e.g. ``"20"``."""
    if not isinstance(text, str):
        return False
    m = _QUANTITY_RE.match(text)
    return m is not None and not (m.group(2) or "").strip()


#: The largest bare length (m) read without comment: a bare number is metres, and a ball,
#: a cut-off or a domain of more than a metre is almost always millimetres meant.
BARE_LENGTH_LIMIT = 1.0


def bare_number_note(text: Any, value: float, kind: str = "length") -> str | None:
    """How a bare number that is implausible in SI was read, for a note on stderr
    (``"20 read as 20 m; write 20mm for millimetres"``), or None.

    The rule for every quantity typed on the command line is one: a bare number is SI
    (metres, newtons, m/s), except a pressure, modulus or hardness, which needs its unit
    (:func:`parse_pressure`). A bare length over :data:`BARE_LENGTH_LIMIT` is accepted as
    metres, and this note says so."""
    if kind == "length" and is_bare_number(text) and abs(value) > BARE_LENGTH_LIMIT:
        t = str(text).strip()
        return f"{t} read as {t} m (a bare number is metres); write {t}mm for millimetres"
    return None


#: Every unit a JSON record may state: SI symbols in ASCII with powers as ``^n``
#: (``m^2``, ``rad/s^2``, ``1/m^2``), ``""`` for a dimensionless value, and the few
#: non-SI names the records need (``%``, ``°``, ``frame``). A record with a unit outside
#: this set is a bug (``tests/test_cli_conventions.py`` walks every command's JSON).
JSON_UNITS: frozenset[str] = frozenset({
    "", "%", "°", "frame",
    "m", "m^2", "m^3", "m^4", "1/m", "1/m^2", "rad/m",
    "N", "N/m", "N m", "Pa", "Pa/m", "J", "J/m", "J/m^2", "W", "W/(m/s)", "W/(m/s)/m",
    "m/s", "s", "1/s", "1/s^2", "rad", "rad/s", "rad/s^2", "rad/s^2/m", "kg", "kg m^2",
})


def csv_column(name: str, unit: str) -> str:
    """A CSV column's header: ``"Sa [m]"``, ``"load [N]"``, the name alone for a
    dimensionless value. One convention for every CSV surfmet writes (``roughness --csv``,
    ``sweep --csv``): the name, then its JSON unit (:data:`JSON_UNITS`) in brackets, the
    values below in that unit (SI)."""
    return f"{name} [{unit}]" if unit else name


def quantity(value: Any, unit: str) -> dict[str, Any]:
    """A JSON quantity ``{"value": v, "unit": unit}``; NaN and inf become ``None``."""
    return {"value": jsonable(value), "unit": unit}


def valid_text(text: str) -> str:
    """``text`` as valid Unicode: the bytes of a file name that are not UTF-8 (which
    Python holds as lone surrogates, PEP 383) written as ``\\xNN`` escapes, as Python's
    ``repr`` and ``ls -b`` show them, so that JSON, CSV and HTML outputs stay valid UTF-8
    and the name can still be read. Text without such bytes is returned unchanged."""
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return text.encode("utf-8", "surrogateescape").decode("utf-8", "backslashreplace")
    return text


def jsonable(obj: Any) -> Any:
    """Convert ``obj`` recursively into plain JSON types.

    Mappings become dicts, sequences and arrays become lists, NumPy scalars become Python
    numbers, NaN and inf become ``None``, bytes are decoded, text is made valid Unicode
    (:func:`valid_text`), anything else unknown is turned into its ``str``.
    """
    import numpy as np

    if obj is None or isinstance(obj, bool):
        return obj
    if isinstance(obj, str):
        return valid_text(obj)
    if isinstance(obj, Mapping):
        return {valid_text(str(k)): jsonable(v) for k, v in obj.items()}
    if isinstance(obj, np.ndarray):
        return [jsonable(v) for v in obj.tolist()]
    if isinstance(obj, (list, tuple)):
        return [jsonable(v) for v in obj]
    if isinstance(obj, np.generic):
        obj = obj.item()
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, int):
        return obj
    if isinstance(obj, (bytes, bytearray)):
        return bytes(obj).decode("utf-8", errors="replace")
    if hasattr(obj, "isoformat"):
        return obj.isoformat()
    return valid_text(str(obj))


#: The display units of each JSON unit (largest first): text shows a value in the first
#: whose factor it reaches (else the last), so that it reads as 3.725 nm, 203.8 MPa,
#: 12.5 µm². JSON states every value in SI with the ASCII unit on the left (powers
#: as ``^``: ``m^2``, ``1/m^2``; ``""`` for a dimensionless value); text and figures show
#: it through :func:`split_quantity` / :func:`format_quantity`, in these units.
DISPLAY_UNITS: dict[str, tuple[tuple[str, float], ...]] = {
    "m": (("m", 1.0), ("mm", 1e-3), ("µm", 1e-6), ("nm", 1e-9)),
    "m^2": (("m²", 1.0), ("mm²", 1e-6), ("µm²", 1e-12), ("nm²", 1e-18)),
    # one display unit each, whatever the value: Spd in 1/m² for one scan and 1/mm² for
    # the next could not be compared by eye (ISO 25178 states Spd in 1/mm²)
    "1/m": (("1/µm", 1e6),),
    "1/m^2": (("1/mm²", 1e6),),
    "Pa": (("GPa", 1e9), ("MPa", 1e6), ("kPa", 1e3), ("Pa", 1.0)),
    "N": (("kN", 1e3), ("N", 1.0), ("mN", 1e-3), ("µN", 1e-6), ("nN", 1e-9)),
    "N/m": (("N/mm", 1e3), ("N/m", 1.0)),
    "J/m^2": (("J/m²", 1.0), ("mJ/m²", 1e-3)),
    "W": (("W", 1.0), ("mW", 1e-3), ("µW", 1e-6), ("nW", 1e-9)),
}


def display_unit(unit: str) -> str:
    """A JSON unit as text shows it: powers as superscripts, no unit for ``""``/``"1"``."""
    if unit in ("", "1"):
        return ""
    return unit.replace("^-1", "⁻¹").replace("^2", "²").replace("^3", "³")


def split_quantity(value: float | None, unit: str, digits: int = 4) -> tuple[str, str]:
    """``(number, unit)`` text of an SI value in its most readable display unit
    (:data:`DISPLAY_UNITS`); ``("n/a", unit)`` for a missing or non-finite value."""
    if value is None or not math.isfinite(value):
        return "n/a", display_unit(unit)
    scales = DISPLAY_UNITS.get(unit)
    if scales is None:
        return f"{value:.{digits}g}", display_unit(unit)
    a = abs(value)
    shown, f = next(((u, f) for u, f in scales if a >= f), scales[-1])
    x = value / f
    # 37267 µm², not 3.727e+04 µm²: whole digits are never cut to an exponent
    whole = int(math.log10(abs(x))) + 1 if abs(x) >= 1 else 0
    return f"{x:.{max(digits, whole)}g}", shown


def format_quantity(value: float | None, unit: str, digits: int = 4) -> str:
    """One value with its unit for text output (:func:`split_quantity`), e.g.
    ``format_quantity(2.037e8, "Pa") == "203.7 MPa"``."""
    if value is None or not math.isfinite(value):
        return "n/a"
    number, shown = split_quantity(value, unit, digits)
    return f"{number} {shown}".rstrip()


def format_length(value: float, digits: int = 4) -> str:
    """Human display of a length in the most readable of nm, µm, mm, m."""
    return format_quantity(value, "m", digits)


#: an SI value as the engines write it in their messages: ``1.45e-05 m``, ``3e+07 Pa``
_ENGINE_QUANTITY = re.compile(
    r"(?<![\w.^/])(-?\d+(?:\.\d+)?(?:e[+-]?\d+)?) (m\^2|m|Pa|N/m|N)(?![\w^²/])")


def readable_quantities(text: str) -> str:
    """``text`` (an engine's message, which cannot use :func:`format_quantity`: the
    engines never import surfmet) with each SI value written as :func:`format_quantity`
    writes it, with as many digits as the engine gave (at least 3):
    ``"zone (= 1.45e-05 m)"`` becomes ``"zone (= 14.5 µm)"``."""

    def one(m: re.Match[str]) -> str:
        number, unit = m.group(1), m.group(2)
        mantissa = number.lstrip("-").split("e")[0].replace(".", "").lstrip("0")
        return format_quantity(float(number), unit, max(3, min(len(mantissa), 6)))

    return _ENGINE_QUANTITY.sub(one, text)
