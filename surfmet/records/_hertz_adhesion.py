"""The JSON record of the adhesion section of ``hertz-check``
(:func:`surfmet.mechanics.hertz_adhesion.assess_adhesion`)."""

from __future__ import annotations

from typing import Any

from surfmet.units import quantity

__all__ = ["hertz_adhesion_record"]


def hertz_adhesion_record(a: Any) -> dict[str, Any]:
    """The JSON record (every value {value, unit}).

    Parameters
    ----------
    a : surfmet.mechanics.hertz_adhesion.HertzAdhesion
        The assessment.

    Returns
    -------
    dict
        Every value as ``{"value": v, "unit": u}``.

    Examples
    --------
    >>> from surfmet.mechanics.hertz_adhesion import assess_adhesion
    >>> from surfmet.records._hertz_adhesion import hertz_adhesion_record
    >>> rec = hertz_adhesion_record(assess_adhesion(None, radius=0.02, load=10.0,
    ...                                             e_star=58.6e9, work=0.05))
    >>> rec["jkr_pull_off_force"]["unit"], rec["adhesion_changes_contact"]
    ('N', False)
    """
    return {
        "work_of_adhesion": quantity(a.work, "J/m^2"),
        "range": quantity(a.range, "m"),
        "tabor_parameter_contact": quantity(a.tabor_contact, ""),
        "summit_radius": quantity(a.summit_radius, "m"),
        "tabor_parameter_asperity": quantity(a.tabor_asperity, ""),
        "slope_rms": quantity(a.slope_rms, ""),
        "curvature_rms": quantity(a.curvature_rms, "1/m"),
        "pastewka_robbins_parameter": quantity(a.pastewka_robbins, ""),
        "sticky": a.sticky,
        "dmt_pull_off_force": quantity(a.dmt_pull_off, "N"),
        "jkr_pull_off_force": quantity(a.jkr_pull_off, "N"),
        "adhesion_changes_contact": a.changes_contact,
        "reason": a.reason,
        "sources": [
            "Tabor 1977, J. Colloid Interface Sci. 58:2 (mu = (R w^2 / (E*^2 z0^3))^(1/3))",
            "Pastewka & Robbins 2014, PNAS 111:3298, eq. 10 (kappa_rep = 2, "
            "d_rep = 4 h'_rms / h''_rms; sticky below 1)",
            "Derjaguin, Muller & Toporov 1975; Johnson, Kendall & Roberts 1971 (pull-off)",
        ],
    }
