"""The one record of a solve, and the one treatment of contact at the domain edge.

Every solver family of :mod:`contact` (the normal BEM, the plane-strain line contact,
the tangential steady-rolling and shift solvers, viscoelastic rolling, the adhesive
solve) returns its answer with a :class:`SolveRecord` in the field ``solve``: how many
iterations it took, the residual it reached against the tolerance it was asked for,
whether it converged, and whether the contact reaches the edge of the computational
domain. Commands print it with :meth:`SolveRecord.text`; its JSON record is built by the user
layer (``surfmet.records._solve``), never here.

Contact at the domain edge
--------------------------
A free-boundary solve assumes no pressure outside its grid. When a loaded cell lies on
the outermost ring of the grid (the first or last cell of a line), the contact may go on
beyond it and the answer is cut short there: :func:`edge_contact` measures this, the one
test every solver uses. A periodic domain has no edge, so it never touches one. The one
policy (:func:`edge_warning`): the record says ``edge_contact``, the solve issues an
:class:`~contact._errors.EdgeContactWarning` whose text says the domain is too small and to
enlarge it, and commands print that text (and put it in JSON). Where an answer cannot be
formed at all (a solver whose upwind operator needs unloaded material entering at the
leading edge, or a rough scan that ends inside the contact), :func:`raise_edge` raises an
:class:`~contact._errors.EdgeContactError` with the same sentence.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from contact._errors import EdgeContactError, EdgeContactWarning

#: What to do about contact at the domain edge (the advice every warning and error ends on).
EDGE_ADVICE = "enlarge the domain (a larger size or scan) and solve again"
#: The advice of a solve that may return a truncated result instead (``on_edge="warn"``);
#: a caller that cannot (a sweep) drops it from the message.
TRUNCATED_ADVICE = " (or accept a truncated result: on_edge='warn')"
#: Why a steady-rolling solve refuses contact at its leading edge.
LEADING_EDGE = ("steady rolling needs unloaded material entering at the leading edge "
                "(largest x), so no answer is formed")


@dataclass(frozen=True)
class SolveRecord:
    """How one solve went.

    Attributes
    ----------
    method : str
        The solver, in a few words (e.g. "normal BEM", "steady rolling").
    iterations : int
        Iterations of the solver's main loop (on the finest grid where it nests).
    residual : float
        The residual reached, dimensionless (each solver states its definition in
        ``residual_definition``).
    tolerance : float
        The residual asked for.
    converged : bool
        The solver's own stopping test was met (solvers that raise on failure only return
        converged records; the BEM returns ``False`` with ``strict=False``). Where that
        test is not a bound on ``residual`` (the tangential solves stop on the change of
        their iterate; their residual is formed afresh from the answer), a converged
        record may show a residual above the tolerance.
    edge_contact : bool
        Pressure on the outermost cells of a free-boundary domain (:func:`edge_contact`).
    residual_definition : str
        What ``residual`` measures.
    outer_iterations : int or None
        Iterations of an outer loop around the main one (coupling, active set), if any.
    solves : int
        How many solves the record stands for (:func:`combine`; 1 for one solve).
    periodic : bool
        The domain is periodic: it has no edge, so ``edge_contact`` is False by the one
        rule and the text says "not applicable" rather than "no".
    counters : mapping, optional
        The solver's own work counters, for benchmarks and diagnostics (the normal BEM's
        FFTs, sparse corrections, projected and damped steps and grid levels, of every
        level of a nested solve); not part of the JSON record, and not compared.
    """

    method: str
    iterations: int
    residual: float
    tolerance: float
    converged: bool
    edge_contact: bool
    residual_definition: str = ""
    outer_iterations: int | None = None
    solves: int = 1
    periodic: bool = False
    counters: Mapping[str, Any] | None = field(default=None, compare=False, repr=False)

    @property
    def warning(self) -> str | None:
        """The edge-contact warning (:func:`edge_warning`), or None."""
        return edge_message() if self.edge_contact else None

    def text(self) -> str:
        """One line: iterations, residual against tolerance, converged, edge contact."""
        outer = ("" if self.outer_iterations is None
                 else f" ({self.outer_iterations} outer)")
        state = "converged" if self.converged else "NOT converged"
        edge = ("yes" if self.edge_contact
                else "not applicable (periodic domain)" if self.periodic else "no")
        many = "" if self.solves == 1 else f"{self.solves} solves, "
        worst = "largest " if self.solves > 1 else ""
        return (f"{self.method}: {many}{self.iterations} iterations{outer}, {worst}residual "
                f"{self.residual:.3g} (tolerance {self.tolerance:.3g}), {state}, "
                f"edge contact: {edge}")


def combine(records: list[SolveRecord], method: str | None = None) -> SolveRecord:
    """One record for several solves (a sweep, a cycle, the levels of a verdict): the
    iterations summed, the largest residual and tolerance, converged only if every solve
    did, edge contact if any solve had it, periodic if every solve was, and the work
    counters summed where every solve kept them (:func:`summed_counters`).
    """
    if not records:
        raise ValueError("combine needs at least one record")
    if len(records) == 1 and method is None:
        return records[0]
    outer = [r.outer_iterations for r in records if r.outer_iterations is not None]
    return SolveRecord(
        method=method or records[0].method,
        iterations=sum(r.iterations for r in records),
        residual=max(r.residual for r in records),
        tolerance=max(r.tolerance for r in records),
        converged=all(r.converged for r in records),
        edge_contact=any(r.edge_contact for r in records),
        residual_definition=records[0].residual_definition,
        outer_iterations=sum(outer) if outer else None,
        solves=sum(r.solves for r in records),
        periodic=all(r.periodic for r in records),
        counters=summed_counters([r.counters for r in records]),
    )


def summed_counters(counters: list[Mapping[str, Any] | None]) -> dict[str, Any] | None:
    """The work counters of several solves as one: each count summed and the grid levels
    one after the other; None unless every solve kept its counters (a partial sum would
    pass for the whole work)."""
    out: dict[str, Any] = {}
    for c in counters:
        if c is None:
            return None
        for key, value in c.items():
            if key == "levels":
                out[key] = (*out.get(key, ()), *value)
            else:
                out[key] = out.get(key, 0) + value
    return out or None


def edge_contact(pressure: np.ndarray, periodic: bool = False, *,
                 leading_only: bool = False) -> bool:
    """True when a cell on the edge of a free-boundary domain carries pressure.

    Parameters
    ----------
    pressure : ndarray, shape (n,) or (ny, nx)
        Pressure (or any field that is positive where the bodies press on each other).
    periodic : bool
        A periodic domain has no edge: always False.
    leading_only : bool
        Only the leading edge (the last column, largest x) counts: the edge through
        which material enters a steady-rolling contact.

    Notes
    -----
    The edge is the first and last cell of a line, the outermost ring of a 2D grid (along
    x only for a grid one row high, which stands for a line).
    """
    if periodic:
        return False
    p = np.asarray(pressure)
    if leading_only:
        return bool((p[..., -1] > 0).any())
    if p.ndim == 1 or (p.ndim == 2 and p.shape[0] == 1):
        row = p.reshape(-1)
        return bool(row[0] > 0 or row[-1] > 0)
    return bool((p[0] > 0).any() or (p[-1] > 0).any()
                or (p[:, 0] > 0).any() or (p[:, -1] > 0).any())


def edge_message(domain: str = "the domain") -> str:
    """The one sentence about contact at the domain edge; ``domain`` names it (e.g. "the
    0.5 mm domain")."""
    return (f"contact reaches the edge of {domain}: the domain is too small and the result "
            f"is truncated there; {EDGE_ADVICE}")


def edge_warning(touched: bool, domain: str = "the domain", stacklevel: int = 3) -> str | None:
    """The one warning policy: if ``touched``, warn (:class:`EdgeContactWarning`) and
    return the message (for a result's notes); else None."""
    if not touched:
        return None
    msg = edge_message(domain)
    warnings.warn(msg, EdgeContactWarning, stacklevel=stacklevel)
    return msg


def raise_edge(why: str, domain: str = "the domain") -> None:
    """Raise the one :class:`EdgeContactError` for contact at an edge where no answer can
    be formed; ``why`` says why it cannot."""
    raise EdgeContactError(f"contact reaches the edge of {domain}: {why}; {EDGE_ADVICE}")
