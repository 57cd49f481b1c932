"""The adhesion laws the commands name: every law of the engine's one table
(:mod:`contact.adhesion.laws`: ``dugdale`` (Maugis 1992), ``exponential``, ...), built by
name from its parameters, and the name of a law back."""

from __future__ import annotations

from typing import TYPE_CHECKING

from surfmet._errors import SurfmetInputError

if TYPE_CHECKING:
    from surfmet.mechanics._types import AdhesionLaw

__all__ = ["INTERACTION", "interaction_law", "interaction_name"]

#: The adhesion law of every command and facade unless told otherwise: the one with a
#: closed form to check it by (Maugis 1992: the sphere's pull-off, tests/maugis_reference.py)
#: and the one the coarse-grid threshold is measured on
#: (:data:`contact._zone_resolution.MIN_ZONE_PIXELS`).
INTERACTION = "dugdale"


def interaction_law(interaction: str | AdhesionLaw, work: float | None = None,
                    range_: float | None = None, **parameters: float) -> AdhesionLaw:
    """The adhesion law named ``interaction`` of its parameters: work ``work`` (J/m^2) and
    range ``range_`` (m) for the laws stated by the two (h0 = w / sigma0 for
    ``"dugdale"``, rho for ``"exponential"``), the keywords of its table entry for another;
    or ``interaction`` itself where it is a law.

    Parameters
    ----------
    interaction : str or InteractionLaw
        The law's name (:func:`contact.adhesion.laws.law_names`), or a law.
    work : float, optional
        Work of adhesion (J/m²).
    range_ : float, optional
        Its range (m).
    **parameters : float
        The parameters of a law of other numbers (SI; its ``parameters``).

    Returns
    -------
    InteractionLaw
        The law (:mod:`contact.adhesion.laws`).

    Raises
    ------
    SurfmetInputError
        For an unknown name or object, a parameter the law does not take or one it needs.

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
    from contact._errors import ContactInputError
    from contact.adhesion.laws import build_law, checked_law

    try:
        if not isinstance(interaction, str):
            if work is not None or range_ is not None or parameters:
                raise SurfmetInputError("give a law, or a law's name and its parameters, "
                                        "not both")
            return checked_law(interaction)
        return build_law(interaction, work_of_adhesion=work, range_=range_, **parameters)
    except ContactInputError as exc:
        raise SurfmetInputError(str(exc)) from None


def interaction_name(law: AdhesionLaw) -> str:
    """The name of an adhesion law, as the table registers it (``"dugdale"``, ...).

    Parameters
    ----------
    law : InteractionLaw
        A registered adhesion law.

    Returns
    -------
    str
        Its name.

    Raises
    ------
    SurfmetInputError
        Where ``law`` is not a registered law.

    Examples
    --------
    >>> from surfmet.mechanics.adhesion_laws import interaction_law, interaction_name
    >>> interaction_name(interaction_law("dugdale", 0.05, 1e-9))
    'dugdale'
    """
    return interaction_law(law).name
