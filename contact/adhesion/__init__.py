"""Adhesive normal contact: interaction laws, the adhesive solve, approach-retraction cycles.

- :mod:`contact.adhesion.laws`: the interaction laws as plug-ins (one table, one module a
  law: Dugdale (Maugis), exponential, ...), the Maugis and Tabor parameters;
- :mod:`contact.adhesion.solver`: one equilibrium at a prescribed approach (or load) on a
  periodic grid, tensile tractions solved (:func:`solve_adhesive`);
- :mod:`contact.adhesion._descent`: its method, the accelerated projected gradient on the
  gap, run by the one driver of the normal solves (:mod:`contact.bem._loop`);
- :mod:`contact.adhesion.cycle`: displacement-controlled approach and retraction, pull-off,
  jumps and hysteresis;
- :mod:`contact.adhesion.ball`: the sphere on a flat (:func:`adhesive_ball`);
- :mod:`contact.adhesion.line`: the cylinder on a flat in plane strain, per unit length;
- :mod:`contact.adhesion.flat`: a rough periodic surface on a flat at prescribed nominal
  pressures (load control around the solve);
- :mod:`contact.adhesion.stickiness`: Pastewka & Robbins' stickiness criterion;
- :mod:`contact.adhesion.rolling`: adhesion hysteresis as a rolling-resistance mechanism.

The pressure bounds that carry a law into a normal solve are
:class:`contact.bem._bounds.PressureBounds`.
"""

from contact._lazy import attach

# Loaded on first use, so that the laws' table (the commands' choices) is read without the
# solvers' numba kernels.
_LAZY = {
    "AdhesiveBall": "contact.adhesion.ball", "adhesive_ball": "contact.adhesion.ball",
    "Cycle": "contact.adhesion.cycle", "approach_retraction": "contact.adhesion.cycle",
    "DugdaleLaw": "contact.adhesion.laws", "ExponentialLaw": "contact.adhesion.laws",
    "InteractionLaw": "contact.adhesion.laws", "maugis_parameter": "contact.adhesion.laws",
    "register_law": "contact.adhesion.laws", "AdhesiveState": "contact.adhesion.solver",
    "adhesive_problem": "contact.adhesion.solver", "solve_adhesive": "contact.adhesion.solver",
}

#: The modules, reachable as ``contact.adhesion.<module>`` without an explicit import.
SUBMODULES = ("ball", "cycle", "default_grid", "flat", "kernels", "laws", "line", "memory",
              "rolling", "solver", "stickiness")

__getattr__, __dir__ = attach(__name__, SUBMODULES, _LAZY)

__all__ = ["AdhesiveBall", "AdhesiveState", "Cycle", "DugdaleLaw", "ExponentialLaw",
           "InteractionLaw", "adhesive_ball", "adhesive_problem", "approach_retraction",
           "maugis_parameter", "register_law", "solve_adhesive"]
