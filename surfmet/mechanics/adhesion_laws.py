"""The adhesion laws the commands name: ``dugdale`` (Maugis 1992) and ``exponential``,
built from the work of adhesion and the range (:mod:`contact.adhesion.laws`), and the name
of a law back."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from surfmet.errors import SurfmetInputError

if TYPE_CHECKING:
    from surfmet.mechanics._types import AdhesionLaw

__all__ = ["INTERACTION", "INTERACTIONS", "interaction_law", "interaction_name"]

INTERACTIONS = ("dugdale", "exponential")
#: The adhesion law of every command and facade unless told otherwise: the one with a
#: closed form to check it by (Maugis 1992: the sphere's pull-off, tests/maugis_reference.py)
#: and the one the coarse-grid threshold is measured on
#: (:data:`contact.zone_resolution.MIN_ZONE_PIXELS`).
INTERACTION = "dugdale"


def interaction_law(interaction: str, work: float, range_: float) -> Any:
    """The adhesion law named ``interaction`` of work ``work`` (J/m^2) and range ``range_``
    (m): h0 = w / sigma0 for ``"dugdale"``, rho for ``"exponential"``.

    Parameters
    ----------
    interaction : {"dugdale", "exponential"}
        The law's name.
    work : float
        Work of adhesion (J/m²).
    range_ : float
        Its range (m).

    Returns
    -------
    DugdaleLaw or ExponentialLaw
        The law (:mod:`contact.adhesion.laws`).

    See Also
    --------
    interaction_name : the inverse.

    References
    ----------
    .. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
       J. Colloid Interface Sci. 150 (1992) 243-269.

    Examples
    --------
    >>> from surfmet.mechanics.adhesion_laws import interaction_law, interaction_name
    >>> law = interaction_law("exponential", 0.05, 1e-9)
    >>> law, interaction_name(law)
    (ExponentialLaw(work=0.05, rho=1e-09), 'exponential')
    """
    from contact.adhesion.laws import DugdaleLaw, ExponentialLaw

    if interaction not in INTERACTIONS:
        raise SurfmetInputError(f"unknown interaction {interaction!r}: use "
                                f"{' or '.join(INTERACTIONS)}")
    return (DugdaleLaw.from_range(work, range_) if interaction == "dugdale"
            else ExponentialLaw(work, range_))


def interaction_name(law: AdhesionLaw) -> str:
    """``"dugdale"`` or ``"exponential"``: the name of an adhesion law.

    Parameters
    ----------
    law : DugdaleLaw or ExponentialLaw
        An adhesion law.

    Returns
    -------
    str
        Its name.

    Examples
    --------
    >>> from surfmet.mechanics.adhesion_laws import interaction_law, interaction_name
    >>> interaction_name(interaction_law("dugdale", 0.05, 1e-9))
    'dugdale'
    """
    return "dugdale" if hasattr(law, "sigma0") else "exponential"
