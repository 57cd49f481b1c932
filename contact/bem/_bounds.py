"""The pressure bounds of a normal contact: tensile bound, hardness cap, interaction law.

Every normal solve carries one :class:`PressureBounds` instead of a bare cap. The three
parts are

- ``tensile``: the largest tension (Pa, >= 0) a touching point may carry. 0 is the
  non-adhesive contact p >= 0 (Johnson 1985, ch. 13 conventions).
- ``hardness``: the cap p <= H of an elastic-perfectly-plastic contact (Almqvist et al.
  2007, Wear 262:1321); ``inf`` for an elastic one.
- ``interaction``: a gap-dependent surface traction (an adhesion law of
  :mod:`contact.adhesion.laws`), or None. With a law the pressure at an open point is not
  0 but the law's traction at the local gap, and the tension a touching point can carry
  is the law's traction at zero gap.

The Polonsky-Keer iteration of :mod:`contact.bem` treats the non-adhesive bounds
(``tensile == 0``, no interaction); an adhesive set of bounds is solved by
:func:`contact.adhesion.solve_adhesive`, and :func:`contact.bem.solve_normal` says so
rather than silently dropping the tension.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from contact._errors import ContactInputError

if TYPE_CHECKING:  # the laws need nothing from the BEM; only the annotation refers to them
    from contact.adhesion.laws import InteractionLaw


@dataclass(frozen=True)
class PressureBounds:
    """Bounds on the contact pressure p (Pa, compression positive).

    Attributes
    ----------
    tensile : float
        Largest tension a touching point carries (Pa, >= 0): p >= -tensile.
    hardness : float
        Cap of the compressive pressure (Pa, > 0); ``inf`` for an elastic contact.
    interaction : InteractionLaw or None
        Gap-dependent adhesive traction; None for a contact without adhesion.

    Examples
    --------
    >>> from contact import PressureBounds
    >>> PressureBounds.elastic(1e9).plastic, PressureBounds().is_adhesive
    (True, False)
    """

    tensile: float = 0.0
    hardness: float = math.inf
    interaction: InteractionLaw | None = None

    def __post_init__(self) -> None:
        if not (math.isfinite(self.tensile) and self.tensile >= 0.0):
            raise ContactInputError(
                f"the tensile bound must be a finite tension >= 0 Pa, got {self.tensile!r}")
        if not (self.hardness > 0.0):  # inf is allowed, NaN is not
            raise ContactInputError(f"the hardness must be positive, got {self.hardness!r}")

    @classmethod
    def elastic(cls, hardness: float | None = None) -> PressureBounds:
        """The non-adhesive bounds 0 <= p <= H (``hardness`` None: no cap)."""
        return cls(hardness=math.inf if hardness is None else float(hardness))

    @classmethod
    def adhesive(cls, law: InteractionLaw, hardness: float | None = None) -> PressureBounds:
        """Bounds with an adhesion law: tension down to the law's zero-gap traction."""
        return cls(tensile=float(law.traction(0.0)),
                   hardness=math.inf if hardness is None else float(hardness),
                   interaction=law)

    @property
    def plastic(self) -> bool:
        """A finite hardness cap: the elastic-perfectly-plastic path."""
        return math.isfinite(self.hardness)

    @property
    def is_adhesive(self) -> bool:
        """Tension allowed, or a gap-dependent traction to solve for."""
        return self.tensile > 0.0 or self.interaction is not None
