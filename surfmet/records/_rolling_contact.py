"""The JSON records of a steady rolling solve with friction (``surfmet rolling-contact``):
elastic (:func:`surfmet.mechanics.rolling_contact.solve_rolling_contact`) and viscoelastic
(:func:`surfmet.mechanics.viscoelastic_rolling_contact.viscoelastic_rolling_contact`), in
one vocabulary: the same keys, sign convention and grid record, every value with its
unit."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from surfmet.mechanics.rolling_contact import RESISTANCE_DEFINITION, SIGN_CONVENTION
from surfmet.mechanics.viscoelastic_rolling_contact import (
    QUASI_IDENTICAL_K,
    VISCO_RESISTANCE_DEFINITION,
)
from surfmet.records._solve import solve_record
from surfmet.units import quantity

__all__ = ["rolling_contact_record", "visco_rolling_contact_record"]


def rolling_contact_record(rc: Any) -> dict[str, Any]:
    """The JSON record of a solve: every value with its unit.

    Parameters
    ----------
    rc : surfmet.mechanics.rolling_contact.RollingContact
        A solve.

    Returns
    -------
    dict
        Every value as ``{"value": v, "unit": u}``.

    Examples
    --------
    >>> from surfmet.mechanics.rolling_contact import solve_rolling_contact
    >>> from surfmet.records._rolling_contact import rolling_contact_record
    >>> rec = rolling_contact_record(solve_rolling_contact(0.02, 10.0, "steel,steel", 0.3,
    ...                                                    creepage=1e-4, grid=32))
    >>> rec["creepage"], rec["pmax"]["unit"]
    ({'value': 0.0001, 'unit': ''}, 'Pa')
    """
    from contact.tangential._results import edge_note

    r = rc.result
    per = "/m" if rc.line else ""
    area = "m" if rc.line else "m^2"  # units as surfmet.units.DISPLAY_UNITS spells them
    rec: dict[str, Any] = {
        "sign_convention": SIGN_CONVENTION,
        "geometry": "cylinder on flat, plane strain" if rc.line else "sphere on flat",
        "free_rolling": rc.free_rolling,
        "radius": quantity(rc.radius, "m"),
        "load": quantity(rc.load, "N" + per),
        "mu": r.mu,
        "grid": {"elements": rc.grid, "element_size": quantity(r.grid.dx, "m"),
                 "domain_side": quantity(rc.side, "m")},
        "creepage": quantity(r.creepage.xi, ""),
        "fx": quantity(r.fx, "N" + per),
        "fy": quantity(r.fy, "N" + per),
        "pmax": quantity(r.pmax, "Pa"),
        "approach": quantity(r.approach, "m"),
        "contact_area": quantity(r.contact_area, area),
        "stick_area": quantity(r.stick_area, area),
        "slip_area": quantity(r.slip_area, area),
        "frictional_power": quantity(r.frictional_power, "W/(m/s)" + per),
        "edge_dissipation_share": quantity(r.edge_dissipation_share, ""),
        "rolling_resistance_coefficient": quantity(r.rolling_resistance_coefficient, ""),
        "pressure_moment_coefficient": quantity(r.pressure_moment_coefficient(rc.radius),
                                                ""),
        "rolling_resistance_definition": RESISTANCE_DEFINITION,
        # convergence, stated as ``contact`` states it (a solve that does not converge
        # raises instead of returning): the solve record's
        "iterations": r.solve.iterations,
        "residual": quantity(r.solve.residual, ""),
        "converged": r.solve.converged,
        "solve": solve_record(r.solve),
        "solver": {"tolerance": r.tol, "coupling_iterations": r.iterations,
                   "operator_products": r.matvecs},
        "kalker_K": r.constants.K,
        "dundurs_beta": r.constants.beta,
    }
    notes = list(rc.notes)
    note = edge_note(r.edge_dissipation_share)
    if note is not None:
        notes.append(note)
    if notes:
        rec["notes"] = notes
    if rc.line:
        rec["approach_note"] = ("plane strain: the approach depends on the datum of the "
                                "2D displacement and is given for the grid's own datum")
    if rc.speed is not None:
        rec["speed"] = quantity(rc.speed, "m/s")
        rec["frictional_power_at_speed"] = quantity(r.frictional_power * rc.speed, "W" + per)
    return rec


def visco_rolling_contact_record(vc: Any) -> dict[str, Any]:
    """The JSON record, keyed as the elastic one
    (:func:`rolling_contact_record`).

    Parameters
    ----------
    vc : surfmet.mechanics.viscoelastic_rolling_contact.ViscoRollingContact
        A solve.

    Returns
    -------
    dict
        Every value as ``{"value": v, "unit": u}``.

    Examples
    --------
    >>> from surfmet.mechanics.viscoelastic_rolling_contact import (
    ...     viscoelastic_rolling_contact)
    >>> from surfmet.records._rolling_contact import visco_rolling_contact_record
    >>> vc = viscoelastic_rolling_contact(radius=0.02, load=10.0, materials="steel,pmma",
    ...                                   viscoelastic=["plate:Eg=3GPa:Er=1GPa:tau=1ms"],
    ...                                   speed=0.01, grid=32)
    >>> rec = visco_rolling_contact_record(vc)
    >>> rec["geometry"], rec["speed"]
    ('sphere on flat', {'value': 0.01, 'unit': 'm/s'})
    """
    r = vc.normal
    per = "/m" if vc.line else ""
    area = "m" if vc.line else "m^2"
    dx = float(r.x[1] - r.x[0])
    cell = dx if vc.line else dx * float(r.y[1] - r.y[0])
    coupled = max(abs(k) for k in vc.kalker_k) > QUASI_IDENTICAL_K
    tangential = ("no friction given (--mu)" if vc.mu is None else vc.not_solved
                  or "solved (plane strain, quasi-identical bodies: K = 0)" if vc.line
                  else "solved (3D, the coupling of K one way)" if coupled
                  else "solved (3D, quasi-identical bodies: K = 0)")
    rec: dict[str, Any] = {
        "sign_convention": SIGN_CONVENTION,
        "geometry": "cylinder on flat, plane strain" if vc.line else "sphere on flat",
        "model": "viscoelastic steady rolling, normal problem" + (
            f" and tangential tractions ({'plane strain' if vc.line else '3D'}, "
            + ("coupling one way)" if coupled and not vc.line else "quasi-identical bodies)")
            if vc.traction is not None else
            " (frictionless)" if vc.mu is None else " (tangential problem not solved)"),
        "free_rolling": vc.free_rolling,
        "radius": quantity(vc.radius, "m"),
        "load": quantity(vc.load, "N" + per),
        "speed": quantity(r.speed, "m/s"),
        "mu": vc.mu,
        "grid": {"elements": vc.grid, "element_size": quantity(dx, "m"),
                 "domain_side": quantity(dx * r.x.size, "m")},
        "tangential": {"solved": vc.traction is not None, "status": tangential},
        **_traction_fields(vc, per, area),
        "pmax": quantity(r.pmax, "Pa"),
        "approach": quantity(r.approach, "m"),
        "contact_area": quantity(float(np.count_nonzero(np.asarray(r.pressure) > 0)) * cell,
                                 area),
        "rolling_resistance_coefficient": quantity(r.rolling_resistance, ""),
        "rolling_resistance_definition": VISCO_RESISTANCE_DEFINITION,
        "pressure_offset": quantity(r.pressure_offset, "m"),
        "leading_edge": quantity(r.leading, "m"),
        "trailing_edge": quantity(r.trailing, "m"),
        "solve": solve_record(r.solve),
        "kalker_K_glassy": vc.kalker_k[0],
        "kalker_K_relaxed": vc.kalker_k[1],
    }
    if vc.traction is not None:
        rec["traction_solve"] = solve_record(vc.traction.solve)
    notes = [*vc.notes, *([vc.not_solved] if vc.not_solved else [])]
    if vc.line:
        rec["approach_note"] = ("plane strain: the approach depends on the datum of the "
                                "2D displacement and is given for the grid's own datum")
    if notes:
        rec["notes"] = notes
    return rec


def _traction_fields(vc: Any, per: str, area: str) -> dict[str, Any]:
    """creepage, fx, fy, stick and slip extent, frictional power: only where solved."""
    tr = vc.traction
    if tr is None:
        return {}
    if vc.line:
        dx = float(vc.normal.x[1] - vc.normal.x[0])
        return {"creepage": quantity(tr.creepage, ""), "fx": quantity(tr.force, "N" + per),
                "stick_area": quantity(float(tr.stick.sum()) * dx, area),
                "slip_area": quantity(float(tr.slip.sum()) * dx, area)}
    power = tr.frictional_power
    out = {"creepage": quantity(tr.creepage.xi, ""), "fx": quantity(tr.fx, "N"),
           "fy": quantity(tr.fy, "N"), "stick_area": quantity(tr.stick_area, area),
           "slip_area": quantity(tr.slip_area, area),
           "frictional_power": quantity(power, "W/(m/s)")}
    if math.isfinite(power):
        out["frictional_power_at_speed"] = quantity(power * vc.normal.speed, "W")
    return out
