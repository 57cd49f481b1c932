"""Adhesive normal contact: interaction laws, the adhesive solve, approach-retraction cycles.

- :mod:`contact.adhesion.laws`: the Dugdale (Maugis) and exponential laws, the Maugis and
  Tabor parameters;
- :mod:`contact.adhesion.solver`: one equilibrium at a prescribed approach (or load) on a
  periodic grid, tensile tractions solved (:func:`solve_adhesive`);
- :mod:`contact.adhesion.descent`: its method, the accelerated projected gradient on the
  gap, run by the one driver of the normal solves (:mod:`contact.bem.loop`);
- :mod:`contact.adhesion.cycle`: displacement-controlled approach and retraction, pull-off,
  jumps and hysteresis;
- :mod:`contact.adhesion.ball`: the sphere on a flat (:func:`adhesive_ball`);
- :mod:`contact.adhesion.line`: the cylinder on a flat in plane strain, per unit length;
- :mod:`contact.adhesion.flat`: a rough periodic surface on a flat at prescribed nominal
  pressures (load control around the solve);
- :mod:`contact.adhesion.stickiness`: Pastewka & Robbins' stickiness criterion;
- :mod:`contact.adhesion.rolling`: adhesion hysteresis as a rolling-resistance mechanism.

The pressure bounds that carry a law into a normal solve are
:class:`contact.bem.bounds.PressureBounds`.
"""

from contact.adhesion.ball import AdhesiveBall, adhesive_ball
from contact.adhesion.cycle import Cycle, approach_retraction
from contact.adhesion.laws import DugdaleLaw, ExponentialLaw, maugis_parameter
from contact.adhesion.solver import AdhesiveState, adhesive_problem, solve_adhesive

__all__ = ["AdhesiveBall", "AdhesiveState", "Cycle", "DugdaleLaw", "ExponentialLaw",
           "adhesive_ball", "adhesive_problem", "approach_retraction", "maugis_parameter",
           "solve_adhesive"]
