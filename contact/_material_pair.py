"""The resolved material pair: the one place two bodies become the constants of a contact.

Every entry point (the ``surfmet`` commands, the mechanics facades, the rotor's budget)
turns its materials, or a bare composite modulus, into a :class:`MaterialPair` through
:func:`resolve_pair`, and reads E*, the default hardness and where it came from, the
Poisson ratios and moduli of rigidity, the displacement shares and Kalker's constants
from it, so no two places can resolve the same pair differently.

- Composite modulus 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson 1985, *Contact
  Mechanics*, eq. 4.22); a rigid counterpart adds no compliance.
- Default hardness: the softer body's (:func:`contact._materials.contact_hardness`).
- Displacement shares: body i takes ((1 - nu_i^2)/E_i) E* of the combined normal
  displacement (:func:`contact._materials.displacement_shares`).
- Kalker's constants G, nu, K (Kalker 1990, *Three-dimensional elastic bodies in rolling
  contact*, sec. 1.5) and Dundurs' beta = K/(1 - nu) (Johnson 1985, sec. 5.1), from the
  tangential solver's ``pair_constants``.

Two E* of one pair, kept apart on purpose: :attr:`MaterialPair.e_star` is 1/P from the
compliances (1 - nu_i^2)/E_i, and is the E* of every normal facade (``contact.setups``,
``contact._hertzcheck``, ``contact.adhesion``, the hysteresis and plastic sweeps, the
mechanisms); ``constants().e_star`` is G/(1 - nu) from Kalker's combined constants, and is
the E* of the tangential and viscoelastic-traction solvers' own normal solves
(``contact.tangential``, ``contact.viscoelastic._traction3d``). They are the same number in
exact arithmetic and differ by rounding (1 ulp for steel on aluminium); each solver family
keeps its own, so neither's outputs change bit for bit.

Every facade that takes ``e_star`` also takes a :class:`MaterialPair` there
(:func:`modulus`); a pair's default hardness is applied by the surfmet facades (their
``plastic`` switches), never silently by a solver, where a hardness turns the solve
elastic-plastic.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

from contact._errors import ContactInputError
from contact._materials import Material, composite_modulus, contact_hardness, displacement_shares


@dataclass(frozen=True)
class MaterialPair:
    """The two bodies of a contact, resolved once: every constant a solver needs of them.

    Build it with :func:`resolve_pair`. Body 1 is the ball (or the scan pressed on a flat),
    the body that receives +q in the tangential problem; body 2 is the plate. A body of
    ``None`` is rigid; a pair with neither body is one given by its composite modulus alone
    (``--e-star``), which has no Poisson's ratios and so no Kalker constants or shares.

    Attributes
    ----------
    body1, body2 : Material or None
        The bodies (None: rigid, or unknown when the pair is given by E* alone).
    e_star : float
        Composite modulus E* = 1/P in Pa, P the summed compliances (Johnson 1985, eq. 4.22).
    hardness : float or None
        The default flow pressure (Pa): the user's, else the softer body's table value.
    hardness_source : str
        Where ``hardness`` comes from: ``"given"`` (the user's, for the pair), ``"material:
        NAME"`` (that body's hardness: the table's, or the user's override of it) or ``"none"``.

    See Also
    --------
    resolve_pair : makes it.

    Examples
    --------
    >>> from contact import material, resolve_pair
    >>> pair = resolve_pair(material("steel"), material("aluminium"))
    >>> print(f"E* = {pair.e_star / 1e9:.2f} GPa, H = {pair.hardness / 1e9:.2f} GPa "
    ...       f"({pair.hardness_source})")
    E* = 58.61 GPa, H = 1.05 GPa (material: aluminium)
    """

    body1: Material | None
    body2: Material | None
    e_star: float
    hardness: float | None
    hardness_source: str

    @property
    def from_e_star(self) -> bool:
        """True for a pair given by its composite modulus alone (no bodies)."""
        return self.body1 is None and self.body2 is None

    def _bodies(self, what: str) -> tuple[Material, Material]:
        if self.body1 is None or self.body2 is None:
            raise ContactInputError(
                f"{what} need both bodies' materials (E and nu), not a composite modulus "
                "or a rigid body; give the materials")
        return self.body1, self.body2

    @property
    def names(self) -> list[str]:
        """The bodies' material names, ball (or scan) first; none for a pair given by E*."""
        return [m.name for m in (self.body1, self.body2) if m is not None]

    @property
    def nu(self) -> tuple[float, float]:
        """Poisson's ratios (nu1, nu2)."""
        b1, b2 = self._bodies("Poisson's ratios")
        return b1.nu, b2.nu

    @property
    def shear_moduli(self) -> tuple[float, float]:
        """Moduli of rigidity (G1, G2) in Pa."""
        b1, b2 = self._bodies("the moduli of rigidity")
        return b1.shear_modulus, b2.shear_modulus

    @property
    def shares(self) -> tuple[float, float]:
        """Fractions of the combined normal displacement each body takes (a rigid body 0):
        body i deflects in proportion to its own compliance (1 - nu_i^2)/E_i."""
        if self.from_e_star:
            raise ContactInputError("the displacement shares need the bodies' materials")
        if self.body1 is None or self.body2 is None:
            return (0.0, 1.0) if self.body1 is None else (1.0, 0.0)
        return displacement_shares(self.body1, self.body2)

    def constants(self) -> Any:
        """Kalker's combined constants G, nu, K (``PairConstants``, Kalker 1990 sec. 1.5):
        K is the difference parameter that couples the normal and tangential problems.
        Its ``e_star`` = G/(1 - nu) may differ from :attr:`e_star` by rounding (module
        notes): the tangential solvers use that one."""
        from contact.tangential import pair_constants

        return pair_constants(*self._bodies("Kalker's constants"))

    @property
    def kalker_k(self) -> float:
        """Kalker's difference parameter K (0 for quasi-identical bodies)."""
        return float(self.constants().K)

    @property
    def beta(self) -> float:
        """Dundurs' second parameter beta = K/(1 - nu) of the pair."""
        return float(self.constants().beta)

    def with_hardness(self, hardness: float | None) -> MaterialPair:
        """The pair with the user's hardness (Pa) in place of the default; None keeps it."""
        if hardness is None:
            return self
        return dataclasses.replace(self, hardness=_hardness_value(hardness),
                                   hardness_source="given")


def _hardness_value(hardness: float) -> float:
    h = float(hardness)
    if not (math.isfinite(h) and h > 0):
        raise ContactInputError(f"the hardness must be a positive pressure in Pa, got {hardness!r}")
    return h


def resolve_pair(
    body1: Material | None = None,
    body2: Material | None = None,
    *,
    e_star: float | None = None,
    hardness: float | None = None,
) -> MaterialPair:
    """The one place materials become E*, the default hardness and their provenance.

    Parameters
    ----------
    body1, body2 : Material, optional
        Ball (or scan) and plate. Only ``body1``: it is pressed on a rigid flat.
    e_star : float, optional
        Composite modulus (Pa), instead of the bodies.
    hardness : float, optional
        The user's hardness (Pa), replacing the softer body's table value.

    Returns
    -------
    MaterialPair
        E*, the default hardness and where it comes from.

    Raises
    ------
    ContactInputError
        Neither or both of bodies and ``e_star``; a non-positive E* or hardness.

    See Also
    --------
    contact.composite_modulus : E* of two materials.
    contact.solve_sphere : takes a pair for its ``e_star``.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), eq. (4.22).

    Examples
    --------
    >>> from contact import material, resolve_pair
    >>> pair = resolve_pair(material("steel"))          # a steel body on a rigid flat
    >>> print(f"{pair.e_star / 1e9:.1f} GPa", pair.hardness_source)
    230.8 GPa material: steel
    >>> resolve_pair(e_star=1e9).hardness is None
    True
    >>> resolve_pair()
    Traceback (most recent call last):
    ...
    contact._errors.ContactInputError: give the materials (at least the first body) or E*
    """
    if e_star is not None:
        if body1 is not None or body2 is not None:
            raise ContactInputError("give the materials or E*, not both")
        e = float(e_star)
        if not (math.isfinite(e) and e > 0):
            raise ContactInputError(f"E* must be a positive modulus in Pa, got {e_star!r}")
        pair = MaterialPair(None, None, e, None, "none")
        return pair.with_hardness(hardness)
    if body1 is None:
        raise ContactInputError("give the materials (at least the first body) or E*")
    if body2 is None:
        # 1/C1 (not E/(1 - nu^2), a different float): the compliance sum with a rigid body
        e, h, src = 1.0 / body1.surface_compliance, body1.hardness, body1
    else:
        e, h = composite_modulus(body1, body2), contact_hardness(body1, body2)
        src = body1 if h is not None and h == body1.hardness else body2
    pair = MaterialPair(body1, body2, e, h, "none" if h is None else f"material: {src.name}")
    return pair.with_hardness(hardness)


def modulus(e_star: float | MaterialPair) -> float:
    """The composite modulus E* (Pa) a contact facade was given: a resolved pair's
    :attr:`MaterialPair.e_star`, or the bare number itself (the array-level form).

    Every facade of ``contact/`` that takes ``e_star`` passes it through here first, so a
    pair and its ``e_star`` give the same solve bit for bit. A number is returned as it
    came, for the facade's own check of it.
    """
    return e_star.e_star if isinstance(e_star, MaterialPair) else e_star
