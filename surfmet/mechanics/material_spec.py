"""Material specifications at the surfmet layer: text such as ``steel,aluminium`` or
``steel:E=200GPa:nu=0.29,aluminium:H=1.1GPa`` to :class:`contact.materials.Material`.

The table itself (values with their sources) lives in :mod:`contact.materials`; this module
only parses the user's text, with units, into it.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING, Any

from surfmet.errors import SurfmetInputError
from surfmet.units import parse_pressure

if TYPE_CHECKING:
    from surfmet.mechanics._types import Materials


def spec_options(opts: Iterable[str], what: str) -> Iterator[tuple[str, str]]:
    """The ``KEY=VALUE`` options of a ``NAME:KEY=VALUE:...`` text, one at a time, as
    (lower-case key, value); ``what`` names them in the message of one without ``=``."""
    for opt in opts:
        key, sep, value = opt.partition("=")
        if not sep:
            raise SurfmetInputError(f"cannot read {what} option {opt!r}: write KEY=VALUE")
        yield key.strip().lower(), value


def poisson_ratio(value: str) -> float:
    """Poisson's ratio from an option's text."""
    try:
        return float(value)
    except ValueError:
        raise SurfmetInputError(f"Poisson's ratio {value!r} is not a number") from None


def material_constant(value: str, what: str) -> float:
    """A modulus or hardness (Pa) from an option's text, with its unit required, as every
    typed pressure (:func:`surfmet.units.parse_pressure`; ``--hardness`` and ``--e-star``
    alike): ``E=200`` meant as GPa would otherwise be read as 200 Pa, a body 1e9 times too
    soft. No range is imposed (a gel's kPa and a "rigid" ball's 1e24 Pa are both legitimate
    inputs)."""
    try:
        return parse_pressure(value, example="GPa")
    except SurfmetInputError as exc:
        raise SurfmetInputError(f"{what}: {exc}") from None


def parse_material(text: str) -> Any:
    """``NAME[:E=..][:nu=..][:H=..]`` -> :class:`contact.materials.Material`.

    ``E`` and ``H`` take pressure units (``200GPa``, ``1.1GPa``); a bare number is
    refused. A name that is
    not in the table is a custom material when ``E`` and ``nu`` are both given
    (:func:`contact.materials.material`).
    """
    from contact.materials import material

    name, *opts = [s.strip() for s in str(text).split(":")]
    kw: dict[str, float] = {}
    for key, value in spec_options(opts, "material"):
        if key == "e":
            kw["E"] = material_constant(value, f"{name}: E")
        elif key in ("nu", "poisson"):
            kw["nu"] = poisson_ratio(value)
        elif key in ("h", "hardness"):
            kw["hardness"] = material_constant(value, f"{name}: H")
        else:
            raise SurfmetInputError(f"unknown material option {key!r}: use E, nu or H")
    return material(name, **kw)


def parse_materials(materials: Materials) -> tuple[Any, Any]:
    """``"BALL,PLATE"`` text, a pair of :class:`contact.materials.Material` or a resolved
    :class:`contact.material_pair.MaterialPair` -> ``(ball, plate)``."""
    from contact.material_pair import MaterialPair
    from contact.materials import Material

    if isinstance(materials, MaterialPair):
        if materials.body1 is None or materials.body2 is None:
            raise SurfmetInputError("this needs both bodies' materials, BALL,PLATE (not E* "
                                    "alone or a rigid body)")
        return materials.body1, materials.body2
    if isinstance(materials, (tuple, list)) and len(materials) == 2 and all(
            isinstance(m, Material) for m in materials):
        return materials[0], materials[1]
    if not isinstance(materials, str):
        raise SurfmetInputError(f"materials must be 'BALL,PLATE' text, got {materials!r}")
    parts = [s for s in materials.split(",") if s.strip()]
    if len(parts) != 2:
        raise SurfmetInputError(f"materials need two names, BALL,PLATE; got {materials!r}")
    return parse_material(parts[0]), parse_material(parts[1])


def material_pair(materials: Materials | None = None, *, e_star: float | None = None,
                  hardness: float | None = None, rigid_flat: bool = False) -> Any:
    """The resolved pair (:class:`contact.material_pair.MaterialPair`) of the user's materials.

    ``materials`` is ``"BALL,PLATE"`` text (or ``"A"``, a body on a rigid flat, where
    ``rigid_flat`` allows it), a pair of :class:`contact.materials.Material`, or an already
    resolved pair; or give ``e_star`` (Pa) instead. ``hardness`` (Pa) replaces the softer
    body's table value.
    """
    from contact.material_pair import MaterialPair, resolve_pair

    if isinstance(materials, MaterialPair):
        if e_star is not None:
            raise SurfmetInputError("give the materials or E*, not both")
        return materials.with_hardness(hardness)
    if materials is None:
        if e_star is None:
            raise SurfmetInputError("give the materials (--materials) or E* (--e-star)")
        return resolve_pair(e_star=e_star, hardness=hardness)
    if e_star is not None:
        raise SurfmetInputError("give the materials or E*, not both")
    if (rigid_flat and isinstance(materials, str)
            and len([s for s in materials.split(",") if s.strip()]) == 1):
        return resolve_pair(parse_material(materials.strip(" ,")), hardness=hardness)
    return resolve_pair(*parse_materials(materials), hardness=hardness)


def scan_pair(materials: Materials | None = None, *, e_star: float | None = None,
              hardness: float | None = None) -> Any:
    """The pair of a scan pressed on a flat (``spectrum``, ``flat-contact``): ``"A"`` (the
    scan's material on a rigid flat), ``"A,B"`` (on an elastic flat of B), a resolved pair,
    or ``e_star`` (Pa) instead; ``hardness`` (Pa) replaces the softer body's table value
    (:func:`material_pair` with ``rigid_flat``)."""
    if isinstance(materials, str) and len([s for s in materials.split(",")
                                           if s.strip()]) not in (1, 2):
        raise SurfmetInputError(f"--materials takes A or A,B; got {materials!r}")
    return material_pair(materials, e_star=e_star, hardness=hardness, rigid_flat=True)
