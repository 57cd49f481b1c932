"""Elastic and plastic constants of common contact materials, and the composite modulus.

Each entry holds Young's modulus ``E`` (Pa), Poisson's ratio ``nu`` and an indentation
hardness ``hardness`` (Pa), the flow pressure at which an elastic-perfectly-plastic contact
caps the pressure. The elastic constants are room-temperature handbook values; hardness
varies with heat treatment and temper by tens of percent, so the table's hardness is a
typical value and any measured value should override it (``material(name, hardness=...)``).

Sources
-------
- Steel and aluminium: E = 210 GPa, nu = 0.30 and E = 70 GPa, nu = 0.33, the textbook
  values that reproduce the Hertz figures of Alaci, Ciornei & Romanu (2022), Materials
  15:2518 (delta = 0.936 um, a = 136 um at 10 N, R = 20 mm).
- Other elastic constants: W. D. Callister & D. G. Rethwisch, *Materials Science and
  Engineering*, 9th ed., Wiley (2014), Table 6.1 and Appendix B; ASM Handbook vol. 2
  (1990) for the aluminium and copper alloys; manufacturers' data sheets for the
  ceramics.
- Hardness: Vickers hardness HV (kgf/mm^2) converted as H = 9.807 MPa * HV (ASTM E384);
  typical HV: hardened AISI 52100 bearing steel 750 (ASTM A295, 60-66 HRC), AISI 1020
  steel 130, 6061-T6 aluminium 107, annealed copper 50, C26000 brass 120, Ti-6Al-4V 349,
  soda-lime glass 550, fused silica 900, WC-6Co 1600, Si3N4 1550, alumina 1700,
  PMMA 20.

Composite modulus (Johnson 1985, *Contact Mechanics*, eq. 4.22)::

    1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2

and the "elastic compliance" P = 1/E* of Alaci et al. (2022), eq. (5).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

from contact._errors import ContactInputError

_HV = 9.807e6  # Pa per Vickers number (1 kgf/mm^2)


@dataclass(frozen=True)
class Material:
    """Isotropic elastic constants and an indentation hardness.

    Parameters
    ----------
    name : str
        Display name.
    E : float
        Young's modulus in Pa.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    hardness : float or None
        Indentation hardness in Pa (the plastic flow pressure), or None if unknown.
    source : str
        Where the numbers come from.

    Raises
    ------
    ContactInputError
        A modulus that is not positive, a Poisson's ratio outside (-1, 0.5] or a negative
        hardness.

    See Also
    --------
    material : a Material from the table.

    Examples
    --------
    >>> from contact import Material, composite_modulus
    >>> rubber = Material("rubber", E=5e6, nu=0.5)
    >>> glass = Material("glass", E=70e9, nu=0.22)
    >>> print(f"E* = {composite_modulus(rubber, glass) / 1e6:.2f} MPa")
    E* = 6.67 MPa
    """

    name: str
    E: float
    nu: float
    hardness: float | None = None
    source: str = "user"

    def __post_init__(self) -> None:
        if not (math.isfinite(self.E) and self.E > 0):
            raise ContactInputError(f"material {self.name!r}: E must be a positive modulus in Pa")
        if not (math.isfinite(self.nu) and -1.0 < self.nu <= 0.5):
            raise ContactInputError(
                f"material {self.name!r}: Poisson's ratio must lie in (-1, 0.5], got {self.nu}"
            )
        if self.hardness is not None and not (
            math.isfinite(self.hardness) and self.hardness > 0
        ):
            raise ContactInputError(
                f"material {self.name!r}: hardness must be a positive pressure in Pa"
            )

    @property
    def plane_strain_modulus(self) -> float:
        """E / (1 - nu^2) in Pa."""
        return self.E / (1.0 - self.nu**2)

    @property
    def surface_compliance(self) -> float:
        """(1 - nu^2) / E in 1/Pa: the body's share of the pair's compliance P = 1/E*
        (Johnson 1985, eq. 4.22), and the elastic creep series of the rolling solvers."""
        return (1.0 - self.nu**2) / self.E

    @property
    def shear_modulus(self) -> float:
        """The modulus of rigidity G = E / (2 (1 + nu)) in Pa."""
        return self.E / (2.0 * (1.0 + self.nu))


_CALLISTER = "Callister & Rethwisch (2014) Table 6.1"

MATERIALS: dict[str, Material] = {
    m.name: m
    for m in (
        Material("steel", 210e9, 0.30, 750 * _HV,
                 "Alaci et al. (2022) E, nu; hardened AISI 52100 bearing steel HV 750"),
        Material("mild_steel", 207e9, 0.30, 130 * _HV, f"{_CALLISTER}; AISI 1020 HV 130"),
        Material("aluminium", 70e9, 0.33, 107 * _HV,
                 "Alaci et al. (2022) E, nu; 6061-T6 HV 107 (ASM Handbook vol. 2)"),
        Material("copper", 110e9, 0.34, 50 * _HV, f"{_CALLISTER}; annealed C11000 HV 50"),
        Material("brass", 97e9, 0.34, 120 * _HV, f"{_CALLISTER}; C26000 half-hard HV 120"),
        Material("titanium", 114e9, 0.34, 349 * _HV, "ASM Handbook vol. 2: Ti-6Al-4V HV 349"),
        Material("glass", 72e9, 0.23, 550 * _HV, "soda-lime glass, data sheets: HV 550"),
        Material("fused_silica", 73e9, 0.17, 900 * _HV, "fused silica, data sheets: HV 900"),
        Material("tungsten_carbide", 620e9, 0.24, 1600 * _HV, "WC-6Co, data sheets: HV 1600"),
        Material("silicon_nitride", 310e9, 0.27, 1550 * _HV,
                 "bearing-grade Si3N4 (ASTM F2094), data sheets: HV 1550"),
        Material("alumina", 380e9, 0.22, 1700 * _HV, "99.5 % Al2O3, data sheets: HV 1700"),
        Material("pmma", 3.0e9, 0.37, 20 * _HV, "PMMA, data sheets: HV 20"),
    )
}

ALIASES: dict[str, str] = {
    "aluminum": "aluminium",
    "al": "aluminium",
    "aluminium_alloy": "aluminium",
    "bearing_steel": "steel",
    "52100": "steel",
    "aisi52100": "steel",
    "ti6al4v": "titanium",
    "ti": "titanium",
    "cu": "copper",
    "silica": "fused_silica",
    "wc": "tungsten_carbide",
    "si3n4": "silicon_nitride",
    "al2o3": "alumina",
    "sapphire": "alumina",
    "soda_lime_glass": "glass",
}


def material(
    name: str,
    *,
    E: float | None = None,
    nu: float | None = None,
    hardness: float | None = None,
) -> Material:
    """A material from the table, with any of its values overridden by the user's.

    Parameters
    ----------
    name : str
        Table name or alias (case-insensitive; ``-`` and spaces read as ``_``).
    E, nu, hardness : float, optional
        User values (Pa, -, Pa) that replace the table's. A name not in the table with
        both ``E`` and ``nu`` given is a custom material (hardness optional): a material
        given with all its elastic constants needs no table entry.

    Returns
    -------
    Material
        The constants, with ``source`` saying where they come from.

    Raises
    ------
    ContactInputError
        If the name is unknown and its constants are not all given, or an override is out
        of range.

    See Also
    --------
    MATERIALS : the table.
    composite_modulus : E* of two materials.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of
       Rolling Friction Moment on the Normal Force for Elastic Materials", Materials 15
       (2022) 2518: the steel and aluminium of the rotor rig.

    Examples
    --------
    >>> from contact import material
    >>> steel = material("steel")
    >>> print(f"E = {steel.E / 1e9:.0f} GPa, nu = {steel.nu}")
    E = 210 GPa, nu = 0.3
    >>> material("Mild Steel").name
    'mild_steel'
    >>> print(f"{material('aluminium', hardness=1.2e9).hardness / 1e9} GPa")
    1.2 GPa
    """
    key = name.strip().lower().replace("-", "_").replace(" ", "_")
    key = ALIASES.get(key, key)
    if key not in MATERIALS:
        if E is not None and nu is not None:
            return Material(name.strip(), E, nu, hardness,
                            "user-defined (constants given by the user)")
        known = ", ".join(sorted(MATERIALS))
        raise ContactInputError(
            f"unknown material {name!r}; known materials: {known}; or define it by giving "
            "its Young's modulus and Poisson's ratio (and optionally its hardness)")
    base = MATERIALS[key]
    given = (("E", E), ("nu", nu), ("hardness", hardness))
    changes: dict[str, Any] = {k: v for k, v in given if v is not None}
    if not changes:
        return base
    return dataclasses.replace(base, source=base.source + " (user overrides)", **changes)


def compliance(m1: Material, m2: Material) -> float:
    """The elastic compliance P = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 in 1/Pa (Alaci eq. 5).

    Parameters
    ----------
    m1, m2 : Material
        The two bodies.

    Returns
    -------
    float
        P in 1/Pa.

    See Also
    --------
    composite_modulus : its inverse.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), eq. (4.22).

    Examples
    --------
    >>> from contact import compliance, material
    >>> print(f"{compliance(material('steel'), material('aluminium')):.4e} 1/Pa")
    1.7063e-11 1/Pa
    """
    return m1.surface_compliance + m2.surface_compliance


def composite_modulus(m1: Material, m2: Material) -> float:
    """The composite (contact) modulus E* = 1/P in Pa (Johnson 1985, eq. 4.22).

    Parameters
    ----------
    m1, m2 : Material
        The two bodies.

    Returns
    -------
    float
        E* in Pa, ``1 / ((1 - nu1²)/E1 + (1 - nu2²)/E2)``.

    See Also
    --------
    compliance, contact.resolve_pair

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), eq. (4.22).

    Examples
    --------
    The steel ball on the aluminium plate of Alaci et al. (2022):

    >>> from contact import composite_modulus, material
    >>> print(f"E* = {composite_modulus(material('steel'), material('aluminium')) / 1e9:.2f} GPa")
    E* = 58.61 GPa
    """
    return 1.0 / compliance(m1, m2)


def contact_hardness(m1: Material, m2: Material) -> float | None:
    """The hardness that caps the contact pressure: that of the softer body (or None).

    Parameters
    ----------
    m1, m2 : Material
        The two bodies.

    Returns
    -------
    float or None
        The smaller of the known hardnesses in Pa; None when neither is known.

    Examples
    --------
    >>> from contact import contact_hardness, material
    >>> print(f"{contact_hardness(material('steel'), material('aluminium')) / 1e9:.2f} GPa")
    1.05 GPa
    """
    values = [m.hardness for m in (m1, m2) if m.hardness is not None]
    return min(values) if values else None


def displacement_shares(m1: Material, m2: Material) -> tuple[float, float]:
    """The fractions of the combined normal displacement taken by each body.

    Under the same pressure each half-space deflects in proportion to its own compliance
    (1 - nu^2)/E, so body ``i`` takes ``((1 - nu_i^2)/E_i) / P`` of the displacement the
    solver reports for the pair.

    Parameters
    ----------
    m1, m2 : Material
        The two bodies.

    Returns
    -------
    (float, float)
        The two shares; they sum to 1.

    See Also
    --------
    compliance

    Examples
    --------
    Aluminium, three times softer, takes three quarters of the deflection:

    >>> from contact import displacement_shares, material
    >>> s1, s2 = displacement_shares(material("steel"), material("aluminium"))
    >>> print(f"{s1:.3f} {s2:.3f}")
    0.254 0.746
    """
    p = compliance(m1, m2)
    return (m1.surface_compliance / p, m2.surface_compliance / p)

