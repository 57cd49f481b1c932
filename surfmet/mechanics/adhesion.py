"""``surfmet adhesion``'s facade: an adhesive sphere on a flat, approached and retracted.

:func:`adhesion` resolves the modulus (a material pair or E* itself), builds the adhesion
law (:mod:`contact.adhesion.laws`) and runs the cycle of
:func:`contact.adhesion.ball.adhesive_ball`; :func:`adhesion_record` is its JSON record,
:func:`plot` its figure. The range means h0 = w / sigma0 for the Dugdale law and rho for
the exponential one.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from surfmet.errors import SurfmetInputError
from surfmet.units import quantity

INTERACTIONS = ("dugdale", "exponential")


def interaction_law(interaction: str, work: float, range_: float) -> Any:
    """The adhesion law named ``interaction`` of work ``work`` (J/m^2) and range ``range_``
    (m): h0 = w / sigma0 for ``"dugdale"``, rho for ``"exponential"``."""
    from contact.adhesion.laws import DugdaleLaw, ExponentialLaw

    if interaction not in INTERACTIONS:
        raise SurfmetInputError(f"unknown interaction {interaction!r}: use "
                                f"{' or '.join(INTERACTIONS)}")
    return (DugdaleLaw.from_range(work, range_) if interaction == "dugdale"
            else ExponentialLaw(work, range_))


def interaction_name(law: Any) -> str:
    """``"dugdale"`` or ``"exponential"``: the name of an adhesion law."""
    return "dugdale" if hasattr(law, "sigma0") else "exponential"


def adhesion(radius: float, *, work: float, range_: float, materials: Any = None,
             e_star: float | None = None, interaction: str = "dugdale", grid: int = 128,
             size: float | None = None, steps: int = 40,
             progress: Callable[[int, int], None] | None = None) -> Any:
    """The approach-retraction cycle of a sphere of ``radius`` on a flat.

    Give exactly one of ``materials`` ("BALL,PLATE" text or two materials) and ``e_star``
    (Pa). Returns a :class:`contact.adhesion.ball.AdhesiveBall`.
    """
    from contact.adhesion.ball import adhesive_ball
    from surfmet.mechanics.material_spec import material_pair

    if (materials is None) == (e_star is None):
        raise SurfmetInputError("give exactly one of the materials and E*")
    if e_star is None:
        e_star = material_pair(materials).e_star
    law = interaction_law(interaction, work, range_)
    return adhesive_ball(radius, e_star, law, grid=grid, size=size, steps=steps,
                         progress=progress)


def _leg(branch: Any) -> dict[str, Any]:
    return {"approach": quantity(branch.surface_approach, "m"),
            "load": quantity(branch.load, "N"),
            "contact_radius": quantity(branch.contact_radius, "m")}


def _jump(jump: Any) -> dict[str, Any] | None:
    if jump is None:
        return None
    return {"approach": quantity(jump.approach, "m"), "step": quantity(jump.step, "m"),
            "load_before": quantity(jump.load_before, "N"),
            "load_after": quantity(jump.load_after, "N"), "abrupt": jump.abrupt}


def adhesion_record(ball: Any) -> dict[str, Any]:
    """The JSON record of an :class:`~contact.adhesion.ball.AdhesiveBall`."""
    cyc, law = ball.cycle, ball.law
    return {
        "radius": quantity(ball.radius, "m"),
        "e_star": quantity(ball.e_star, "Pa"),
        "interaction": interaction_name(law),
        "work_of_adhesion": quantity(law.work, "J/m^2"),
        "range": quantity(law.range, "m"),
        "peak_tension": quantity(law.peak, "Pa"),
        "maugis_parameter": quantity(ball.maugis_parameter, ""),
        "tabor_parameter": quantity(ball.tabor_parameter, ""),
        "pull_off_force": quantity(cyc.pull_off_force, "N"),
        "pull_off_approach": quantity(cyc.pull_off_approach, "m"),
        "jkr_pull_off_force": quantity(ball.jkr_pull_off, "N"),
        "dmt_pull_off_force": quantity(ball.dmt_pull_off, "N"),
        "jump_in": _jump(cyc.jump_in),
        "jump_out": _jump(cyc.jump_out),
        "hysteresis_energy": quantity(cyc.hysteresis_energy, "J"),
        "grid": {"cells": ball.grid, "size": quantity(ball.size, "m"),
                 "pixel": quantity(ball.dx, "m"), "periodic": True,
                 "process_zone": quantity(ball.process_zone, "m"),
                 "process_zone_pixels": quantity(ball.process_zone / ball.dx, "")},
        "solver": {"iterations": int(cyc.approach_leg.iterations.sum()
                                     + cyc.retraction_leg.iterations.sum())},
        "solve": cyc.solve.to_json(),
        "curve": {"in": _leg(cyc.approach_leg), "out": _leg(cyc.retraction_leg)},
        "warnings": list(ball.warnings),
    }


def plot(ball: Any, path: Any = None) -> Any:
    """Load against approach, and contact radius against load, in and out."""
    from surfmet.plots._style import finish, new_figure

    fig, (a1, a2) = new_figure(1, 2, size=(10, 4.2))
    for leg, style, name in ((ball.cycle.approach_leg, "C0o-", "approach"),
                             (ball.cycle.retraction_leg, "C3s-", "retraction")):
        a1.plot(leg.surface_approach * 1e9, leg.load * 1e6, style, ms=3, label=name)
        a2.plot(leg.load * 1e6, leg.contact_radius * 1e6, style, ms=3, label=name)
    a1.axhline(-ball.jkr_pull_off * 1e6, color="0.5", ls=":", label="JKR pull-off")
    a1.axhline(-ball.dmt_pull_off * 1e6, color="0.5", ls="--", label="DMT pull-off")
    a1.set_xlabel("approach (nm)")
    a1.set_ylabel("load (µN)")
    a2.set_xlabel("load (µN)")
    a2.set_ylabel("contact radius (µm)")
    a1.set_title(f"Maugis lambda = {ball.maugis_parameter:.3g}")
    for ax in (a1, a2):
        ax.legend(fontsize=8)
    return finish(fig, path)
