"""The JSON record of a solve (:class:`contact._record.SolveRecord`), and the record read
back, so that a command printing its JSON prints the same line as from the solve itself.

The engine returns the dataclass; only this module writes it as JSON: dimensionless
values with unit ``""``, the edge-contact warning or null.
"""

from __future__ import annotations

import math
from typing import Any

from surfmet.units import quantity

__all__ = ["solve_from_record", "solve_record"]


def solve_record(rec: Any) -> dict[str, Any]:
    """A :class:`contact._record.SolveRecord` as JSON.

    Parameters
    ----------
    rec : contact._record.SolveRecord
        The record of a solve.

    Returns
    -------
    dict
        ``method``, ``iterations``, ``residual`` and ``tolerance`` (unit ``""``, null when
        not finite), ``residual_definition``, ``converged``, ``edge_contact``, ``warning``;
        ``outer_iterations``, ``solves`` and ``periodic`` where they apply.

    Examples
    --------
    >>> from contact._record import SolveRecord
    >>> from surfmet.records._solve import solve_record
    >>> solve_record(SolveRecord("normal BEM", 7, 2.5e-3, 1e-6, False, False))["residual"]
    {'value': 0.0025, 'unit': ''}
    """
    out: dict[str, Any] = {
        "method": rec.method,
        "iterations": int(rec.iterations),
        "residual": quantity(float(rec.residual), ""),
        "residual_definition": rec.residual_definition,
        "tolerance": quantity(float(rec.tolerance), ""),
        "converged": bool(rec.converged),
        "edge_contact": bool(rec.edge_contact),
        "warning": rec.warning,
    }
    if rec.outer_iterations is not None:
        out["outer_iterations"] = int(rec.outer_iterations)
    if rec.solves != 1:
        out["solves"] = int(rec.solves)
    if rec.periodic:
        out["periodic"] = True  # edge contact does not apply: the domain has no edge
    return out


def solve_from_record(rec: dict[str, Any]) -> Any:
    """The :class:`contact._record.SolveRecord` back from :func:`solve_record` (null
    residuals become inf, NaN tolerances stay NaN).

    Parameters
    ----------
    rec : dict
        A command's JSON ``"solve"`` object.

    Returns
    -------
    contact._record.SolveRecord
        The record, equal to the one written.

    Examples
    --------
    >>> from contact._record import SolveRecord
    >>> from surfmet.records._solve import solve_from_record, solve_record
    >>> rec = SolveRecord("normal BEM", 7, 2.5e-3, 1e-6, False, True)
    >>> solve_from_record(solve_record(rec)) == rec
    True
    """
    from contact._record import SolveRecord

    res, tol = rec["residual"]["value"], rec["tolerance"]["value"]
    return SolveRecord(method=rec["method"], iterations=rec["iterations"],
                       residual=math.inf if res is None else res,
                       tolerance=math.nan if tol is None else tol,
                       converged=rec["converged"], edge_contact=rec["edge_contact"],
                       residual_definition=rec.get("residual_definition", ""),
                       outer_iterations=rec.get("outer_iterations"),
                       solves=rec.get("solves", 1), periodic=rec.get("periodic", False))
