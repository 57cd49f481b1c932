"""Material specifications at the surfmet layer: text such as ``steel,aluminium`` or
``steel:E=200GPa:nu=0.29,aluminium:H=1.1GPa`` to :class:`contact._materials.Material`.

The table itself (values with their sources) lives in :mod:`contact._materials`; this module
only parses the user's text, with units, into it.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING, Any

from surfmet._errors import SurfmetInputError
from surfmet.units import parse_pressure

if TYPE_CHECKING:
    from surfmet.mechanics._types import Materials


def spec_options(opts: Iterable[str], what: str) -> Iterator[tuple[str, str]]:
    """The ``KEY=VALUE`` options of a ``NAME:KEY=VALUE:...`` text, one at a time, as
    (lower-case key, value); ``what`` names them in the message of one without ``=``.

    Parameters
    ----------
    opts : iterable of str
        The ``KEY=VALUE`` parts after the name.
    what : str
        What they are options of, for the message.

    Yields
    ------
    (str, str)
        Lower-case key and its value text.

    Raises
    ------
    SurfmetInputError
        A part without ``=``.

    Examples
    --------
    >>> from surfmet.mechanics.material_spec import spec_options
    >>> list(spec_options(["E=70GPa", "NU=0.33"], "material"))
    [('e', '70GPa'), ('nu', '0.33')]
    """
    for opt in opts:
        key, sep, value = opt.partition("=")
        if not sep:
            raise SurfmetInputError(f"cannot read {what} option {opt!r}: write KEY=VALUE")
        yield key.strip().lower(), value


def poisson_ratio(value: str) -> float:
    """Poisson's ratio from an option's text.

    Parameters
    ----------
    value : str
        The option's text.

    Returns
    -------
    float
        The ratio (its range is checked by :class:`contact._materials.Material`).

    Raises
    ------
    SurfmetInputError
        Text that is not a number.

    Examples
    --------
    >>> from surfmet.mechanics.material_spec import poisson_ratio
    >>> poisson_ratio("0.33")
    0.33
    >>> poisson_ratio("half")
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetInputError: Poisson's ratio 'half' is not a number
    """
    try:
        return float(value)
    except ValueError:
        raise SurfmetInputError(f"Poisson's ratio {value!r} is not a number") from None


def material_constant(value: str, what: str) -> float:
    """A modulus or hardness (Pa) from an option's text, with its unit required, as every
    typed pressure (:func:`surfmet.units.parse_pressure`; ``--hardness`` and ``--e-star``
    alike): ``E=200`` meant as GPa would otherwise be read as 200 Pa, a body 1e9 times too
    soft. No range is imposed (a gel's kPa and a "rigid" ball's 1e24 Pa are both legitimate
    inputs).

    Parameters
    ----------
    value : str
        The option's text, with a pressure unit.
    what : str
        The option's name, for the message.

    Returns
    -------
    float
        The value in Pa.

    Raises
    ------
    SurfmetInputError
        A bare number or an unknown unit.

    See Also
    --------
    surfmet.units.parse_pressure

    Examples
    --------
    >>> from surfmet.mechanics.material_spec import material_constant
    >>> material_constant("70GPa", "E")
    70000000000.0
    >>> material_constant("70", "E")
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetInputError: E: pressure '70' has no unit: write it with one, ...
    """
    try:
        return parse_pressure(value, example="GPa")
    except SurfmetInputError as exc:
        raise SurfmetInputError(f"{what}: {exc}") from None


def parse_material(text: str) -> Any:
    """``NAME[:E=..][:nu=..][:H=..]`` -> :class:`contact._materials.Material`.

    ``E`` and ``H`` take pressure units (``200GPa``, ``1.1GPa``); a bare number is
    refused. A name that is
    not in the table is a custom material when ``E`` and ``nu`` are both given
    (:func:`contact._materials.material`).

    Parameters
    ----------
    text : str
        ``NAME[:E=..][:nu=..][:H=..]``.

    Returns
    -------
    contact._materials.Material
        The material, the user's values replacing the table's.

    Raises
    ------
    SurfmetInputError, ContactInputError
        An unreadable option, or an unknown name without both ``E`` and ``nu``.

    See Also
    --------
    contact.material : the table.

    Examples
    --------
    >>> from surfmet.mechanics.material_spec import parse_material
    >>> al = parse_material("al:H=0.9GPa")
    >>> print(al.name, f"E = {al.E / 1e9:.0f} GPa, H = {al.hardness / 1e9} GPa")
    aluminium E = 70 GPa, H = 0.9 GPa
    >>> parse_material("gel:E=50kPa:nu=0.5").E
    50000.0
    """
    from contact._materials import material

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
    """``"BALL,PLATE"`` text, a pair of :class:`contact._materials.Material` or a resolved
    :class:`contact._material_pair.MaterialPair` -> ``(ball, plate)``.

    Parameters
    ----------
    materials : str, (Material, Material) or MaterialPair
        The pair.

    Returns
    -------
    (Material, Material)
        Ball and plate.

    Raises
    ------
    SurfmetInputError
        Text without two names.

    Examples
    --------
    >>> from surfmet.mechanics.material_spec import parse_materials
    >>> [m.name for m in parse_materials("steel,al")]
    ['steel', 'aluminium']
    >>> parse_materials("steel")
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetInputError: materials need two names, BALL,PLATE; got 'steel'
    """
    from contact._material_pair import MaterialPair
    from contact._materials import Material

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
    """The resolved pair (:class:`contact._material_pair.MaterialPair`) of the user's materials.

    ``materials`` is ``"BALL,PLATE"`` text (or ``"A"``, a body on a rigid flat, where
    ``rigid_flat`` allows it), a pair of :class:`contact._materials.Material`, or an already
    resolved pair; or give ``e_star`` (Pa) instead. ``hardness`` (Pa) replaces the softer
    body's table value.

    Parameters
    ----------
    materials : str, (Material, Material) or MaterialPair, optional
        The bodies.
    e_star : float, optional
        Composite modulus (Pa), instead of ``materials``.
    hardness : float, optional
        The user's hardness (Pa).
    rigid_flat : bool
        Allow a single name (a body on a rigid flat).

    Returns
    -------
    contact._material_pair.MaterialPair
        E*, the default hardness and its source.

    Raises
    ------
    SurfmetInputError, ContactInputError
        Unreadable or unknown materials, both or neither of ``materials`` and ``e_star``.

    See Also
    --------
    contact.resolve_pair : the engine's resolution.

    Examples
    --------
    >>> from surfmet.mechanics.material_spec import material_pair
    >>> pair = material_pair("steel,aluminium")
    >>> print(f"E* = {pair.e_star / 1e9:.2f} GPa, H = {pair.hardness / 1e9:.2f} GPa")
    E* = 58.61 GPa, H = 1.05 GPa
    """
    from contact._material_pair import MaterialPair, resolve_pair

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
    (:func:`material_pair` with ``rigid_flat``).

    Returns
    -------
    contact._material_pair.MaterialPair
        The pair.

    Raises
    ------
    SurfmetInputError, ContactInputError
        As for :func:`material_pair`.

    Examples
    --------
    An aluminium scan on a rigid flat: E* = E / (1 - ν²):

    >>> from surfmet.mechanics.material_spec import scan_pair
    >>> pair = scan_pair("aluminium")
    >>> print(pair.names, f"E* = {pair.e_star / 1e9:.2f} GPa", f"{70 / (1 - 0.33 ** 2):.2f}")
    ['aluminium'] E* = 78.55 GPa 78.55
    """
    if isinstance(materials, str) and len([s for s in materials.split(",")
                                           if s.strip()]) not in (1, 2):
        raise SurfmetInputError(f"--materials takes A or A,B; got {materials!r}")
    return material_pair(materials, e_star=e_star, hardness=hardness, rigid_flat=True)
